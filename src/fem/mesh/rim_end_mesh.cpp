// The rim end's mesh (fem/mesh/rim_end_mesh.h).
#include "fem/mesh/rim_end_mesh.h"
#include "core/error.h"
#include "fem/mesh/oblique_end_angle.h"
#include "fem/mesh/rim_end_distribute.h"
#include "fem/mesh/rim_end_solid.h"
#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <numbers>

namespace rollcheck::fem
{
using namespace scene_build;

SceneMesh build_rim_end_mesh(MPI_Comm comm, const RimEndGeometry& g, const RimEndSizes& sizes)
{
  const auto start = std::chrono::steady_clock::now();
  const double H = g.depth_m, L = g.length_m;
  for (double v : {g.radius_m, H, L, sizes.edge_m, sizes.contact_m, sizes.far_m, sizes.growth})
    if (!std::isfinite(v) || v <= 0)
      throw InputError(fmt::format("rim end: radius, depth, length and element sizes must be positive and finite "
                                   "(R = {} m, H = {} m, L = {} m, sizes {} m, {} m, {} m, growth {})",
                                   g.radius_m, H, L, sizes.edge_m, sizes.contact_m, sizes.far_m, sizes.growth));
  if (!(g.interior_angle_rad >= std::numbers::pi / 3 && g.interior_angle_rad < std::numbers::pi))
    throw InputError(fmt::format("rim end: the interior angle must lie in [60, 180) deg, got {} deg",
                                 g.interior_angle_rad * 180 / std::numbers::pi));
  if (!(g.edge_radius_m >= 0 && g.edge_radius_m < largest_edge_radius_over_depth * H) || (!g.flat_sheet && g.radius_m < H))
    throw InputError(fmt::format("rim end: need 0 <= edge radius < {} H, and R >= H for the cylinder sheet (edge "
                                 "radius {} m, R = {} m, H = {} m)",
                                 largest_edge_radius_over_depth, g.edge_radius_m, g.radius_m, H));
  // OpenCASCADE's tolerances are absolute (1e-7): the geometry is built with
  // H as the unit and the mesh scaled back.
  const RimEndGeometry unit{
      g.radius_m / H, g.interior_angle_rad, g.edge_radius_m / H, 1.0, L / H, g.flat_sheet, g.crossing_angle_rad};
  SceneMesh scene = distribute_quietly(comm, 3, [&] { return mesh_rim_end(unit, sizes, H, false); });
  const double tol = 1e-9 * H;
  tag_rim_end(
      scene, H, L, [](double, double, double) { return true; },
      [=](double x, double y, double z) {
        return std::abs(x + L) < tol || std::abs(x - H) < tol || std::abs(y) < tol || std::abs(y - H) < tol
               || std::abs(z - H) < tol;
      },
      crosses_obliquely(g.crossing_angle_rad));
  scene.wall_s = seconds_since(start);
  return scene;
}
} // namespace rollcheck::fem
