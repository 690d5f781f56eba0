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

SceneMesh build_rim_end_mesh(MPI_Comm comm, const RimEndGeometry& g, const RimEndSizes& sizes, VolumeMesher mesher)
{
  const auto start = std::chrono::steady_clock::now();
  check_rim_end_input(g, sizes);
  const double H = g.depth_m, L = g.length_m;
  // OpenCASCADE's tolerances are absolute (1e-7): the geometry is built with
  // H as the unit and the mesh scaled back.
  const RimEndGeometry unit{
      g.radius_m / H, g.interior_angle_rad, g.edge_radius_m / H, 1.0, L / H, g.flat_sheet, g.crossing_angle_rad};
  SceneMesh scene = distribute_quietly(comm, 3, [&] { return mesh_rim_end(unit, sizes, H, false, mesher); });
  tag_rim_end(
      scene, H, L, [](double, double, double) { return true; }, rim_end_block_planes(H, L),
      crosses_obliquely(g.crossing_angle_rad));
  scene.wall_s = seconds_since(start);
  return scene;
}
} // namespace rollcheck::fem
