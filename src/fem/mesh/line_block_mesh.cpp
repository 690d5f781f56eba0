// Two bodies in plane strain as twins along their interface
// (fem/mesh/line_block_mesh.h).
#include "fem/mesh/line_block_mesh.h"
#include "fem/mesh/gmsh_scene.h"
#include "fem/mesh/scene_parts.h"
#include <cmath>
#include <gmsh.h>

namespace rollcheck::fem
{
using namespace scene_build;

SceneMesh build_line_block_mesh(MPI_Comm comm, double size_m, const MeshGrading& grading)
{
  const auto start = std::chrono::steady_clock::now();
  const double W = size_m;
  SceneMesh scene = distribute(comm, 2, [&] {
    return mesh_with_gmsh(2, [&] {
      namespace occ = gmsh::model::occ;
      const int body = occ::addRectangle(0, 0, 0, W, W);
      const int block = occ::addRectangle(0, -W, 0, W, W);
      gmsh::vectorpair out;
      std::vector<gmsh::vectorpair> map;
      occ::fragment({{2, body}}, {{2, block}}, out, map);
      occ::synchronize();
      set_graded_size_field(point_at_origin(W), grading);
      return grading.contact_size_m;
    });
  });
  const double tol = 1e-9 * W;
  SceneParts parts;
  parts.symmetry_x = [=](double x, double, double) { return std::abs(x) < tol; };
  parts.top = [=](double, double y, double) { return std::abs(std::abs(y) - W) < tol; };
  parts.curved = [](double, double, double) { return false; };
  parts.in_plane = [](double, double, double) { return true; };
  tag_parts(scene, parts);
  upper_interface_facets(scene, [=](double, double y, double) { return std::abs(y) < tol; }, 1);
  scene.symmetry_multiplicity = 2;
  scene.wall_s = seconds_since(start);
  return scene;
}
} // namespace rollcheck::fem
