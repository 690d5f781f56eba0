// The rims over a body's rolling loop (study/rims/rim_loop.h): the interior
// (fem-sds), the direct ends, the flat-rim table, the FEM end table and the
// end-aware scores, in that order.
#include "study/rims/rim_loop.h"
#include "core/degree.h"
#include "contact/hertz.h"
#include "contact/rim_dihedral_angle.h"
#include "core/error.h"
#include "core/named_values.h"
#include "fem/mesh/scene_mesh.h"
#include "fem/petsc_session.h"
#include "fem/scenes/slice_scaling.h"
#include "oracle/contact_density.h"
#include "core/progress_beat.h"
#include "study/rims/loop_half_space_end.h"
#include "study/rims/table_nodes.h"
#include <algorithm>
#include <chrono>
#include <cmath>
#include <fmt/format.h>
#include <functional>
#include <limits>
#include <numbers>
#include <span>
#include <spdlog/spdlog.h>
#include <tuple>

namespace rollcheck::study::rims
{
namespace
{

double median(std::vector<double> values)
{
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

/// Line Hertz's b of an end model's q and R against its counter-face.
double half_width(const fem::RimEndSettings& e)
{
  const double modulus
      = contact::effective_modulus(e.youngs_modulus_pa, e.poisson_ratio, e.counter_face == fem::CounterFace::block);
  return contact::line_contact(e.load_n_per_m, e.radius_m, modulus, e.poisson_ratio).half_width_m;
}

/// The settings with the loop's counter-face (settings.loop.elastic_plane),
/// checked. The interior's slices meet the same counter-face as the ends:
/// on a steel block, E* of the pair (half-space theory's reduction, as the
/// end model's block), so that the pressures, load ratios and b / R of the
/// loop are the pair's.
RimLoopSettings checked_settings(const RimLoopSettings& settings)
{
  RimLoopSettings s = settings;
  s.loop.elastic_plane = s.end.counter_face == fem::CounterFace::block;
  if (!(s.end_table_step_rad > 0) || !std::isfinite(s.end_table_step_rad))
    throw InputError(fmt::format("rim --body: end_table_step_deg must be positive and finite, got {}",
                                 s.end_table_step_rad / degree));
  if (!(s.end_table_acute_step_rad >= 0) || !std::isfinite(s.end_table_acute_step_rad))
    throw InputError(fmt::format("rim --body: end_table_acute_step_deg must be 0 (the table's step) or positive, got {}",
                                 s.end_table_acute_step_rad / degree));
  if (!(s.depth_over_edge_radius * fem::largest_edge_radius_over_depth > 1) || !std::isfinite(s.depth_over_edge_radius))
    throw InputError(fmt::format("rim --body: depth_over_edge_radius must exceed {} (the fillet inside the block), "
                                 "got {}",
                                 1 / fem::largest_edge_radius_over_depth, s.depth_over_edge_radius));
  if (!(s.end_table_radius_step == 0 || s.end_table_radius_step > 1) || !std::isfinite(s.end_table_radius_step))
    throw InputError(fmt::format("rim --body: end_table_radius_step must be 0 (one column) or above 1, got {}",
                                 s.end_table_radius_step));
  return s;
}

fem::RimEndSettings end_settings(const RimLoopSettings& s, double radius_m, double load_n_per_m, double angle_rad)
{
  fem::RimEndSettings e = s.end;
  e.radius_m = radius_m;
  e.load_n_per_m = load_n_per_m;
  e.interior_angle_rad = std::clamp(angle_rad, smallest_modelled_angle_rad, largest_modelled_angle(s.end));
  e.youngs_modulus_pa = s.loop.youngs_modulus_pa;
  e.poisson_ratio = s.loop.poisson_ratio;
  e.xdmf_path.clear(); // one end's fields, not the loop's
  return resolved_as_loop_end(e, s.depth_over_edge_radius);
}

/// The flat-rim solves' settings: the loop's load and material, the end
/// models' edge, counter-face and tolerance.
FlatRimSettings flat_rim_settings(const RimLoopSettings& s)
{
  FlatRimSettings setup;
  setup.normal_load_n = s.loop.normal_load_n;
  setup.edge_radius_m = s.end.edge_radius_m;
  setup.youngs_modulus_pa = s.loop.youngs_modulus_pa;
  setup.poisson_ratio = s.loop.poisson_ratio;
  setup.steel_counter_face = s.end.counter_face == fem::CounterFace::block;
  setup.tolerance = s.end.tolerance;
  // A node whose cells do not yet resolve its end gets a third level (the
  // U optimum's 178 deg side on steel, -8.44 % at b/8, -0.44 % at b/16; the
  // FEM-SDS optimum's vertex on steel, +3.98 % then -2.41 %: docs/methods/flat-rim.md).
  setup.extra_levels = 1;
  return setup;
}

/// An end model's level callback (fem::RimEndSettings::on_level) that
/// makes the beat's step `what` at that level.
std::function<void(int, double)> level_beat(ProgressBeat& beat, const std::string& what)
{
  return [&beat, what](int level, double edge_element_m) {
    beat.step(fmt::format("{}, level {} (h_e = {:.3g} m)", what, level + 1, edge_element_m));
  };
}

/// The end model at one loaded end of a directly solved orientation, from
/// `approach_over_estimate` (the end before's); outside the model (no
/// solve) where b / R is too large for line contact.
RimLoopEnd direct_end(MPI_Comm comm, const RimLoopSettings& s, std::span<const oracle::Circle> circles,
                      const loop_scores::FemSdsOrientation& r, int end, double q, bool static_load,
                      double approach_over_estimate, const std::function<void(int, double)>& on_level)
{
  const oracle::Ruling& ruling = *r.locus.ruling;
  RimLoopEnd e;
  e.orientation = r.index;
  e.end = end;
  e.section_angle_rad = std::numbers::pi / 2 + r.rim_overhang_rad[static_cast<std::size_t>(end)];
  e.dihedral_angle_rad = contact::rim_dihedral_angle(circles, r.locus.support.circles[0], r.locus.support.circles[1],
                                                     ruling)[static_cast<std::size_t>(end)];
  // A rounded part's finish leaves no radius below r_e (study/loop_scores/loop_sds.h loop_scores::end_aware_scores).
  const double hull_radius = end == 0 ? ruling.start_radius_m : ruling.end_radius_m;
  fem::RimEndSettings settings = end_settings(s, std::max(hull_radius, s.end.edge_radius_m), q, e.dihedral_angle_rad);
  settings.first_approach_scale = approach_over_estimate;
  settings.on_level = on_level;
  e.modelled_angle_rad = settings.interior_angle_rad;
  const double b = half_width(settings);
  if (!(b < fem::largest_half_width_over_radius * settings.radius_m))
  {
    e.study.setup = settings;
    e.study.half_width_m = b;
    e.outside_model = fmt::format("b / R = {:.2f}: near its sheet's apex the contact is no line contact (the end "
                                  "model needs b / R < {:.1f})",
                                  b / settings.radius_m, fem::largest_half_width_over_radius);
    return e;
  }
  std::tie(e.study, e.half_space) = loop_end_model(comm, settings, s.half_space_from_rad);
  e.interior_peak_pa = static_load ? r.fem_peak_pa : 0.0;
  if (e.study.end_to_interior && e.study.resolved && !e.study.singular)
    e.end_peak_pa = *e.study.end_to_interior * e.study.levels.back().far_peak_pa;
  return e;
}

/// The line load at end `end` (0 its start, 1 its end) of an orientation's
/// ruling under the load rule: F through the centre of mass (`loads`
/// empty: the static rule, as fem-sds solved it) or the sample's own load
/// (rule_loop_samples.h); 0 where the rule leaves that end unloaded or the
/// load falls outside the ruling.
double end_line_load(const RimLoopSettings& s, const loop_scores::FemSdsOrientation& r, int end,
                     std::span<const RulingLoad> loads)
{
  const oracle::Ruling& ruling = *r.locus.ruling;
  if (loads.empty())
    return r.solved && (end == 0 ? r.locus.loaded_from == 0 : r.locus.loaded_to == 1)
               ? oracle::line_load(s.loop.normal_load_n, r.locus.centre_of_pressure, ruling.length_m, end)
               : 0.0;
  const RulingLoad& load = loads[r.locus.sample];
  const double c = (load.through_m - ruling.start_m).dot(ruling.axis) / ruling.length_m;
  return r.solved && c > 0 && c < 1 ? oracle::line_load(load.force_n, c, ruling.length_m, end) : 0.0;
}

/// The end models at every loaded end of the directly solved orientations.
std::vector<RimLoopEnd> direct_ends(MPI_Comm comm, const RimLoopSettings& s, const loop_scores::FemSdsResult& interior,
                                    std::span<const RulingLoad> loads, ProgressBeat& beat)
{
  struct Loaded
  {
    const loop_scores::FemSdsOrientation* orientation;
    int end;
    double load_n_per_m;
  };
  std::vector<Loaded> loaded;
  for (const loop_scores::FemSdsOrientation& r : interior.orientations)
    for (const int end : {0, 1})
      if (r.solved)
        if (const double q = end_line_load(s, r, end, loads); q > 0)
          loaded.push_back({&r, end, q});
  std::vector<RimLoopEnd> ends;
  // Each end's load control starts from the end before's converged approach
  // over its estimate, as the end table's nodes do: the estimate overshoots
  // a held block's approach by about 20 % whatever the end's q and R.
  double approach_over_estimate = 1;
  for (const Loaded& l : loaded)
  {
    const std::string what = fmt::format("direct end {} of {} (orientation {}, its {})", ends.size() + 1,
                                         loaded.size(), l.orientation->index, l.end == 0 ? "start" : "end");
    beat.step(what);
    ends.push_back(direct_end(comm, s, interior.circles, *l.orientation, l.end, l.load_n_per_m, loads.empty(),
                              approach_over_estimate, level_beat(beat, what)));
    // A half-space end has no approach: the next end starts from the last FEM end's.
    if (ends.back().outside_model.empty() && !ends.back().half_space)
      approach_over_estimate = ends.back().study.approach_over_estimate();
  }
  return ends;
}

void log_flat_rim_node(const FlatRimNode& node)
{
  for (const FlatRimSide& side : node.sides)
    spdlog::info("rim loop: flat-rim at {:.2f} deg (c = {:.4f}, q = {:.5g} N/m, hull's R = {:.4g} m): peak {:.5g} "
                 "Pa, {:.4f} times line Hertz ({}: {:+.2f} % last level, {}; {:.0f} s)",
                 node.section_angle_rad / degree, side.centre_of_pressure, side.end_line_load_n_per_m,
                 side.end_radius_m, side.peak_pressure_pa, side.peak_pressure_pa / side.line_hertz_peak_pa,
                 side.converged ? "converged" : "NOT converged", 100 * side.last_change,
                 side.whole_ruling ? fmt::format("the whole ruling, where the shortened window gave {:.5g} Pa",
                                                 side.window_peak_pa)
                                   : fmt::format("{:+.2f} % longer window", 100 * side.window_change),
                 side.wall_s);
}

/// A rounded edge's flattest ends: the body's own, by half-space theory
/// (study/rims/flat_rim_table.h). Where half-space theory cannot stand for
/// them (the hull not found, or steep beside the contact), the FEM end table
/// takes them, as for a body with no such ends; the JSON says why.
void add_flat_rim_table(MPI_Comm comm, const RimLoopSettings& s, RimLoopResult& result, ProgressBeat& beat)
{
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  try
  {
    FlatRimTable flat = flat_rim_table(comm, flat_rim_settings(s), result.fem_sds.circles,
                                       result.fem_sds.centre_of_mass_m, s.flat_rim_from_rad, s.flat_rim_step_rad,
                                       &beat);
    result.flat_table = std::move(flat.nodes);
    result.flat_rim_refused = std::move(flat.refused);
    result.flat_from_rad
        = result.flat_rim_refused.empty() ? s.flat_rim_from_rad : result.flat_table.front().section_angle_rad;
    if (!result.flat_rim_refused.empty() && rank == 0)
      spdlog::warn("rim loop: {}", result.flat_rim_refused);
  }
  catch (const std::runtime_error& e) // a failed solve, or no orientation at a node's angle (InputError)
  {
    result.flat_rim_refused = e.what();
    if (rank == 0)
      spdlog::warn("rim loop: no flat-rim table, the FEM end table takes every end: {}", e.what());
  }
  for (const FlatRimNode& node : result.flat_table)
  {
    result.table_converged = result.table_converged && node.converged();
    if (rank == 0)
      log_flat_rim_node(node);
  }
}

/// The range of the dihedral angles over the loop's loaded ends (the
/// samples' and the directly modelled ones) whose section angle lies below
/// `below_section_rad`; none without such ends.
std::optional<std::pair<double, double>> dihedral_range(MPI_Comm comm, const loop_scores::LoopSamples& samples,
                                                        const std::vector<RimLoopEnd>& direct, double below_section_rad)
{
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  auto add = [&](double section, double dihedral) {
    if (section >= below_section_rad)
      return;
    lo = std::min(lo, dihedral);
    hi = std::max(hi, dihedral);
  };
  for (const loop_scores::RulingSample& ruling : samples.rulings)
    for (const loop_scores::LoadedEnd& end : ruling.ends)
      add(end.interior_angle_rad, end.dihedral_angle_rad);
  for (const RimLoopEnd& e : direct)
    add(e.section_angle_rad, e.dihedral_angle_rad);
  MPI_Allreduce(MPI_IN_PLACE, &lo, 1, MPI_DOUBLE, MPI_MIN, comm);
  MPI_Allreduce(MPI_IN_PLACE, &hi, 1, MPI_DOUBLE, MPI_MAX, comm);
  if (!(hi >= lo))
    return std::nullopt;
  return std::pair{lo, hi};
}

/// Over the loop's loaded ends (every rank's samples): the mean and the
/// largest of the sharp edge's exponent at the dihedral angle less that at
/// the section angle.
std::pair<double, double> exponent_shift(MPI_Comm comm, const loop_scores::LoopSamples& samples,
                                         const fem::RimEndSettings& end)
{
  double sums[2] = {0, 0}, largest = 0;
  for (const loop_scores::RulingSample& ruling : samples.rulings)
    for (const loop_scores::LoadedEnd& e : ruling.ends)
    {
      const double shift
          = sharp_edge_exponent(end, e.dihedral_angle_rad) - sharp_edge_exponent(end, e.interior_angle_rad);
      sums[0] += shift;
      sums[1] += 1;
      largest = std::max(largest, shift);
    }
  MPI_Allreduce(MPI_IN_PLACE, sums, 2, MPI_DOUBLE, MPI_SUM, comm);
  MPI_Allreduce(MPI_IN_PLACE, &largest, 1, MPI_DOUBLE, MPI_MAX, comm);
  return {sums[1] > 0 ? sums[0] / sums[1] : 0.0, largest};
}

/// The range of R over the loaded ends the end table stands for: the loop's
/// (as loop_scores::finished_end has them, inside the end model, below `flat_from_rad`)
/// and the directly modelled ones; none without such ends.
std::optional<std::pair<double, double>> sheet_radius_range(MPI_Comm comm, const loop_scores::LoopSamples& samples,
                                                            const std::vector<RimLoopEnd>& direct,
                                                            double edge_radius_m, double flat_from_rad)
{
  double lo = std::numeric_limits<double>::infinity(), hi = 0;
  auto add = [&](double radius) {
    lo = std::min(lo, radius);
    hi = std::max(hi, radius);
  };
  for (const loop_scores::RulingSample& ruling : samples.rulings)
    for (const loop_scores::LoadedEnd& hull_end : ruling.ends)
    {
      const loop_scores::LoadedEnd end = loop_scores::finished_end(hull_end, edge_radius_m);
      if (end.interior_angle_rad < flat_from_rad
          && loop_scores::half_width_over_radius(end) < fem::largest_half_width_over_radius)
        add(end.radius_m);
    }
  for (const RimLoopEnd& e : direct)
    if (e.outside_model.empty() && e.section_angle_rad < flat_from_rad)
      add(e.study.setup.radius_m);
  MPI_Allreduce(MPI_IN_PLACE, &lo, 1, MPI_DOUBLE, MPI_MIN, comm);
  MPI_Allreduce(MPI_IN_PLACE, &hi, 1, MPI_DOUBLE, MPI_MAX, comm);
  if (!(hi > 0))
    return std::nullopt;
  return std::pair{lo, hi};
}

/// The end table's q and R from the direct ends (their medians), and its
/// columns' R: that R alone, or with a rounded edge and a radius step
/// geometrically across the range of R at the loop's ends.
std::vector<double> end_table_columns(MPI_Comm comm, const RimLoopSettings& s, const loop_scores::LoopSamples& covered,
                                      RimLoopResult& result)
{
  std::vector<double> loads, radii;
  for (const RimLoopEnd& e : result.ends)
    if (e.outside_model.empty())
    {
      loads.push_back(e.study.setup.load_n_per_m);
      radii.push_back(e.study.setup.radius_m);
    }
  if (loads.empty())
    throw InputError(fmt::format("rim --body: the loop loads {} rim ends, but none of the {} orientations solved "
                                 "directly loads one the end model stands for; raise orientations",
                                 result.fem_sds.loop.loaded_ends, s.loop.orientations));
  result.reference_load_n_per_m = median(loads);
  result.reference_radius_m = median(radii);
  const auto range = s.end.edge_radius_m > 0 && s.end_table_radius_step > 0
                         ? sheet_radius_range(comm, covered, result.ends, s.end.edge_radius_m,
                                              result.flat_from_rad)
                         : std::nullopt;
  if (!range)
    return {result.reference_radius_m};
  std::vector<double> columns;
  for (const double log_radius :
       even_nodes(std::log(range->first), std::log(range->second), std::log(s.end_table_radius_step)))
    columns.push_back(std::exp(log_radius));
  return columns;
}

/// Marks the end table's nodes that the loop's look-ups read
/// (end_table_nodes_read): every loaded end of every rank's samples and the
/// direct ends below the flat-rim table, each by every node and by every
/// other (EndRatios, check_tables_against_direct_ends), and where the two
/// tables meet (RimLoopResult::flat_rim_seam). A node none reads is left
/// unsolved: no score, check or ratio of the loop depends on it.
void mark_reached_nodes(MPI_Comm comm, const RimLoopSettings& s, const loop_scores::LoopSamples& covered,
                        const RimLoopResult& result, std::vector<EndTableNode>& table)
{
  std::vector<int> reached(table.size(), 0);
  auto reach = [&](double angle, double radius) {
    for (const int stride : {1, 2})
      for (const std::size_t k : end_table_nodes_read(table, stride, result.singular_from_rad, angle, radius))
        reached[k] = 1;
  };
  const bool flat = !result.flat_table.empty();
  for (const loop_scores::RulingSample& ruling : covered.rulings)
    for (const loop_scores::LoadedEnd& hull_end : ruling.ends)
    {
      const loop_scores::LoadedEnd end = loop_scores::finished_end(hull_end, s.end.edge_radius_m);
      if (!flat || end.interior_angle_rad < result.flat_from_rad)
        reach(std::clamp(end.dihedral_angle_rad, smallest_modelled_angle_rad, largest_modelled_angle(s.end)),
              end.radius_m);
    }
  for (const RimLoopEnd& e : result.ends)
    if (!flat || e.section_angle_rad < result.flat_from_rad)
      reach(e.modelled_angle_rad, e.study.setup.radius_m);
  if (flat)
    reach(result.flat_rim_seam_dihedral(), result.flat_rim_seam_radius());
  MPI_Allreduce(MPI_IN_PLACE, reached.data(), static_cast<int>(reached.size()), MPI_INT, MPI_MAX, comm);
  for (std::size_t k = 0; k < table.size(); ++k)
    table[k].reached = reached[k] != 0;
}

/// The FEM end table (study/rims/end_table.h) over the loop's loaded ends'
/// angles from the smallest the end model takes to the last below the
/// singular angle, where the end model still finds a (square) edge, or to
/// where the flat-rim table takes over.
void add_end_table(MPI_Comm comm, const RimLoopSettings& s, const loop_scores::LoopSamples& covered,
                   RimLoopResult& result, ProgressBeat& beat)
{
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  // The dihedral angles of the ends the end table stands for: those below the flat-rim table's section angle.
  const auto range = dihedral_range(comm, covered, result.ends,
                                    result.flat_table.empty() ? std::numeric_limits<double>::infinity()
                                                              : result.flat_from_rad);
  const auto [lowest, highest]
      = range.value_or(std::pair{result.loaded_end_dihedral_min_rad, result.loaded_end_dihedral_min_rad});
  const double lo = std::max(lowest, smallest_modelled_angle_rad);
  const double hi = std::min({highest, result.singular_from_rad - 10 * singular_angle_tolerance_rad,
                              largest_modelled_angle(s.end)});
  const std::vector<double> columns = end_table_columns(comm, s, covered, result);
  // Each node's load control starts from the node before's converged
  // approach over its estimate (neighbours differ in angle or R only): one
  // load step fewer than from the estimate, which overshoots by about 20 %;
  // the first node from the last direct end's.
  double approach_over_estimate = 1;
  for (const RimLoopEnd& e : result.ends)
    if (!e.study.levels.empty() && !e.half_space)
      approach_over_estimate = e.study.approach_over_estimate();
  const std::vector<double> angles
      = end_table_angles(std::min(lo, hi), hi, s.end_table_step_rad, s.end_table_acute_step_rad);
  std::vector<EndTableNode> table;
  for (const double radius : columns)
    for (const double angle : angles)
      table.push_back({.dihedral_angle_rad = angle, .sheet_radius_m = radius, .reached = true, .study = {}});
  mark_reached_nodes(comm, s, covered, result, table);
  const auto reached = std::count_if(table.begin(), table.end(), [](const EndTableNode& n) { return n.reached; });
  if (rank == 0)
    spdlog::info("rim loop: the loop's ends read {} of the end table's {} nodes; the others are not solved", reached,
                 table.size());
  int solved = 0;
  for (EndTableNode& node : table)
  {
    if (!node.reached)
      continue;
    const double angle = node.dihedral_angle_rad, radius = node.sheet_radius_m;
    const std::string what = fmt::format("end table node {} of {} ({:.2f} deg, R = {:.4g} m)", ++solved, reached,
                                         angle / degree, radius);
    beat.step(what);
    fem::RimEndSettings settings = end_settings(s, radius, result.reference_load_n_per_m, angle);
    settings.first_approach_scale = approach_over_estimate;
    settings.on_level = level_beat(beat, what);
    std::tie(node.study, node.half_space) = loop_end_model(comm, settings, s.half_space_from_rad);
    if (!node.half_space) // a half-space end has no approach to start the next node from
      approach_over_estimate = node.study.approach_over_estimate();
    result.table_converged = result.table_converged && node.study.converged;
    if (rank == 0)
      spdlog::info("rim loop: end table at {:.2f} deg, R = {:.4g} m (r_e / b = {:.3g}{}): end/interior {} ({})",
                   angle / degree, radius, s.end.edge_radius_m / node.study.half_width_m,
                   node.half_space ? ", half-space theory" : "",
                   node.study.end_to_interior ? fmt::format("{:.4f}", *node.study.end_to_interior) : "none",
                   node.study.converged ? "converged" : "NOT converged");
  }
  result.table = std::move(table);
}

/// Each direct end's ratio from the tables, and the end table's largest
/// difference from the direct ends' own ratios.
void check_tables_against_direct_ends(RimLoopResult& result)
{
  const bool own_load = result.load_rule == contact::LoadRule::static_through_centre_of_mass;
  for (RimLoopEnd& e : result.ends)
  {
    if (!result.flat_table.empty() && e.section_angle_rad >= result.flat_from_rad)
    {
      // Not a check of the end table: the flat-rim table stands for it.
      if (e.study.hertz_peak_pa > 0)
        e.table_ratio = own_load ? flat_rim_peak(result.flat_table, 1, e.section_angle_rad) / e.study.hertz_peak_pa
                                 : flat_rim_ratio(result.flat_table, 1, e.section_angle_rad);
      continue;
    }
    e.table_ratio
        = end_table_ratio(result.table, 1, result.singular_from_rad, e.modelled_angle_rad, e.study.setup.radius_m);
    if (e.table_ratio && e.study.end_to_interior && e.study.resolved && !e.study.singular)
      // Over the larger of the end's and the interior's pressure, as the end
      // model's own change: an acute end's ratio tends to 0.
      result.table_vs_direct
          = std::max(result.table_vs_direct.value_or(0.0),
                     std::abs(*e.table_ratio - *e.study.end_to_interior) / std::max(*e.study.end_to_interior, 1.0));
  }
}
/// The load rules scored: the settings' first, then with each_load_rule the others.
std::vector<contact::LoadRule> scored_rules(const RimLoopSettings& s)
{
  std::vector<contact::LoadRule> rules = {s.loop.load_rule};
  if (s.each_load_rule)
    for (const auto& [name, rule] : contact::load_rule_names())
      if (rule != s.loop.load_rule)
        rules.push_back(rule);
  return rules;
}

/// This rank's ruling samples' loaded ends under every rule (the rulings
/// without their mapped points): what the end table's range and reached
/// nodes cover.
loop_scores::LoopSamples loaded_ends_of(const std::vector<RuleSamples>& rules)
{
  loop_scores::LoopSamples covered;
  for (const RuleSamples& rule : rules)
    for (const loop_scores::RulingSample& ruling : rule.samples.rulings)
      if (!ruling.ends.empty())
        covered.rulings.push_back({{}, ruling.ends, ruling.even});
  return covered;
}
} // namespace

fem::RimEndSettings resolved_as_loop_end(fem::RimEndSettings e, double depth_over_edge_radius)
{
  e.resolve_boundary_layer = true; // every end's ratio is a number of the end, not of the mesh
  // An end whose levels still differ gets a third, as a flat-rim node does:
  // the preprint's body's steel end table had 4 of 15 nodes at 3.3-6.4 %
  // per level (docs/notes/rim-runs.md).
  e.extra_levels = std::max(e.extra_levels, 1);
  // The fillet must fit in the block, and b varies from end to end: deepen
  // the block where the setting's H / b would be too shallow for this end's b.
  if (e.edge_radius_m > 0)
    e.depth_over_half_width = std::max(e.depth_over_half_width, depth_over_edge_radius * e.edge_radius_m / half_width(e));
  return e;
}

RimLoopResult run_rim_loop(MPI_Comm comm, const RimLoopSettings& settings)
{
  const RimLoopSettings s = checked_settings(settings);
  const auto start = std::chrono::steady_clock::now();
  fem::ensure_petsc();
  RimLoopResult result;
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  ProgressBeat beat("rim loop", rank == 0);
  beat.step(fmt::format("the interior (fem-sds; orientations solved directly: {})", s.loop.orientations));
  fem::SliceScaling slices(loop_scores::slice_settings(s.loop), s.loop.table_nodes_per_decade);
  result.fem_sds = loop_scores::run_fem_sds(comm, s.loop, slices);
  result.load_rule = s.loop.load_rule;
  beat.step("the loop's samples under each load rule scored");
  std::vector<RuleSamples> rules = rule_loop_samples(comm, s.loop, result.fem_sds, scored_rules(s));
  // The interior under each rule (the static rule's is fem-sds's own).
  std::vector<RuleLoop> loops;
  for (const RuleSamples& rule : rules)
    loops.push_back({rule.rule, loop_scores::loop_sds(comm, rule.samples, slices, loop_scores::loop_settings(s.loop)),
                     std::nullopt});
  result.ends = direct_ends(comm, s, result.fem_sds, rules.front().loads, beat);
  result.end_setup = end_settings(s, s.end.radius_m, s.end.load_n_per_m, s.end.interior_angle_rad);
  result.singular_from_rad = singular_from_angle(result.end_setup);
  result.half_space_from_rad = s.half_space_from_rad;

  // What the tables cover: every scored rule's loaded ends.
  const loop_scores::LoopSamples covered = loaded_ends_of(rules);
  const bool loaded = std::ranges::any_of(loops, [](const RuleLoop& l) { return l.loop.loaded_ends > 0; });
  if (const auto range = dihedral_range(comm, covered, result.ends, std::numeric_limits<double>::infinity()))
    std::tie(result.loaded_end_dihedral_min_rad, result.loaded_end_dihedral_max_rad) = *range;
  std::tie(result.exponent_shift_mean, result.exponent_shift_max)
      = exponent_shift(comm, rules.front().samples, result.end_setup);
  if (s.end.edge_radius_m > 0 && result.fem_sds.circles.size() == 2
      && std::ranges::any_of(loops, [&](const RuleLoop& l) {
           return l.loop.loaded_ends > 0 && l.loop.loaded_end_angle_max_rad >= s.flat_rim_from_rad;
         }))
  {
    beat.step("the flat-rim table (the loop's flattest ends, half-space theory)");
    add_flat_rim_table(comm, s, result, beat);
  }
  const bool with_tables = loaded && result.loaded_end_dihedral_min_rad <= result.singular_from_rad;
  if (with_tables)
  {
    add_end_table(comm, s, covered, result, beat);
    check_tables_against_direct_ends(result);
  }
  beat.step("the end-aware scores over the loop's samples");
  for (std::size_t k = 0; k < rules.size(); ++k)
  {
    std::vector<loop_scores::EndFactor> factors;
    if (with_tables)
    {
      const EndRatios ratios{result.table,
                             result.flat_table,
                             result.flat_from_rad,
                             result.singular_from_rad,
                             largest_modelled_angle(s.end),
                             rules[k].rule == contact::LoadRule::static_through_centre_of_mass};
      factors = ratios.factors();
      loops[k].largest_end = loop_largest_end(comm, rules[k].samples, rules[k].ruling_sample, rules[k].times_s,
                                              ratios, s.end.edge_radius_m, result.fem_sds.effective_modulus_pa);
    }
    else if (loops[k].loop.loaded_ends > 0) // every loaded end singular
      factors.push_back([](const loop_scores::LoadedEnd&) { return std::optional<double>(); });
    loops[k].loop.end_aware = loop_scores::end_aware_scores(comm, rules[k].samples, slices,
                                                            loop_scores::loop_settings(s.loop), factors,
                                                            s.end.edge_radius_m);
  }
  result.loop = std::move(loops.front().loop);
  result.largest_end = loops.front().largest_end;
  result.other_rules.assign(std::make_move_iterator(loops.begin() + 1), std::make_move_iterator(loops.end()));
  result.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}
} // namespace rollcheck::study::rims
