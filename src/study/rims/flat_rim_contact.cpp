#include "study/rims/flat_rim_contact.h"
#include "contact/ruling_end_surface.h"
#include "contact/straight_rim_end.h"
#include "core/error.h"
#include "oracle/line_load.h"
#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <memory>
#include <nlohmann/json.hpp>
#include <numbers>
#include <utility>

namespace rollcheck::study::rims
{
namespace
{
void check_settings(const FlatRimSettings& s)
{
  for (const auto& [value, name] : {std::pair{s.body.radius_m, "--radius"}, {s.normal_load_n, "--load"},
                                    {s.edge_radius_m, "--edge-radius"}, {s.youngs_modulus_pa, "--youngs-modulus"},
                                    {s.sheet_radius_m, "--sheet-radius"}, {s.load_n_per_m, "--load-per-length"},
                                    {s.cells_per_half_width, "--cells"}, {s.before_over_half_width, "--before"},
                                    {s.after_over_half_width, "--after"}, {s.across_over_half_width, "--across"}})
    if (!(value > 0) || !std::isfinite(value))
      throw InputError(fmt::format("flat-rim: {} must be positive and finite, got {}", name, value));
  if (!(s.poisson_ratio > -1 && s.poisson_ratio < 0.5))
    throw InputError(fmt::format("flat-rim: --poisson must lie in (-1, 0.5), got {}", s.poisson_ratio));
  if (s.levels < 1)
    throw InputError("flat-rim: --levels must be at least 1");
  if (s.extra_levels < 0)
    throw InputError("flat-rim: --extra-levels must not be negative");
  const auto check_angle = [](double angle, const char* name) {
    if (!(angle >= smallest_flat_rim_angle_rad && angle <= std::numbers::pi))
      throw InputError(fmt::format("flat-rim: {} {} deg is outside [{}, 180] deg, where the rim's other face is "
                                   "gentle enough for half-space theory (use `rollcheck rim`)",
                                   name, angle * 180 / std::numbers::pi,
                                   smallest_flat_rim_angle_rad * 180 / std::numbers::pi));
  };
  if (s.interior_angle_rad != 0)
    check_angle(s.interior_angle_rad, "--interior-angle");
  check_angle(s.end_angle_rad, "--end-angle");
}

/// A loop's loaded end as the method's problem: the hull near it, the
/// sheet's radius linear along the ruling, and the contact locus's
/// no-tension linear rule from this end (oracle::line_load) carrying F,
/// balanced again beyond the window. ComputationError for an end the rule
/// leaves unloaded.
contact::RoundedEndProblem loop_end_problem(const LoopEnd& loop_end, double normal_load_n)
{
  const oracle::Ruling& ruling = loop_end.ruling;
  const auto surface = std::make_shared<const contact::RulingEndSurface>(loop_end.circles, ruling, loop_end.end);
  contact::RoundedEndProblem end;
  end.hull_height = [surface](double x, double y) { return surface->height(x, y); };
  // Linear along the ruling: exact for a developable sheet.
  end.sheet_radius = [r0 = loop_end.radius_m(), r1 = loop_end.other_radius_m(), length = ruling.length_m](double x) {
    return r0 + (r1 - r0) * std::clamp(x / length, 0.0, 1.0);
  };
  const double c = loop_end.centre_of_pressure_from_end();
  const auto q = [&](double f) { return oracle::line_load(normal_load_n, c, ruling.length_m, f); };
  if (!(q(0) > 0))
    throw ComputationError(fmt::format("flat rim: the end carries no load (c = {:.4f} from it)", c));
  end.load = contact::RulingLineLoad::no_tension(
      q(0), c < 1.0 / 3 ? -q(0) / (3 * c * ruling.length_m) : (q(1) - q(0)) / ruling.length_m, ruling.length_m);
  end.ruling_length_m = ruling.length_m;
  end.balance_body = true;
  return end;
}

/// The levels' table: a row per level.
std::string level_table(const FlatRimContact& r)
{
  std::string table = "| level | cell (m) | cells | CG iterations | solves | peak p (Pa) | peak at x', y (m) | "
                      "contact from x' (m) | far station / line Hertz - 1 | s |\n|---|---|---|---|---|---|---|---|---|---|\n";
  for (const FlatRimLevel& l : r.levels)
    table += fmt::format("| {} | {:.3g} | {} | {} | {} | {:.5g} | {:.3g}, {:.3g} | {:.3g} | {:+.2f} % | {:.1f} |\n",
                         &l - r.levels.data(), l.cell_m, l.cells, l.iterations, l.solves, l.peak_pressure_pa,
                         l.peak_along_m, l.peak_across_m, l.contact_start_m,
                         100 * (l.far_peak_pa / l.far_line_hertz_pa - 1), l.wall_s);
  return table;
}
} // namespace

double end_hull_height(const LoopEnd& end, double along_m, double across_m)
{
  return contact::RulingEndSurface(end.circles, end.ruling, end.end).height(along_m, across_m);
}

FlatRimContact flat_rim_contact(const FlatRimSettings& s, const contact::RoundedEndProgress& progress)
{
  check_settings(s);
  if (s.interior_angle_rad == 0)
    return flat_rim_contact(s, body_loop_end(s.body, s.end_angle_rad, s.loop_side), progress);
  if (s.whole_ruling)
    throw InputError("flat-rim: --whole-ruling solves a body's loop end; a straight rim's load is held along a long "
                     "contact, with no ruling to end it (drop --interior-angle or --whole-ruling)");
  const contact::RoundedEndProblem end
      = contact::straight_rim_end(s, s.interior_angle_rad, s.sheet_radius_m, s.load_n_per_m);
  // The straight rim is square to the ruling: its section is its dihedral.
  return {contact::solve_rounded_end(s, end, progress), 0.0, 0.0, s.interior_angle_rad, s.sheet_radius_m,
          s.interior_angle_rad};
}

FlatRimContact flat_rim_contact(const FlatRimSettings& s, const LoopEnd& loop_end,
                                const contact::RoundedEndProgress& progress)
{
  check_settings(s);
  if (!(loop_end.interior_angle_rad >= smallest_flat_rim_angle_rad))
    throw InputError(fmt::format("flat-rim: the end's interior angle, {:.4g} deg, is below {} deg (use `rollcheck rim`)",
                                 loop_end.interior_angle_rad * 180 / std::numbers::pi,
                                 smallest_flat_rim_angle_rad * 180 / std::numbers::pi));
  const contact::RoundedEndProblem end = loop_end_problem(loop_end, s.normal_load_n);
  return {contact::solve_rounded_end(s, end, progress), loop_end.ruling.length_m,
          loop_end.centre_of_pressure_from_end(),
          loop_end.interior_angle_rad, loop_end.radius_m(), loop_end.dihedral_angle_rad()};
}

nlohmann::json to_json(const FlatRimContact& r)
{
  nlohmann::json levels = nlohmann::json::array();
  for (const FlatRimLevel& l : r.levels)
    levels.push_back({{"cell_m", l.cell_m},
                      {"cells", l.cells},
                      {"iterations", l.iterations},
                      {"solves", l.solves},
                      {"peak_pressure_pa", l.peak_pressure_pa},
                      {"peak_along_m", l.peak_along_m},
                      {"peak_across_m", l.peak_across_m},
                      {"contact_start_m", l.contact_start_m},
                      {"window_load_change", l.window_load_change},
                      {"balanced_end_line_load_n_per_m", l.balanced_end_line_load_n_per_m},
                      {"balanced_slope_n_per_m2", l.balanced_slope_n_per_m2},
                      {"balanced_loaded_length_m", l.balanced_loaded_length_m},
                      {"far_peak_pa", l.far_peak_pa},
                      {"far_line_hertz_pa", l.far_line_hertz_pa},
                      {"wall_s", l.wall_s},
                      {"station_m", l.station_m},
                      {"station_peak_pa", l.station_peak_pa},
                      {"station_load_n_per_m", l.station_load_n_per_m}});
  return {{"ruling_length_m", r.ruling_length_m},
          {"end_interior_angle_deg", r.interior_angle_rad * 180 / std::numbers::pi},
          {"end_dihedral_angle_deg", r.dihedral_angle_rad * 180 / std::numbers::pi},
          {"end_sheet_radius_m", r.end_radius_m},
          {"centre_of_pressure", r.centre_of_pressure},
          {"end_line_load_n_per_m", r.end_line_load_n_per_m},
          {"effective_modulus_pa", r.effective_modulus_pa},
          {"reference_radius_m", r.reference_radius_m},
          {"half_width_m", r.half_width_m},
          {"line_hertz_peak_pa", r.line_hertz_peak_pa},
          {"largest_slope", r.largest_slope},
          {"end_lift_m", r.end_lift_m},
          {"peak_pressure_pa", r.levels.back().peak_pressure_pa},
          {"far_line_hertz_error", r.levels.back().far_peak_pa / r.levels.back().far_line_hertz_pa - 1},
          {"last_change", r.last_change},
          // The whole ruling has no longer window.
          {"longer_window_peak_pa", r.whole_ruling ? nlohmann::json(nullptr) : nlohmann::json(r.longer_window_peak_pa)},
          {"window_change", r.whole_ruling ? nlohmann::json(nullptr) : nlohmann::json(r.window_change)},
          {"after_over_half_width", r.after_over_half_width},
          {"across_scale", r.across_scale},
          {"whole_ruling", r.whole_ruling},
          {"converged", r.converged},
          {"wall_s", r.wall_s},
          {"levels", levels}};
}

std::string report(const FlatRimSettings& setup, const FlatRimContact& r)
{
  const double peak = r.levels.back().peak_pressure_pa;
  const std::string what =
      setup.interior_angle_rad > 0
          ? fmt::format("straight rim of {:.4g} deg across a sheet of R = {} m, q = {} N/m",
                        setup.interior_angle_rad * 180 / std::numbers::pi, setup.sheet_radius_m, setup.load_n_per_m)
          : fmt::format("{} r1 = {} m at its loop's end of {:.4f} deg ({}c = {:.4f} from the end, hull's R there "
                        "{:.4g} m), F = {} N, q = {:.6g} N/m at the end",
                        setup.body.body, setup.body.radius_m, r.interior_angle_rad * 180 / std::numbers::pi,
                        setup.end_angle_rad < std::numbers::pi ? (setup.loop_side == 0 ? "forwards, " : "backwards, ")
                                                               : "the flattest, ",
                        r.centre_of_pressure, r.end_radius_m, setup.normal_load_n, r.end_line_load_n_per_m);
  const std::string window
      = r.whole_ruling ? fmt::format("the whole loaded ruling: the grid reaches {:.4g} b along it", r.after_over_half_width)
                       : fmt::format("{:+.2f} % with the first level's window twice as long; the window {:.4g} b along "
                                     "the ruling",
                                     100 * r.window_change, r.after_over_half_width);
  return fmt::format("\n{}, counter-face {}, edge radius {} m: b = {:.4g} m (R = {:.4g} m), E* = {:.4g} Pa\n\n{}\npeak "
                     "{:.5g} Pa ({}: {:+.2f} % at the last level, {}, {:.3g} times --across across); line Hertz at the "
                     "end's q with R = max(R_end, r_e) gives {:.5g} Pa (peak / that = {:.4f}); the rounded surface lies "
                     "{:.3g} m above the ground at the end; largest slope over the contact {:.3f} (half-space theory)\n",
                     what, setup.steel_counter_face ? "steel" : "rigid", setup.edge_radius_m, r.half_width_m,
                     r.reference_radius_m, r.effective_modulus_pa, level_table(r), peak,
                     r.converged ? "converged" : "NOT converged", 100 * r.last_change, window, r.across_scale,
                     r.line_hertz_peak_pa, peak / r.line_hertz_peak_pa, r.end_lift_m, r.largest_slope);
}
} // namespace rollcheck::study::rims
