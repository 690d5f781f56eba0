// The crease scene's mesh (fem/mesh/crease_mesh.h).
#include "fem/mesh/crease_mesh.h"
#include "core/error.h"
#include "fem/mesh/gmsh_scene.h"
#include "fem/mesh/scene_parts.h"
#include <cmath>
#include <fmt/format.h>
#include <gmsh.h>
#include <numbers>

namespace rollcheck::fem
{
using namespace scene_build;

namespace
{
/// The crease scene's polygon in the xy-plane of gmsh (y is the model's z);
/// returns the tag of the apex.
int add_half_crease(const CreaseGeometry& k)
{
  namespace occ = gmsh::model::occ;
  const double W = k.width_m, H = k.height_m;
  const int apex = occ::addPoint(0, 0, 0);
  const int face_end = occ::addPoint(W, W * std::tan(k.face_angle_rad), 0);
  const int top_right = occ::addPoint(W, H, 0);
  const int top_left = occ::addPoint(0, H, 0);
  const std::vector<int> lines = {occ::addLine(apex, face_end), occ::addLine(face_end, top_right),
                                  occ::addLine(top_right, top_left), occ::addLine(top_left, apex)};
  occ::addPlaneSurface({occ::addCurveLoop(lines)});
  occ::synchronize();
  return apex;
}
} // namespace

SceneMesh build_crease_mesh(MPI_Comm comm, const CreaseGeometry& crease, const MeshGrading& grading)
{
  const auto start = std::chrono::steady_clock::now();
  const double W = crease.width_m, H = crease.height_m, slope = std::tan(crease.face_angle_rad);
  if (!(W > 0 && H > 2 * W * slope && crease.face_angle_rad > 0 && crease.face_angle_rad <= std::numbers::pi / 4))
    throw InputError(fmt::format("crease scene: need W > 0, 0 < beta <= 45 deg and H above the face's end "
                                 "(W = {} m, H = {} m, beta = {} rad)",
                                 W, H, crease.face_angle_rad));
  SceneMesh scene = distribute(comm, 2, [&] { return mesh_with_gmsh(2, [&] { return add_half_crease(crease); }, grading); });
  const double tol = 1e-9 * W;
  SceneParts parts;
  parts.symmetry_x = [tol](double x, double, double) { return std::abs(x) < tol; };
  parts.top = [H, tol](double, double y, double) { return std::abs(y - H) < tol; };
  parts.curved = [slope, tol](double x, double y, double) { return std::abs(y - x * slope) < tol; };
  parts.in_plane = [W, tol](double x, double, double) { return std::abs(x) < tol || std::abs(x - W) < tol; };
  tag_parts(scene, parts);
  scene.symmetry_multiplicity = 2;
  scene.wall_s = seconds_since(start);
  return scene;
}
} // namespace rollcheck::fem
