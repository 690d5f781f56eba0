// Issue 14's whole-body check (study/whole_body/whole_body_check.h): the
// orchestrator of its stages (the orientation, the load rule, the slices, the
// end models, the whole body, the comparison) and the outcome. The stages:
// check_context.h (shared inputs, the whole body's solve), share_rules.h,
// check_stages.h; the orientations: whole_body_orientation.cpp; the JSON and
// the tables: whole_body_json.cpp, whole_body_report.cpp.
#include "study/whole_body/whole_body_check.h"
#include "core/degree.h"
#include "core/error.h"
#include "fem/all_gather.h"
#include "fem/petsc_session.h"
#include "study/whole_body/check_stages.h"
#include "study/whole_body/share_rules.h"
#include <algorithm>
#include <chrono>
#include <cmath>
#include <fmt/format.h>
#include <spdlog/spdlog.h>

namespace rollcheck::study::whole_body
{
namespace
{
/// InputError for settings out of range or a body without a whole-body mesh.
void check_settings(const WholeBodyCheckSettings& s)
{
  if (s.body.body != "cylinder" && s.body.body != "oloid")
    throw InputError(fmt::format(
        "body '{}': the whole-body check meshes the cylinder (extruded) and the oloid (mapped); other bodies have no "
        "whole-body mesh (docs/methods/whole-body.md)",
        s.body.body));
  if (s.body.body == "oloid" && s.body.points < 64)
    throw InputError(fmt::format("points {}: the oloid's sections are ray cast against its hull, which needs at least "
                                 "64 points per circle (default 400)",
                                 s.body.points));
  if (!s.body.mesh_file.empty())
    throw InputError("the whole-body check needs the exact body, not a mesh file");
  auto require = [](bool ok, const std::string& what) {
    if (!ok)
      throw InputError(what);
  };
  require(s.body.radius_m > 0 && s.body.height_m > 0, "radius_m and height_m must be positive");
  require(s.normal_load_n > 0, fmt::format("normal_load_n must be positive, got {}", s.normal_load_n));
  require(s.youngs_modulus_pa > 0, "youngs_modulus_pa must be positive");
  require(s.poisson_ratio >= 0 && s.poisson_ratio < 0.5, "poisson_ratio must lie in [0, 0.5)");
  require(s.contact_elements >= 2 && s.contact_elements <= 40, "contact_elements must lie in [2, 40]");
  require(s.strip_over_half_width >= 1, "strip_over_half_width must be at least 1");
  require(s.section_growth > 0 && s.section_growth <= 1, "section_growth must lie in (0, 1]");
  require(s.layer_growth >= 1 && s.layer_growth <= 3, "layer_growth must lie in [1, 3]");
  require(s.layers_across_length >= 2, "layers_across_length must be at least 2");
  require(s.penalty_c > 0, "penalty_c must be positive");
  require(s.stations >= 2, "stations must be at least 2");
  require(s.rule_stations >= 4 && s.rule_stations <= 200, "rule_stations must lie in [4, 200]");
  require(s.rule_contact_elements >= 2 && s.rule_contact_elements <= 40, "rule_contact_elements must lie in [2, 40]");
  require(s.rule_end_layer > 0 && s.rule_end_layer <= 1, "rule_end_layer must lie in (0, 1]");
  require(s.end_match_over_half_width >= 1 && s.end_match_over_half_width <= 100,
          "end_match_over_half_width must lie in [1, 100]");
  require(s.end_margin > 0 && s.end_margin < 0.25, "end_margin must lie in (0, 0.25)");
  require(s.end_levels >= 1 && s.end_levels <= 6, "end_levels must lie in [1, 6]");
  require(s.end_edge_element > 0 && s.end_edge_element <= 1, "end_edge_element must lie in (0, 1]");
  require(s.end_contact_elements >= 2 && s.end_contact_elements <= 40, "end_contact_elements must lie in [2, 40]");
  require(s.body_end_layer > 0 && s.body_end_layer <= 1, "body_end_layer must lie in (0, 1]");
  require(s.end_zone_over_half_width > 0 && s.end_zone_over_half_width <= 20,
          "end_zone_over_half_width must lie in (0, 20]");
  require(s.tolerance > 0 && s.tolerance < 1, "tolerance must lie in (0, 1)");
}

/// The orientation at settings.direction_deg; InputError where the body
/// tips (no line contact in equilibrium).
WholeBodyOrientation balanced_orientation(const WholeBodyCheckSettings& s)
{
  WholeBodyOrientation o = whole_body_orientation(s, s.direction_deg);
  if (!o.in_equilibrium)
    throw InputError(fmt::format("direction {} deg: the centre of mass's foot lies outside the ruling (c = {:.4f}): "
                                 "the body tips, no line contact in equilibrium",
                                 s.direction_deg, o.centre_of_pressure));
  return o;
}

/// The ruling, the locus's loaded part and the rule's b at the centre of
/// mass's foot, logged once the rule is known.
void log_ruling(const CheckContext& context, const WholeBodyCheck& r)
{
  const WholeBodyOrientation& o = r.orientation;
  const double L = context.length_m();
  spdlog::info("whole-body check, {}: ruling L = {:.5g} m, R = {:.5g}..{:.5g} m, c = {:.4f}, loaded {:.3f}..{:.3f}, "
               "rim leans {:.2f}, {:.2f} deg, b = {:.4g} m (b / L = {:.3g})",
               r.body, L, o.ruling.start_radius_m, o.ruling.end_radius_m, o.centre_of_pressure, o.loaded_from,
               o.loaded_to, o.rim_overhang_rad[0] / degree, o.rim_overhang_rad[1] / degree, r.half_width_m,
               r.half_width_m / L);
}
} // namespace

WholeBodyCheck run_whole_body_check(MPI_Comm comm, const WholeBodyCheckSettings& s)
{
  check_settings(s);
  const auto start = std::chrono::steady_clock::now();
  fem::ensure_petsc();
  WholeBodyCheck r;
  r.settings = s;
  r.body = geometry::body_label(s.body);
  r.orientation = balanced_orientation(s);
  const CheckContext context(comm, s, r.orientation);
  r.effective_modulus_pa = context.effective_modulus_pa;
  r.sizes = context.sizing.sizes;

  // The load rule, chosen once: its q(f) for the slices and end models.
  const ShareRuleStrategy& rule = share_rule_strategy(s.share_rule);
  require_rule_applies(rule, context);
  const LineLoad load_at = rule.solve(context, r);
  const double c = context.centre_of_pressure();
  r.half_width_m = context.half_width_at(load_at(c), c);
  if (context.log)
    log_ruling(context, r);

  // The reduced models under the rule, then the whole body (the reference).
  const SliceReadings slices = solve_slice_stage(context, load_at, rule.softens_ends);
  r.slices_s = slices.wall_s;
  const auto clock = std::chrono::steady_clock::now();
  r.ends = solve_end_model_stage(context, load_at, slices, rule.softens_ends);
  r.ends_s = fem::wall_seconds_since(comm, clock);
  solve_whole_body_stage(context, load_at(c), r);

  compare_stations(slices, r);
  compare_ends(context, r);
  r.wall_s = fem::wall_seconds_since(comm, start);
  if (context.log)
    spdlog::info("{} ({:.1f} s: slices {:.1f}, end models {:.1f}, whole body {:.1f})", r.verdict, r.wall_s, r.slices_s,
                 r.ends_s, r.body_s);
  return r;
}

WholeBodyOutcome check_outcome(double worst_along, std::span<const EndComparison> ends, double tolerance)
{
  if (ends.empty() || !(worst_along <= tolerance))
    return WholeBodyOutcome::fail;
  bool singular = false;
  for (const EndComparison& end : ends)
  {
    if (end.difference)
    {
      if (!(std::abs(*end.difference) <= tolerance))
        return WholeBodyOutcome::fail;
    }
    else if (end.end_model.singular)
      singular = true;
    else
      return WholeBodyOutcome::fail; // did not converge: no value, and no reason why none exists
  }
  return singular ? WholeBodyOutcome::singular_ends : WholeBodyOutcome::pass;
}

std::string outcome_name(WholeBodyOutcome outcome)
{
  return outcome == WholeBodyOutcome::pass            ? "PASS"
         : outcome == WholeBodyOutcome::singular_ends ? "SINGULAR ENDS"
                                                      : "FAIL";
}

double largest_peak_difference(std::span<const StationComparison> stations)
{
  if (stations.empty())
    return 0;
  return std::ranges::max(stations, {}, &StationComparison::body_peak_pa).body_peak_pa
             / std::ranges::max(stations, {}, &StationComparison::slice_peak_pa).slice_peak_pa
         - 1;
}
} // namespace rollcheck::study::whole_body
