#include "study/life/fem_subsurface.h"
#include "contact/subsurface_pass.h"
#include "core/error.h"
#include "core/json_number.h"
#include <chrono>
#include <fmt/format.h>
#include <spdlog/spdlog.h>

namespace rollcheck::study::life
{
SubsurfaceCheck check_subsurface(const SubsurfaceSettings& s, double nu)
{
  if (s.refines.empty())
    throw InputError("life: the subsurface check needs at least one refinement level");
  const auto start = std::chrono::steady_clock::now();
  SubsurfaceCheck check;
  check.settings = s;
  const contact::DepthExtremum shear = contact::largest_over_depth(contact::FatigueCriterion::largest_shear, nu, 0);
  const contact::DepthExtremum orthogonal
      = contact::largest_over_depth(contact::FatigueCriterion::orthogonal_shear, nu, 0);
  check.closed_max_shear_over_p0 = shear.value_over_p0;
  check.closed_max_shear_depth_over_b = shear.z_over_b;
  check.closed_orthogonal_shear_over_p0 = orthogonal.value_over_p0;
  check.closed_orthogonal_shear_depth_over_b = orthogonal.z_over_b;
  check.closed_orthogonal_shear_offset_over_b = orthogonal.x_over_b;
  fem::SliceLoad load;
  load.radius_m = s.radius_m;
  load.load_n_per_m = s.load_n_per_m;
  for (const int refine : s.refines)
  {
    SubsurfaceLevel level;
    level.fem = fem::solve_slice_subsurface(load, s.slice, refine, s.degree);
    const double p0 = level.fem.hertz_peak_pressure_pa, b = level.fem.hertz_half_width_m;
    level.max_shear_over_p0 = level.fem.max_shear_pa / p0;
    level.max_shear_depth_over_b = level.fem.max_shear_depth_m / b;
    level.orthogonal_shear_over_p0 = level.fem.orthogonal_shear_pa / p0;
    level.orthogonal_shear_depth_over_b = level.fem.orthogonal_shear_depth_m / b;
    level.orthogonal_shear_offset_over_b = level.fem.orthogonal_shear_offset_m / b;
    spdlog::info("life: slice at refine {} ({:.0f} elements across b, {} dofs): max shear {:.4f} p0 at {:.4f} b, "
                 "orthogonal shear {:.4f} p0 at ({:.3f} b, {:.3f} b), {:.1f} s",
                 refine, level.fem.elements_across_b, level.fem.dofs, level.max_shear_over_p0,
                 level.max_shear_depth_over_b, level.orthogonal_shear_over_p0, level.orthogonal_shear_offset_over_b,
                 level.orthogonal_shear_depth_over_b, level.fem.wall_s);
    check.levels.push_back(level);
  }
  check.max_shear_ratio = check.levels.back().max_shear_over_p0 / check.closed_max_shear_over_p0;
  check.orthogonal_shear_ratio = check.levels.back().orthogonal_shear_over_p0 / check.closed_orthogonal_shear_over_p0;
  check.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return check;
}

nlohmann::json to_json(const SubsurfaceCheck& c)
{
  nlohmann::json levels = nlohmann::json::array();
  for (const SubsurfaceLevel& l : c.levels)
    levels.push_back({{"refine", l.fem.refine},
                      {"elements_across_b", json_number(l.fem.elements_across_b)},
                      {"dofs", l.fem.dofs},
                      {"load_n_per_m", json_number(l.fem.load_n_per_m)},
                      {"max_shear_over_p0", json_number(l.max_shear_over_p0)},
                      {"max_shear_depth_over_b", json_number(l.max_shear_depth_over_b)},
                      {"orthogonal_shear_over_p0", json_number(l.orthogonal_shear_over_p0)},
                      {"orthogonal_shear_depth_over_b", json_number(l.orthogonal_shear_depth_over_b)},
                      {"orthogonal_shear_offset_over_b", json_number(l.orthogonal_shear_offset_over_b)},
                      {"wall_s", json_number(l.fem.wall_s)}});
  const SubsurfaceLevel& finest = c.levels.back();
  auto change = [&](auto member) {
    return c.levels.size() < 2 ? nlohmann::json(nullptr)
                               : json_number(finest.*member / c.levels[c.levels.size() - 2].*member - 1);
  };
  return {{"slice_radius_m", json_number(c.settings.radius_m)},
          {"slice_load_n_per_m", json_number(c.settings.load_n_per_m)},
          {"fem_max_shear_over_p0", json_number(finest.max_shear_over_p0)},
          {"fem_max_shear_depth_over_b", json_number(finest.max_shear_depth_over_b)},
          {"fem_orthogonal_shear_over_p0", json_number(finest.orthogonal_shear_over_p0)},
          {"fem_orthogonal_shear_depth_over_b", json_number(finest.orthogonal_shear_depth_over_b)},
          {"fem_orthogonal_shear_offset_over_b", json_number(finest.orthogonal_shear_offset_over_b)},
          {"closed_max_shear_over_p0", json_number(c.closed_max_shear_over_p0)},
          {"closed_max_shear_depth_over_b", json_number(c.closed_max_shear_depth_over_b)},
          {"closed_orthogonal_shear_over_p0", json_number(c.closed_orthogonal_shear_over_p0)},
          {"closed_orthogonal_shear_depth_over_b", json_number(c.closed_orthogonal_shear_depth_over_b)},
          {"closed_orthogonal_shear_offset_over_b", json_number(c.closed_orthogonal_shear_offset_over_b)},
          {"change_last_refinement",
           {{"max_shear", change(&SubsurfaceLevel::max_shear_over_p0)},
            {"max_shear_depth", change(&SubsurfaceLevel::max_shear_depth_over_b)},
            {"orthogonal_shear", change(&SubsurfaceLevel::orthogonal_shear_over_p0)}}},
          {"max_shear_ratio", json_number(c.max_shear_ratio)},
          {"orthogonal_shear_ratio", json_number(c.orthogonal_shear_ratio)},
          {"levels", levels},
          {"wall_s", json_number(c.wall_s)}};
}
} // namespace rollcheck::study::life
