#include "cli/scenes.h"
#include "core/error.h"
#include <fmt/format.h>
#include <map>

namespace rollcheck::cli
{
namespace
{
std::map<std::string, Scene>& registry()
{
  static std::map<std::string, Scene> scenes;
  return scenes;
}
} // namespace

void register_scene(const Scene& scene) { registry()[scene.schema->kind] = scene; }

const Scene& find_scene(const std::string& kind, const std::string& origin)
{
  if (auto it = registry().find(kind); it != registry().end())
    return it->second;
  throw InputError(fmt::format("{}: unknown scene kind '{}' (known: {})", origin, kind, fmt::join(scene_kinds(), ", ")));
}

std::vector<std::string> scene_kinds()
{
  std::vector<std::string> kinds;
  for (const auto& [kind, scene] : registry())
    kinds.push_back(kind);
  return kinds;
}

namespace
{
/// The body's parameters; a line-contact scene (`line_contact`) offers only
/// the hulls of two circles (oracle/rolling_study.h require_line_contact):
/// no spheres, no mesh file, no circle count.
void declare_body(io::BoundSchema<geometry::BodySpec>& s, bool line_contact)
{
  using geometry::BodySpec;
  s.text("body", "--body", &BodySpec::body,
         line_contact ? "Body, the hull of two circles: oloid (true oloid), paper-oloid (the preprint's (90,1,1) "
                        "roller, not an oloid), roller, cylinder"
                      : "Body: oloid (true oloid), paper-oloid (the preprint's (90,1,1) roller, not an oloid), roller, "
                        "cylinder, sphere (icosphere), uv-sphere, hemisphere",
         line_contact ? std::vector<std::string>{"oloid", "paper-oloid", "roller", "cylinder"}
                      : std::vector<std::string>{"oloid", "paper-oloid", "roller", "cylinder", "sphere", "uv-sphere",
                                                 "hemisphere"})
      .choice("family", "--family", &BodySpec::family,
              "Roller family: paper (C2's plane turned about z, the preprint's) or centre-line (turned about the "
              "line of centres; its (90,1,1) is the true oloid)",
              {{"paper", geometry::RollerFamily::paper}, {"centre-line", geometry::RollerFamily::centre_line}})
      .real("theta_deg", "--theta", [](BodySpec& b) -> double& { return b.genome.theta_deg; }, "deg",
            "Roller: angle between the circle planes", io::Bounds{0, 180, true, true})
      .real("offset", "--offset", [](BodySpec& b) -> double& { return b.genome.offset; }, "",
            "Roller: centre distance d in units of r1", io::non_negative)
      .real("ratio", "--ratio", [](BodySpec& b) -> double& { return b.genome.ratio; }, "",
            "Roller: radius ratio rho = r2 / r1", io::positive);
  if (!line_contact)
    s.integer("circles", "--circles", [](BodySpec& b) -> int& { return b.genome.n_circles; }, "",
              "Roller: number of generating circles (the reference's n >= 3 variant)", io::Bounds{2, 16});
  s.integer("points", "--points", &BodySpec::points, "",
            "Samples per generating circle (the reference: 400 for the oloid, 300 in its search)", body_points_range)
      .real("radius_m", "--radius", &BodySpec::radius_m, "m",
            line_contact ? "r1 of rollers, radius of the cylinder (the preprint: 1)"
                         : "r1 of rollers, radius of the other bodies (the preprint: 1)",
            io::positive)
      .real("height_m", "--height", &BodySpec::height_m, "m", "Cylinder height (the reference: 2)", io::positive)
      .integer("sections", "--sections", &BodySpec::sections, "",
               line_contact ? "Cylinder sides (the reference: 60)" : "Cylinder sides, UV-sphere sectors (the reference: 60)",
               io::body_sections);
  if (line_contact)
    return;
  s.integer("subdivisions", "--subdivisions", &BodySpec::subdivisions, "", "Icosphere subdivisions (the reference: 3)",
            io::Bounds{0, 8})
      .path("mesh_file", "--mesh", &BodySpec::mesh_file,
            "Read the body from a surface mesh file (OBJ/STL/PLY/OFF) instead");
}
} // namespace

const io::BoundSchema<geometry::BodySpec>& body_schema()
{
  return kept_schema<geometry::BodySpec>("body", [](auto& s) { declare_body(s, false); });
}

const io::BoundSchema<geometry::BodySpec>& line_contact_body_schema()
{
  return kept_schema<geometry::BodySpec>("body", [](auto& s) { declare_body(s, true); });
}

const io::BoundSchema<double>& penalty_schema()
{
  return kept_schema<double>("penalty", [](auto& s) {
    s.real("penalty_c", "--penalty-c", [](double& c) -> double& { return c; }, "",
           "Penalty kappa = c E / h_c (docs/results/hertz.md#penalty-study-error-against-c-at-fixed-mesh)", io::positive);
  });
}
} // namespace rollcheck::cli
