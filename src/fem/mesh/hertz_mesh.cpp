// The Hertz scenes' mesh (fem/mesh/hertz_mesh.h).
#include "fem/mesh/hertz_mesh.h"
#include "fem/mesh/gmsh_scene.h"
#include "fem/mesh/scene_parts.h"
#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <gmsh.h>
#include <numbers>

namespace rollcheck::fem
{
using namespace scene_build;

namespace
{
/// Quarter hemisphere x, y >= 0, z <= R of the sphere about (0, 0, R). The cut
/// box overlaps the tangent plane z = 0 instead of touching it (an OCC cut
/// exactly at a tangent plane is fragile).
int add_quarter_hemisphere(double R)
{
  namespace occ = gmsh::model::occ;
  const int sphere = occ::addSphere(0, 0, R, R);
  // Parametric poles from (0, 0, 0) and (0, 0, 2R) to (0, -R, R) and (0, R, R).
  occ::rotate({{3, sphere}}, 0, 0, R, 1, 0, 0, std::numbers::pi / 2);
  const int box = occ::addBox(0, 0, -0.1 * R, 1.1 * R, 1.1 * R, 1.1 * R);
  gmsh::vectorpair out;
  std::vector<gmsh::vectorpair> map;
  occ::intersect({{3, sphere}}, {{3, box}}, out, map);
  occ::synchronize();
  return point_at_origin(R);
}

/// The grading's size field about the point `pole`, refined as `refinement`
/// says (hertz_mesh.h), as the background mesh.
void set_refined_size_field(int pole, double R, const MeshGrading& g, const ContactRefinement& refinement)
{
  namespace field = gmsh::model::mesh::field;
  const int from_pole = field::add("Distance");
  field::setNumbers(from_pole, "PointsList", {static_cast<double>(pole)});
  std::vector<double> sizes = {
      static_cast<double>(add_threshold_field(from_pole, g.contact_size_m, g.far_size_m, g.fine_radius_m, g.growth))};
  if (refinement.pole_size_m > 0)
    sizes.push_back(add_threshold_field(from_pole, refinement.pole_size_m, g.far_size_m, refinement.pole_radius_m,
                                        g.growth));
  if (refinement.edge_size_m > 0)
  {
    const double c = refinement.edge_radius_m;
    const int from_edge = field::add("MathEval");
    field::setString(from_edge, "F",
                     fmt::format("Sqrt((Sqrt(x * x + y * y) - {0:.17g})^2 + (z - {1:.17g})^2)", c,
                                 R - std::sqrt(R * R - c * c)));
    sizes.push_back(add_threshold_field(from_edge, refinement.edge_size_m, g.far_size_m,
                                        refinement.edge_half_width_m, g.growth));
  }
  const int smallest = field::add("Min");
  field::setNumbers(smallest, "FieldsList", sizes);
  field::setAsBackgroundMesh(smallest);
  sizes_from_fields_alone();
}
} // namespace

SceneMesh build_scene_mesh(MPI_Comm comm, Model model, double R, const MeshGrading& grading,
                           const ContactRefinement& refinement)
{
  const auto start = std::chrono::steady_clock::now();
  const bool solid = model == Model::solid;
  const int gdim = solid ? 3 : 2;
  SceneMesh scene = distribute(comm, gdim, [&] {
    if (!solid)
      return mesh_with_gmsh(gdim, [&] { return add_quarter_disc(R); }, grading);
    return mesh_with_gmsh(gdim, [&] {
      set_refined_size_field(add_quarter_hemisphere(R), R, grading, refinement);
      return std::min({grading.contact_size_m, refinement.pole_size_m > 0 ? refinement.pole_size_m : R,
                       refinement.edge_size_m > 0 ? refinement.edge_size_m : R});
    });
  });
  const double tol = 1e-9 * R;
  auto z_of = [solid](double y, double z) { return solid ? z : y; };
  SceneParts parts;
  parts.symmetry_x = [tol](double x, double, double) { return std::abs(x) < tol; };
  if (solid)
    parts.symmetry_y = [tol](double, double y, double) { return std::abs(y) < tol; };
  parts.top = [&](double, double y, double z) { return std::abs(z_of(y, z) - R) < tol; };
  parts.curved = [&](double x, double y, double z) {
    const double h = z_of(y, z) - R;
    const double r2 = solid ? x * x + y * y : x * x;
    return std::abs(std::sqrt(r2 + h * h) - R) < 1e-7 * R;
  };
  parts.in_plane = [&](double x, double y, double z) {
    return std::abs(x) < tol || (solid && std::abs(y) < tol) || std::abs(z_of(y, z) - R) < tol;
  };
  tag_parts(scene, parts);
  scene.symmetry_multiplicity = model == Model::axisymmetric ? 1 : model == Model::plane_strain ? 2 : 4;
  scene.wall_s = seconds_since(start);
  return scene;
}
} // namespace rollcheck::fem
