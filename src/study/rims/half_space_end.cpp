#include "study/rims/half_space_end.h"
#include "contact/hertz.h"
#include "core/error.h"
#include "core/seconds_since.h"
#include <chrono>
#include <cmath>
#include <fmt/format.h>
#include <nlohmann/json.hpp>
#include <numbers>
#include <utility>

namespace rollcheck::study::rims
{
namespace
{
void check_settings(const HalfSpaceEndSettings& s)
{
  for (const auto& [value, name] : {std::pair{s.sheet_radius_m, "--sheet-radius"},
                                    {s.load_n_per_m, "--load-per-length"},
                                    {s.edge_radius_m, "--edge-radius"}, {s.youngs_modulus_pa, "--youngs-modulus"},
                                    {s.depth_over_edge_radius, "--block-depth"}})
    if (!(value > 0) || !std::isfinite(value))
      throw InputError(fmt::format("rounded-end: {} must be positive and finite, got {}", name, value));
  if (!(s.poisson_ratio > -1 && s.poisson_ratio < 0.5))
    throw InputError(fmt::format("rounded-end: --poisson must lie in (-1, 0.5), got {}", s.poisson_ratio));
  if (s.levels < 1)
    throw InputError("rounded-end: --levels must be at least 1");
}

/// The settings of level k: the finest cells halved k times.
contact::RoundedEndHalfSpaceSettings level_settings(const HalfSpaceEndStudy& study, int level)
{
  contact::RoundedEndHalfSpaceSettings s;
  s.radius_ratio = study.radius_ratio;
  s.held_length_over_half_width = study.held_length_over_half_width;
  s.grid = study.settings.grid;
  s.threads = study.settings.threads;
  s.max_bytes = largest_half_space_end_bytes;
  s.grid.finest_over_layer = study.settings.grid.finest_over_layer / std::pow(2.0, level);
  return s;
}
} // namespace

HalfSpaceEndStudy half_space_end(const HalfSpaceEndSettings& settings, const HalfSpaceEndProgress& progress)
{
  check_settings(settings);
  HalfSpaceEndStudy study;
  study.settings = settings;
  study.effective_modulus_pa
      = contact::effective_modulus(settings.youngs_modulus_pa, settings.poisson_ratio, settings.steel_counter_face);
  const contact::LineHertz hertz = contact::line_contact(settings.load_n_per_m, settings.sheet_radius_m,
                                                         study.effective_modulus_pa, settings.poisson_ratio);
  study.half_width_m = hertz.half_width_m;
  study.line_hertz_p0_pa = hertz.peak_pressure_pa;
  study.radius_ratio = settings.sheet_radius_m / settings.edge_radius_m;
  const double edge_over_b = settings.edge_radius_m / study.half_width_m;
  if (edge_over_b < 2)
    throw InputError(fmt::format("rounded-end: r_e = {:.3g} b (--edge-radius {} m against line Hertz's b = {:.3g} m): "
                                 "half-space theory needs the fillet well above the contact (r_e >= 2 b; it meets "
                                 "the FEM from about 20 b); use `rollcheck rim`",
                                 edge_over_b, settings.edge_radius_m, study.half_width_m));
  study.held_length_over_half_width = settings.depth_over_half_width > 0
                                          ? settings.depth_over_half_width
                                          : settings.depth_over_edge_radius * edge_over_b;
  study.boundary_layer_m = contact::boundary_layer_over_half_width(study.radius_ratio) * study.half_width_m;
  const double held = study.held_length_over_half_width, layer_over_b = study.boundary_layer_m / study.half_width_m;
  const std::string hold = settings.depth_over_half_width > 0
                               ? fmt::format("--depth {}", held)
                               : fmt::format("--depth 0: --block-depth {} r_e = {:.4g} b",
                                             settings.depth_over_edge_radius, held);
  if (!(held >= 10 && held <= largest_held_length_over_half_width))
    throw InputError(fmt::format("rounded-end: the line contact is held over {:.4g} b ({}); it must lie in [10, {}] b",
                                 held, hold, largest_held_length_over_half_width));
  if (held < 4 * layer_over_b)
    throw InputError(fmt::format("rounded-end: the hold ({}) lies within 4 of the fillet's boundary layers s = 2 r_e b "
                                 "/ (pi R) = {:.4g} b (--edge-radius {} m against --sheet-radius {} m): hold it longer",
                                 hold, layer_over_b, settings.edge_radius_m, settings.sheet_radius_m));
  // Every level's grid before any solve: the finest is the largest.
  const std::size_t finest_cells = contact::rounded_end_grid(level_settings(study, settings.levels - 1)).size();
  const double bytes = contact::graded_half_space_bytes(finest_cells);
  if (bytes > largest_half_space_end_bytes)
    throw InputError(fmt::format("rounded-end: the finest of {} levels has {} cells, whose dense matrices take {:.1f} "
                                 "GiB (at most {:.0f}); ask for fewer --levels, coarser --finest or --across, or a "
                                 "shorter --depth",
                                 settings.levels, finest_cells, bytes / (1ull << 30),
                                 largest_half_space_end_bytes / (1ull << 30)));
  for (int level = 0; level < settings.levels; ++level)
  {
    const contact::RoundedEndHalfSpaceSettings s = level_settings(study, level);
    const double finest_m = s.grid.finest_over_layer * study.boundary_layer_m;
    if (progress)
      progress(level, finest_m);
    const auto start = std::chrono::steady_clock::now();
    HalfSpaceEndLevel l{s.grid.finest_over_layer, contact::rounded_end_half_space(s), 0};
    l.wall_s = seconds_since(start);
    study.levels.push_back(l);
    study.end_factor.add(finest_m, l.end.peak_over_far);
  }
  study.converged = converged(study.end_factor, settings.tolerance);
  return study;
}

nlohmann::json to_json(const HalfSpaceEndStudy& study)
{
  const HalfSpaceEndSettings& s = study.settings;
  nlohmann::json levels = nlohmann::json::array();
  for (const HalfSpaceEndLevel& l : study.levels)
    levels.push_back({{"finest_cell_over_layer", l.finest_over_layer},
                      {"cells", l.end.cells},
                      {"active_set_passes", l.end.active_set_passes},
                      {"far_side_over_p0", l.end.far_over_p0},
                      {"peak_over_p0", l.end.peak_over_p0},
                      {"end_to_interior", l.end.peak_over_far},
                      {"peak_past_fillet_start_over_layer", l.end.peak_x_over_layer},
                      {"extent_over_half_width", l.end.extent_over_half_width},
                      {"wall_s", l.wall_s}});
  return {{"model", "half-space, graded grid"},
          {"sheet_radius_m", s.sheet_radius_m},
          {"load_n_per_m", s.load_n_per_m},
          {"edge_radius_m", s.edge_radius_m},
          {"youngs_modulus_pa", s.youngs_modulus_pa},
          {"poisson_ratio", s.poisson_ratio},
          {"counter_face", s.steel_counter_face ? "steel" : "rigid"},
          {"effective_modulus_pa", study.effective_modulus_pa},
          {"half_width_m", study.half_width_m},
          {"line_hertz_peak_pa", study.line_hertz_p0_pa},
          {"sheet_over_edge_radius", study.radius_ratio},
          {"edge_radius_over_half_width", s.edge_radius_m / study.half_width_m},
          {"boundary_layer_m", study.boundary_layer_m},
          {"depth_over_half_width", s.depth_over_half_width},
          {"depth_over_edge_radius", s.depth_over_edge_radius},
          {"held_length_over_half_width", study.held_length_over_half_width},
          {"across_over_half_width", s.grid.across_over_half_width},
          {"tolerance", s.tolerance},
          {"levels", levels},
          {"last_change", last_change(study.end_factor)},
          {"converged", study.converged},
          {"end_to_interior", study.end_to_interior()},
          {"peak_pressure_pa", study.peak_pressure_pa()}};
}

std::string report(const HalfSpaceEndStudy& study)
{
  const HalfSpaceEndSettings& s = study.settings;
  std::string text = fmt::format(
      "rounded end by half-space theory: R = {:.4g} m, q = {:.4g} N/m, r_e = {:.4g} m ({} counter-face): b = {:.4g} m, "
      "p0 = {:.4g} Pa, R / r_e = {:.4g}, r_e / b = {:.4g}, held over {:.4g} b\n",
      s.sheet_radius_m, s.load_n_per_m, s.edge_radius_m, s.steel_counter_face ? "steel" : "rigid", study.half_width_m,
      study.line_hertz_p0_pa, study.radius_ratio, s.edge_radius_m / study.half_width_m,
      study.held_length_over_half_width);
  text += "| finest cell / s | cells | far side / p0 | peak / p0 | end / interior | peak at x / s | wall s |\n";
  text += "|---|---|---|---|---|---|---|\n";
  for (const HalfSpaceEndLevel& l : study.levels)
    text += fmt::format("| {:.4g} | {} | {:.4f} | {:.4f} | {:.4f} | {:.2f} | {:.1f} |\n", l.finest_over_layer,
                        l.end.cells, l.end.far_over_p0, l.end.peak_over_p0, l.end.peak_over_far,
                        l.end.peak_x_over_layer, l.wall_s);
  const double change = last_change(study.end_factor);
  text += study.levels.size() < 2
              ? fmt::format("end / interior {:.4f} from one level: not checked for convergence (--levels 2)\n",
                            study.end_to_interior())
              : fmt::format("end / interior {:.4f}, last level {:+.2f} %: {}\n", study.end_to_interior(), 100 * change,
                            study.converged ? "converged" : "NOT converged");
  return text;
}
} // namespace rollcheck::study::rims
