#include "geometry/body.h"
#include "core/error.h"
#include "geometry/mesh_checks.h"
#include "geometry/primitives.h"
#include "geometry/read_mesh.h"
#include <fmt/format.h>

namespace rollcheck::geometry
{
SurfaceMesh make_body(const BodySpec& spec)
{
  const RollerGenome oloid{90.0, 1.0, 1.0, 2};
  SurfaceMesh mesh;
  if (!spec.mesh_file.empty())
  {
    mesh = read_mesh(spec.mesh_file);
    require_closed_convex(mesh, fmt::format("mesh file '{}'", spec.mesh_file));
    return mesh;
  }
  if (spec.body == "oloid")
    mesh = two_circle_roller(oloid, RollerFamily::centre_line, spec.radius_m, spec.points);
  else if (spec.body == "paper-oloid")
    mesh = two_circle_roller(oloid, RollerFamily::paper, spec.radius_m, spec.points);
  else if (spec.body == "roller")
    mesh = two_circle_roller(spec.genome, spec.family, spec.radius_m, spec.points);
  else if (spec.body == "cylinder")
    mesh = cylinder(spec.radius_m, spec.height_m, spec.sections);
  else if (spec.body == "sphere")
    mesh = icosphere(spec.radius_m, spec.subdivisions);
  else if (spec.body == "uv-sphere")
    mesh = uv_sphere(spec.radius_m, spec.sections / 2, spec.sections);
  else if (spec.body == "hemisphere")
    mesh = hemisphere(spec.radius_m, spec.sections / 4, spec.sections);
  else
    throw InputError(fmt::format("body '{}' is unknown (oloid, paper-oloid, roller, cylinder, sphere, uv-sphere, "
                                 "hemisphere)",
                                 spec.body));
  require_closed_convex(mesh, spec.body);
  return mesh;
}

std::string body_label(const BodySpec& spec)
{
  if (!spec.mesh_file.empty())
    return spec.mesh_file;
  if (spec.body == "roller")
    return fmt::format("roller({}, {}, {}, {}, {})", spec.family == RollerFamily::paper ? "paper" : "centre-line",
                       spec.genome.theta_deg, spec.genome.offset, spec.genome.ratio, spec.genome.n_circles);
  return spec.body;
}
} // namespace rollcheck::geometry
