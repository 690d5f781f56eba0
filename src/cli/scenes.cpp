#include "cli/scenes.h"
#include "geometry/error.h"
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

std::vector<io::Parameter> body_parameters()
{
  return {
      {"body", "--body", std::string("oloid"), "",
       "Body: oloid (true oloid), paper-oloid (the preprint's (90,1,1) roller, not an oloid), roller, cylinder, "
       "sphere (icosphere), uv-sphere, hemisphere",
       {"oloid", "paper-oloid", "roller", "cylinder", "sphere", "uv-sphere", "hemisphere"}},
      {"family", "--family", std::string("paper"), "",
       "Roller family: paper (C2's plane turned about z, the preprint's) or centre-line (turned about the line of "
       "centres; its (90,1,1) is the true oloid)",
       {"paper", "centre-line"}},
      {"theta_deg", "--theta", 90.0, "deg", "Roller: angle between the circle planes"},
      {"offset", "--offset", 1.0, "", "Roller: centre distance d in units of r1"},
      {"ratio", "--ratio", 1.0, "", "Roller: radius ratio rho = r2 / r1"},
      {"circles", "--circles", std::int64_t{2}, "", "Roller: number of generating circles (the reference's n >= 3 variant)"},
      {"points", "--points", std::int64_t{400}, "",
       "Samples per generating circle (the reference: 400 for the oloid, 300 in its search)"},
      {"radius_m", "--radius", 1.0, "m", "r1 of rollers, radius of the other bodies (the preprint: 1)"},
      {"height_m", "--height", 2.0, "m", "Cylinder height (the reference: 2)"},
      {"sections", "--sections", std::int64_t{60}, "", "Cylinder sides, UV-sphere sectors (the reference: 60)"},
      {"subdivisions", "--subdivisions", std::int64_t{3}, "", "Icosphere subdivisions (the reference: 3)"},
      {"mesh_file", "--mesh", std::string(), "", "Read the body from a surface mesh file (OBJ/STL/PLY/OFF) instead"},
  };
}
} // namespace rollcheck::cli
