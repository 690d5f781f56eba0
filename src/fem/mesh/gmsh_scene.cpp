// gmsh run on a scene's geometry (fem/mesh/gmsh_scene.h).
#include "fem/mesh/gmsh_scene.h"
#include "core/error.h"
#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <gmsh.h>

namespace rollcheck::fem::scene_build
{
namespace
{
/// gmsh compares lengths with its geometric tolerance, 1e-8 of the model's
/// size (Geometry.Tolerance); an element size near it makes the 2D mesher
/// throw from inside an OpenMP region, which aborts the process. Measured on
/// the plane-strain Hertz scene: h_c = 1.35e-8 of the model (1e-5 N) meshes
/// and solves (b within 0.05 % of Hertz), 1.35e-9 (1e-7 N) aborts. Sizes below
/// 1e-8 of the model are refused before meshing, as bad input.
void require_meshable(double smallest_size_m)
{
  constexpr double smallest_relative_size = 1e-8;
  double x0, y0, z0, x1, y1, z1;
  gmsh::model::getBoundingBox(-1, -1, x0, y0, z0, x1, y1, z1);
  const double model_size = std::max({x1 - x0, y1 - y0, z1 - z0});
  if (!(smallest_size_m >= smallest_relative_size * model_size))
    throw InputError(fmt::format(
        "the contact element size {:.3g} is {:.3g} of the modelled body ({:.3g}), below the {:g} gmsh can mesh "
        "reliably: the load is too small (or the body too large) for the contact to be resolved; the smallest "
        "representable load gives a contact about {:g} times larger",
        smallest_size_m, smallest_size_m / model_size, model_size, smallest_relative_size,
        smallest_relative_size * model_size / smallest_size_m));
}

/// Meshes the current model's volumes one at a time, on one surface mesh
/// (conforming wherever volumes share a face). gmsh's Delaunay
/// tetrahedralises volumes that share a face together, and the surface
/// meshes of both must then stay apart by more than its tolerances: the rim
/// end's fillet on the steel block, lifting off tangentially from the
/// block's free top (d^2 / (2 r_e) above it at d beyond the fillet's start),
/// failed below edge elements of about 2 um ("Invalid boundary mesh
/// (overlapping facets)"). Each volume alone, the others hidden
/// (Mesh.MeshOnlyVisible), never sees the other's faces.
void generate_volume_by_volume()
{
  gmsh::vectorpair volumes;
  gmsh::model::getEntities(volumes, 3);
  gmsh::model::mesh::generate(2);
  gmsh::option::setNumber("Mesh.MeshOnlyVisible", 1);
  for (const auto& volume : volumes)
  {
    gmsh::model::setVisibility(volumes, 0);
    gmsh::model::setVisibility({volume}, 1);
    gmsh::model::mesh::generate(3);
  }
  gmsh::model::setVisibility(volumes, 1);
}
} // namespace

int point_at_origin(double size)
{
  gmsh::vectorpair points;
  gmsh::model::getEntities(points, 0);
  for (const auto& [dim, tag] : points)
  {
    double x0, y0, z0, x1, y1, z1;
    gmsh::model::getBoundingBox(dim, tag, x0, y0, z0, x1, y1, z1);
    if (std::max({std::abs(x0), std::abs(y0), std::abs(z0), std::abs(x1), std::abs(y1), std::abs(z1)})
        < 1e-9 * size)
      return tag;
  }
  throw ComputationError("scene mesh: the geometry has no vertex at the point of contact");
}

int add_quarter_disc(double R)
{
  namespace occ = gmsh::model::occ;
  const int pole = occ::addPoint(0, 0, 0);
  const int centre = occ::addPoint(0, R, 0);
  const int rim = occ::addPoint(R, R, 0);
  const int arc = occ::addCircleArc(pole, centre, rim);
  const int top = occ::addLine(rim, centre);
  const int axis = occ::addLine(centre, pole);
  occ::addPlaneSurface({occ::addCurveLoop({arc, top, axis})});
  occ::synchronize();
  return pole;
}

void set_graded_size_field(int pole, const MeshGrading& g)
{
  namespace field = gmsh::model::mesh::field;
  const int distance = field::add("Distance");
  field::setNumbers(distance, "PointsList", {static_cast<double>(pole)});
  field::setAsBackgroundMesh(
      add_threshold_field(distance, g.contact_size_m, g.far_size_m, g.fine_radius_m, g.growth));
  sizes_from_fields_alone();
}

RawMesh mesh_with_gmsh(int dim, const std::function<double()>& add_geometry_and_sizes, VolumeMesher mesher)
{
  return run_gmsh_session("scene", "scene", [&] {
    gmsh::option::setNumber("Mesh.Algorithm", 6); // Frontal-Delaunay: near-equilateral triangles
    gmsh::option::setNumber("Mesh.Algorithm3D", mesher == VolumeMesher::hxt ? 10 : 1); // HXT or Delaunay
    gmsh::option::setNumber("Mesh.Optimize", 1);
    require_meshable(add_geometry_and_sizes());
    gmsh::vectorpair volumes;
    gmsh::model::getEntities(volumes, 3);
    if (dim == 3 && volumes.size() > 1)
      generate_volume_by_volume();
    else
      gmsh::model::mesh::generate(dim);
    return read_gmsh_mesh(dim);
  });
}

RawMesh mesh_with_gmsh(int dim, const std::function<int()>& add_geometry, const MeshGrading& grading)
{
  return mesh_with_gmsh(dim, [&] {
    set_graded_size_field(add_geometry(), grading);
    return grading.contact_size_m;
  });
}
} // namespace rollcheck::fem::scene_build
