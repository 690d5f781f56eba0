// A scene mesh distributed and its parts tagged (fem/mesh/scene_parts.h).
#include "fem/mesh/scene_parts.h"
#include "fem/on_rank_zero.h"
#include <dolfinx/mesh/utils.h>
#include <xtensor/xtensor.hpp>

namespace rollcheck::fem::scene_build
{
std::vector<std::int32_t> boundary_facets(const dolfinx::mesh::Mesh& mesh, const Predicate& on)
{
  const int fdim = mesh.topology().dim() - 1;
  return dolfinx::mesh::locate_entities_boundary(mesh, fdim, [&](const xt::xtensor<double, 2>& x) {
    xt::xtensor<bool, 1> marked = xt::zeros<bool>({x.shape(1)});
    for (std::size_t i = 0; i < x.shape(1); ++i)
      marked(i) = on(x(0, i), x(1, i), x(2, i));
    return marked;
  });
}

SceneMesh distribute(MPI_Comm comm, int gdim, const std::function<RawMesh()>& make_raw)
{
  SceneMesh scene;
  scene.mesh = distribute_raw_mesh(comm, gdim, on_rank_zero<RawMesh>(comm, make_raw));
  return scene;
}

void tag_parts(SceneMesh& scene, const SceneParts& parts)
{
  const dolfinx::mesh::Mesh& mesh = *scene.mesh;
  const int fdim = mesh.topology().dim() - 1;
  if (parts.symmetry_x)
    scene.symmetry_x_facets = boundary_facets(mesh, parts.symmetry_x);
  if (parts.symmetry_y)
    scene.symmetry_y_facets = boundary_facets(mesh, parts.symmetry_y);
  scene.top_facets = boundary_facets(mesh, parts.top);
  std::vector<std::int32_t> candidates = boundary_facets(mesh, parts.curved);
  const std::vector<double> mid = dolfinx::mesh::compute_midpoints(mesh, fdim, candidates);
  const std::vector<double> normal_z
      = parts.facing_plane_only ? outward_normal_z(mesh, candidates) : std::vector<double>(candidates.size(), -1.0);
  for (std::size_t i = 0; i < candidates.size(); ++i)
    if (!parts.in_plane(mid[3 * i], mid[3 * i + 1], mid[3 * i + 2]) && normal_z[i] < -1e-6)
      scene.contact_facets.push_back(candidates[i]);
}

void upper_interface_facets(SceneMesh& scene, const Predicate& on, int up)
{
  const dolfinx::mesh::Mesh& mesh = *scene.mesh;
  const int tdim = mesh.topology().dim();
  const std::vector<std::int32_t> interface = boundary_facets(mesh, on);
  auto facet_cells = mesh.topology().connectivity(tdim - 1, tdim);
  std::vector<std::int32_t> cells;
  for (std::int32_t f : interface)
    cells.push_back(facet_cells->links(f)[0]);
  const std::vector<double> mid = dolfinx::mesh::compute_midpoints(mesh, tdim, cells);
  for (std::size_t i = 0; i < interface.size(); ++i)
    if (mid[3 * i + up] > 0)
      scene.contact_facets.push_back(interface[i]);
}
} // namespace rollcheck::fem::scene_build
