// The structured grid of the sharp square end (fem/mesh/square_end_grid_mesh.h).
#include "fem/mesh/square_end_grid_mesh.h"
#include "core/error.h"
#include "fem/mesh/mesh_grading.h"
#include "fem/mesh/rim_end_solid.h"
#include <algorithm>
#include <array>
#include <cmath>
#include <fmt/format.h>

namespace rollcheck::fem
{
using namespace scene_build;

namespace
{
/// The sheared grid (fem/mesh/square_end_grid_mesh.h) of the block x in
/// [-L, 0], y and z in [0, H], its end face leaning by `lean`.
RawMesh sheared_grid(double H, double L, double lean, const RimEndSizes& sizes)
{
  // Across the edge (x from it, z from the sheet) h_e growing; along it
  // (y) the strip's size over the contact zone: the edge's field varies on
  // the scale b along the edge, and on the element's own scale across it.
  const std::vector<double> along_x = graded_nodes(L, sizes.edge_m, 0, sizes.growth, sizes.far_m);
  const std::vector<double> along_y = graded_nodes(H, sizes.contact_m, sizes.contact_zone_m, sizes.growth, sizes.far_m);
  const std::vector<double> along_z = graded_nodes(H, sizes.edge_m, 0, sizes.growth, sizes.far_m);
  const std::size_t nx = along_x.size(), ny = along_y.size(), nz = along_z.size();
  RawMesh raw;
  raw.x.reserve(3 * nx * ny * nz);
  for (std::size_t i = 0; i < nx; ++i)
    for (std::size_t j = 0; j < ny; ++j)
      for (std::size_t k = 0; k < nz; ++k)
        // Sheared so that the end face x = 0 leans by a - 90 deg, the far side fixed.
        raw.x.insert(raw.x.end(),
                     {-along_x[i] + along_z[k] * std::tan(lean) * (1 - along_x[i] / L), along_y[j], along_z[k]});
  auto node = [&](std::size_t i, std::size_t j, std::size_t k) {
    return static_cast<std::int64_t>((i * ny + j) * nz + k);
  };
  // Kuhn's six tetrahedra about each box's diagonal, one per order of the
  // axes: conforming across the grid, and each a path simplex with no
  // obtuse dihedral angle whatever the box's aspect ratio.
  constexpr std::array<std::array<int, 3>, 6> orders{
      {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}}};
  raw.cells.reserve(24 * (nx - 1) * (ny - 1) * (nz - 1));
  for (std::size_t i = 0; i + 1 < nx; ++i)
    for (std::size_t j = 0; j + 1 < ny; ++j)
      for (std::size_t k = 0; k + 1 < nz; ++k)
        for (const std::array<int, 3>& order : orders)
        {
          std::array<std::size_t, 3> corner{i, j, k};
          raw.cells.push_back(node(corner[0], corner[1], corner[2]));
          for (int axis : order)
          {
            ++corner[axis];
            raw.cells.push_back(node(corner[0], corner[1], corner[2]));
          }
        }
  return raw;
}
} // namespace

SceneMesh build_square_end_grid_mesh(MPI_Comm comm, const RimEndGeometry& g, const RimEndSizes& sizes)
{
  const auto start = std::chrono::steady_clock::now();
  const double H = g.depth_m, L = g.length_m;
  const double lean = g.interior_angle_rad - std::numbers::pi / 2;
  if (!g.flat_sheet || !(std::abs(lean) <= max_grid_end_lean_rad) || g.edge_radius_m != 0)
    throw InputError(fmt::format("rim end grid: only a sharp end within {:.0f} deg of square (interior angle {:.3f} "
                                 "deg, edge radius {} m) on the flat sheet",
                                 max_grid_end_lean_rad * 180 / std::numbers::pi,
                                 g.interior_angle_rad * 180 / std::numbers::pi, g.edge_radius_m));
  for (double v : {H, L, sizes.edge_m, sizes.contact_m, sizes.contact_zone_m, sizes.far_m, sizes.growth})
    if (!std::isfinite(v) || v <= 0)
      throw InputError(fmt::format("rim end grid: depth, length and element sizes must be positive and finite "
                                   "(H = {} m, L = {} m, sizes {} m, {} m, {} m, {} m, growth {})",
                                   H, L, sizes.edge_m, sizes.contact_m, sizes.contact_zone_m, sizes.far_m,
                                   sizes.growth));
  SceneMesh scene = distribute(comm, 3, [&] { return sheared_grid(H, L, lean, sizes); });
  const double tol = 1e-9 * H;
  // The sheet, and the end face where it faces the plane (obtuse, as in
  // build_rim_end_mesh; a square or acute end's face never does).
  tag_rim_end(
      scene, H, L,
      [=](double x, double, double z) { return std::abs(z) < tol || std::abs(x - z * std::tan(lean)) < tol; },
      [](double, double, double) { return false; });
  scene.wall_s = seconds_since(start);
  return scene;
}
} // namespace rollcheck::fem
