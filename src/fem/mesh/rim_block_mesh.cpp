// The rim end on a block (fem/mesh/rim_block_mesh.h).
#include "fem/mesh/rim_block_mesh.h"
#include "core/error.h"
#include "fem/mesh/rim_end_distribute.h"
#include "fem/mesh/rim_end_solid.h"
#include <cmath>
#include <dolfinx/mesh/utils.h>

namespace rollcheck::fem
{
using namespace scene_build;

SceneMesh build_rim_block_mesh(MPI_Comm comm, const RimEndGeometry& g, const RimEndSizes& sizes, VolumeMesher mesher)
{
  const auto start = std::chrono::steady_clock::now();
  if (!g.flat_sheet)
    throw InputError("rim end on a block: the sheet must be flat (its profile in the initial gap)");
  const double H = g.depth_m, L = g.length_m;
  const RimEndGeometry unit{g.radius_m / H, g.interior_angle_rad, g.edge_radius_m / H, 1.0, L / H, true};
  SceneMesh scene = distribute_quietly(comm, 3, [&] { return mesh_rim_end(unit, sizes, H, true, mesher); });
  const double tol = 1e-9 * H;
  SceneParts parts = rim_end_planes(L, tol);
  parts.top = [=](double, double, double z) { return std::abs(std::abs(z) - H) < tol; };
  parts.curved = [](double, double, double) { return false; };
  parts.in_plane = [](double, double, double) { return true; };
  tag_parts(scene, parts);
  // The body's face on the interface and, rounded, its fillet (which lifts
  // off the block's top: mortar pairs), the cylinder of radius r_e about
  // the line (-x_t, y, r_e), x_t = r_e tan((180 deg - a) / 2).
  const double r_e = g.edge_radius_m, x_t = fillet_start_distance(r_e, g.interior_angle_rad);
  upper_interface_facets(
      scene,
      [=](double x, double, double z) {
        return (std::abs(z) < tol && x < tol)
               || (r_e > 0 && x > -x_t - tol && z < r_e && std::abs(std::hypot(x + x_t, z - r_e) - r_e) < 1e-6 * r_e);
      },
      2);
  // A facet of the side planes y = 0, H whose corners all lie on the
  // fillet's end arc passes the corner test but is not on the fillet.
  const int fdim = scene.mesh->topology().dim() - 1;
  const std::vector<double> mid = dolfinx::mesh::compute_midpoints(*scene.mesh, fdim, scene.contact_facets);
  std::vector<std::int32_t> on_fillet_or_face;
  for (std::size_t i = 0; i < scene.contact_facets.size(); ++i)
    if (std::abs(mid[3 * i + 1]) > tol && std::abs(mid[3 * i + 1] - H) > tol)
      on_fillet_or_face.push_back(scene.contact_facets[i]);
  scene.contact_facets = std::move(on_fillet_or_face);
  scene.symmetry_multiplicity = 2;
  scene.wall_s = seconds_since(start);
  return scene;
}
} // namespace rollcheck::fem
