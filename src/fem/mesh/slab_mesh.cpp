// The slab's mesh (fem/mesh/slab_mesh.h).
#include "fem/mesh/slab_mesh.h"
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
/// Quarter disc of radius 1 extruded along gmsh's z by `length` in the given
/// layers (structured, tetrahedra); returns the tag of the point of contact
/// on the section z = 0.
int add_extruded_quarter_disc(double length, const std::vector<double>& layer_fractions)
{
  const int pole = add_quarter_disc(1.0);
  gmsh::vectorpair out;
  gmsh::model::occ::extrude({{2, 1}}, 0, 0, length, out, std::vector<int>(layer_fractions.size(), 1),
                            layer_fractions, false);
  gmsh::model::occ::synchronize();
  return pole;
}
} // namespace

double slab_along(const SlabGeometry& slab, const double* x)
{
  // Inverse of x = a + z s(a), s(a) = -tan t_0 + (tan t_0 + tan t_L) a / L.
  const double t0 = std::tan(slab.end_overhang_rad[0]), tL = std::tan(slab.end_overhang_rad[1]);
  return (x[0] + x[2] * t0) / (1 + x[2] * (t0 + tL) / slab.length_m);
}

SceneMesh build_slab_mesh(MPI_Comm comm, const SlabGeometry& slab, const MeshGrading& section_grading)
{
  const auto start = std::chrono::steady_clock::now();
  const double L = slab.length_m;
  for (double overhang : slab.end_overhang_rad)
    if (!(std::abs(overhang) <= std::numbers::pi / 3))
      throw InputError(fmt::format("slab: end overhang must lie within +-60 deg, got {} rad", overhang));
  auto radius = [&](double a) { return slab.start_radius_m + (slab.end_radius_m - slab.start_radius_m) * a / L; };
  const double t0 = std::tan(slab.end_overhang_rad[0]), tL = std::tan(slab.end_overhang_rad[1]);
  SceneMesh scene = distribute(comm, 3, [&] {
    RawMesh raw = mesh_with_gmsh(
        3, [&] { return add_extruded_quarter_disc(L, slab.layer_fractions); }, section_grading);
    // gmsh (across, up, along) at unit radius -> (along, R across, R up),
    // then sheared along the ruling so that the end faces overhang.
    for (std::size_t i = 0; i < raw.x.size(); i += 3)
    {
      const double across = raw.x[i], up = raw.x[i + 1], along = raw.x[i + 2];
      const double z = radius(along) * up;
      raw.x[i] = along + z * (-t0 + (t0 + tL) * along / L);
      raw.x[i + 1] = radius(along) * across;
      raw.x[i + 2] = z;
    }
    return raw;
  });
  // Tolerances relative to the local radius: the section is the unit disc scaled.
  const double tol = 1e-9;
  auto along = [&](double x, double y, double z) {
    const double point[3] = {x, y, z};
    return slab_along(slab, point);
  };
  SceneParts parts;
  parts.symmetry_y = [&](double x, double y, double z) { return std::abs(y / radius(along(x, y, z))) < tol; };
  parts.top = [&](double x, double y, double z) { return std::abs(z / radius(along(x, y, z)) - 1) < tol; };
  parts.curved = [&](double x, double y, double z) {
    const double R = radius(along(x, y, z));
    return std::abs(std::hypot(y / R, z / R - 1) - 1) < 1e-7;
  };
  parts.in_plane = [&](double x, double y, double z) {
    const double a = along(x, y, z), R = radius(a);
    return std::abs(a) < tol * L || std::abs(a - L) < tol * L || std::abs(y / R) < tol || std::abs(z / R - 1) < tol;
  };
  tag_parts(scene, parts);
  scene.symmetry_multiplicity = 2;
  scene.wall_s = seconds_since(start);
  return scene;
}
} // namespace rollcheck::fem
