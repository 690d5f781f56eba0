// The outward normals' z components of boundary facets (fem/mesh/scene_facets.h).
#include "fem/mesh/scene_facets.h"
#include <array>
#include <cmath>
#include <dolfinx/mesh/utils.h>

namespace rollcheck::fem
{
std::vector<double> outward_normal_z(const dolfinx::mesh::Mesh& mesh, std::span<const std::int32_t> facets)
{
  const int tdim = mesh.topology().dim();
  const std::vector<std::int32_t> nodes = dolfinx::mesh::entities_to_geometry(mesh, tdim - 1, facets, false);
  auto facet_cells = mesh.topology().connectivity(tdim - 1, tdim);
  std::vector<std::int32_t> cells;
  for (std::int32_t f : facets)
    cells.push_back(facet_cells->links(f)[0]);
  const std::vector<double> cell_mid = dolfinx::mesh::compute_midpoints(mesh, tdim, cells);
  std::span<const double> x = mesh.geometry().x();
  std::vector<double> normal_z;
  for (std::size_t i = 0; i < facets.size(); ++i)
  {
    const double* p0 = &x[3 * nodes[3 * i]];
    const double* p1 = &x[3 * nodes[3 * i + 1]];
    const double* p2 = &x[3 * nodes[3 * i + 2]];
    const std::array<double, 3> a{p1[0] - p0[0], p1[1] - p0[1], p1[2] - p0[2]};
    const std::array<double, 3> c{p2[0] - p0[0], p2[1] - p0[1], p2[2] - p0[2]};
    std::array<double, 3> n{a[1] * c[2] - a[2] * c[1], a[2] * c[0] - a[0] * c[2], a[0] * c[1] - a[1] * c[0]};
    // Outward: away from the cell's midpoint.
    double away = 0;
    for (int k = 0; k < 3; ++k)
      away += n[k] * ((p0[k] + p1[k] + p2[k]) / 3 - cell_mid[3 * i + k]);
    normal_z.push_back((away < 0 ? -n[2] : n[2]) / std::hypot(n[0], n[1], n[2]));
  }
  return normal_z;
}
} // namespace rollcheck::fem
