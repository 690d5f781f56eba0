#include "cli/body_from_parameters.h"
#include "geometry/body.h"
#include "geometry/mesh_checks.h"
#include "geometry/read_mesh.h"
#include <fmt/format.h>

namespace rollcheck::cli
{
geometry::BodySpec body_spec_from_parameters(const io::Parameters& params)
{
  geometry::BodySpec spec;
  spec.body = params.text("body");
  spec.family = params.text("family") == "paper" ? geometry::RollerFamily::paper
                                                  : geometry::RollerFamily::centre_line;
  spec.genome = {params.real("theta_deg"), params.real("offset"), params.real("ratio"),
                 static_cast<int>(params.integer("circles"))};
  spec.radius_m = params.real("radius_m");
  spec.points = static_cast<int>(params.integer("points"));
  spec.height_m = params.real("height_m");
  spec.sections = static_cast<int>(params.integer("sections"));
  spec.subdivisions = static_cast<int>(params.integer("subdivisions"));
  return spec;
}

geometry::SurfaceMesh body_from_parameters(const io::Parameters& params, std::string* label)
{
  if (const std::string& file = params.text("mesh_file"); !file.empty())
  {
    geometry::SurfaceMesh mesh = geometry::read_mesh(file);
    geometry::require_closed_convex(mesh, fmt::format("mesh file '{}'", file));
    if (label)
      *label = file;
    return mesh;
  }
  const geometry::BodySpec spec = body_spec_from_parameters(params);
  if (label)
    *label = spec.body == "roller" ? fmt::format("roller({}, {}, {}, {}, {})", params.text("family"), spec.genome.theta_deg,
                                                 spec.genome.offset, spec.genome.ratio, spec.genome.n_circles)
                                   : spec.body;
  return geometry::make_body(spec);
}
} // namespace rollcheck::cli
