// The slices, the whole body and the comparison of a whole-body check
// (study/whole_body/check_stages.h; the end models: end_model_stage.cpp).
#include "study/whole_body/check_stages.h"
#include "fem/all_gather.h"
#include <algorithm>
#include <chrono>
#include <cmath>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <spdlog/spdlog.h>

namespace rollcheck::study::whole_body
{
namespace
{
/// largest = max(largest, x), but a NaN x wins (std::max would drop it),
/// so that a NaN comparison fails the check.
void keep_largest(double& largest, double x)
{
  if (!(x <= largest))
    largest = x;
}

/// The whole body's readings at one loaded end (its edge pressure, its peak
/// at the nearest station, its largest plane peak within 2 b of the edge, b
/// the locus's there) and the end's differences from the end model's
/// prediction and, for a singular end, its matched-mesh reading.
void compare_end(const CheckContext& context, const WholeBodyCheck& check, EndComparison& end)
{
  const fem::WholeBodyFem& body = check.fem;
  const bool at_start = end.position_m < 0.5 * context.length_m();
  end.body_edge_pa = body.edge_pressure_pa[at_start ? 0 : 1];
  end.body_interior_pa = at_start ? check.stations.front().body_peak_pa : check.stations.back().body_peak_pa;
  const double reach = 2 * context.orientation.end_half_width_m[at_start ? 0 : 1];
  for (std::size_t k = 0; k < body.plane_x_m.size(); ++k)
    if (std::abs(body.plane_x_m[k] - end.position_m) <= reach)
      end.body_near_edge_peak_pa = std::max(end.body_near_edge_peak_pa, body.plane_peak_pa[k]);
  if (end.predicted_edge_pa)
    end.difference = (end.near_edge_peak ? end.body_near_edge_peak_pa : end.body_edge_pa) / *end.predicted_edge_pa - 1;
  if (end.matched_edge_pa)
    end.matched_difference = end.body_edge_pa / *end.matched_edge_pa - 1;
}
} // namespace

SliceReadings solve_slice_stage(const CheckContext& context, const LineLoad& load_at, bool match_near_edge)
{
  const WholeBodyCheckSettings& s = context.settings;
  const double L = context.length_m();
  SliceReadings readings;
  auto read_at = [&](double f) { readings.loads.push_back({f * L, context.radius_at(f), load_at(f)}); };
  for (const double f : context.fractions)
    read_at(f);
  readings.stations = context.fractions.size();
  for (int e = 0; e < 2; ++e)
    if (const double locus_b = context.orientation.end_half_width_m[e]; locus_b > 0)
    {
      readings.loaded_ends.push_back(e);
      const double inward = (e == 0 ? 1 : -1) * s.end_match_over_half_width * locus_b / L;
      readings.read_at_fraction[e] = context.end_fractions[e] + (match_near_edge ? inward : 0.0);
      read_at(readings.read_at_fraction[e]);
    }
  fem::SliceSettings slice;
  slice.youngs_modulus_pa = s.youngs_modulus_pa;
  slice.poisson_ratio = s.poisson_ratio;
  slice.refine = s.slice_refine;
  const auto clock = std::chrono::steady_clock::now();
  readings.slices = fem::solve_slices(context.comm, readings.loads, slice);
  readings.wall_s = fem::wall_seconds_since(context.comm, clock);
  if (context.log)
    spdlog::info("slices: {} solved in {:.1f} s", readings.slices.size(), readings.wall_s);
  return readings;
}

void solve_whole_body_stage(const CheckContext& context, double load_at_centre, WholeBodyCheck& check)
{
  const auto clock = std::chrono::steady_clock::now();
  BodySolve body = solve_body(context, check.sizes, load_at_centre);
  check.fem = std::move(body.fem);
  check.node_planes = body.node_planes;
  check.section_nodes = body.section_nodes;
  check.gmsh_s = body.gmsh_s;
  check.body_s = fem::wall_seconds_since(context.comm, clock);
}

void compare_stations(const SliceReadings& slices, WholeBodyCheck& check)
{
  const fem::WholeBodyFem& body = check.fem;
  for (std::size_t k = 0; k < slices.stations; ++k)
  {
    StationComparison st;
    st.position_m = slices.loads[k].position_m;
    st.radius_m = slices.loads[k].radius_m;
    st.rule_load_n_per_m = slices.loads[k].load_n_per_m;
    st.slice_peak_pa = slices.slices[k].peak_pressure_pa;
    st.hertz_peak_pa = slices.slices[k].hertz_peak_pressure_pa;
    st.body_peak_pa = fem::interpolate_planes(body.plane_x_m, body.plane_peak_pa, st.position_m);
    st.body_load_n_per_m = fem::interpolate_planes(body.plane_x_m, body.plane_load_n_per_m, st.position_m);
    keep_largest(check.worst_along, std::abs(st.peak_difference()));
    keep_largest(check.worst_load, std::abs(st.load_difference()));
    check.stations.push_back(st);
  }
  check.largest_peak_difference = largest_peak_difference(check.stations);
}

void compare_ends(const CheckContext& context, WholeBodyCheck& check)
{
  bool ends_compared = true;
  double worst_end = 0;
  std::vector<std::string> singular_ends, unconverged_ends;
  for (EndComparison& end : check.ends)
  {
    compare_end(context, check, end);
    if (end.difference)
    {
      keep_largest(worst_end, std::abs(*end.difference));
      continue;
    }
    ends_compared = false;
    const std::string where = fmt::format("the ruling's {} ({:.2f} deg)",
                                          end.position_m < 0.5 * context.length_m() ? "start" : "end",
                                          end.interior_angle_deg);
    if (end.end_model.singular)
      singular_ends.push_back(
          fmt::format("{} singular (the wedge's exponent {:.3f})", where, end.end_model.wedge_exponent));
    else
      unconverged_ends.push_back(fmt::format("the end model at {} did not converge", where));
  }
  if (ends_compared && !check.ends.empty())
    check.worst_end = worst_end;
  check.outcome = check_outcome(check.worst_along, check.ends, context.settings.tolerance);
  check.pass = check.outcome == WholeBodyOutcome::pass;
  std::vector<std::string> at_ends;
  if (check.ends.size() > singular_ends.size() + unconverged_ends.size())
    at_ends.push_back(fmt::format("the compared ends within {:.2f} % of the end models' reading", 100 * worst_end));
  at_ends.insert(at_ends.end(), singular_ends.begin(), singular_ends.end());
  at_ends.insert(at_ends.end(), unconverged_ends.begin(), unconverged_ends.end());
  check.verdict = fmt::format(
      "{}: along the ruling the whole body's peak is within {:.2f} % of the slices' ({} stations; the largest over "
      "them, fem-sds's peak, {:+.2f} %); at the ends {}; tolerance {:.1f} %",
      outcome_name(check.outcome), 100 * check.worst_along, check.stations.size(), 100 * check.largest_peak_difference,
      check.ends.empty() ? std::string("no loaded end") : fmt::format("{}", fmt::join(at_ends, ", ")),
      100 * context.settings.tolerance);
}
} // namespace rollcheck::study::whole_body
