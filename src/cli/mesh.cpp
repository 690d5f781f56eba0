// `rollcheck mesh`: build or read a body, check it, report its mass
// properties, and write it as a surface mesh or a gmsh tetrahedral mesh.
#include "cli/body_from_parameters.h"
#include "cli/cli.h"
#include "cli/scenes.h"
#include "core/error.h"
#include "geometry/mass_properties.h"
#include "geometry/mesh_checks.h"
#include "geometry/tetrahedralize.h"
#include "geometry/write_mesh.h"
#include <spdlog/spdlog.h>

namespace rollcheck::cli
{
namespace
{
const io::Schema& mesh_schema()
{
  static const io::Schema schema = [] {
    io::Schema s{"mesh", body_parameters()};
    s.parameters.push_back({"out", "--out", std::string(), "",
                            "Write the mesh here: .obj/.stl/.ply/.off (surface) or .msh (gmsh tetrahedra)"});
    s.parameters.push_back({"volume_mesh_size_m", "--size", 0.1, "m", "Tetrahedron size of a .msh volume mesh"});
    return s;
  }();
  return schema;
}

nlohmann::json run_mesh(const io::Parameters& params)
{
  std::string label;
  const geometry::SurfaceMesh mesh = body_from_parameters(params, &label);
  const geometry::MeshChecks checks = geometry::check_mesh(mesh);
  const geometry::MassProperties mp = geometry::mass_properties(mesh);
  auto vec = [](const Eigen::Vector3d& v) { return nlohmann::json::array({v.x(), v.y(), v.z()}); };
  nlohmann::json inertia = nlohmann::json::array();
  for (int i = 0; i < 3; ++i)
    inertia.push_back(vec(mp.inertia.row(i).transpose()));
  nlohmann::json summary = {{"body", label},
                            {"n_vertices", mesh.vertices.rows()},
                            {"n_faces", mesh.faces.rows()},
                            {"area_m2", mp.area_m2},
                            {"volume_m3", mp.volume_m3},
                            {"centre_of_mass_m", vec(mp.centre_of_mass)},
                            {"surface_centroid_m", vec(mp.surface_centroid)},
                            {"inertia_density1_kg_m2", inertia},
                            {"watertight", checks.watertight},
                            {"outward", checks.outward},
                            {"convex", checks.convex}};
  if (const std::string& out = params.text("out"); !out.empty())
  {
    const std::filesystem::path path(out);
    if (path.extension() == ".msh")
    {
      const auto info = geometry::write_tetrahedral_mesh(mesh, params.real("volume_mesh_size_m"), path);
      summary["volume_mesh"] = {{"nodes", info.nodes}, {"tetrahedra", info.tetrahedra}};
    }
    else
      geometry::write_mesh(mesh, path);
    summary["out"] = out;
  }
  spdlog::info("{}: {} faces, area {:.9g} m^2, volume {:.9g} m^3, watertight {}, convex {}", label,
               mesh.faces.rows(), mp.area_m2, mp.volume_m3, checks.watertight, checks.convex);
  return summary;
}
} // namespace

void add_mesh_command(CLI::App& app)
{
  CLI::App* sub = app.add_subcommand("mesh", "Build or read a body, check it and write its mesh");
  static std::string json_path;
  add_json_option(sub, json_path);
  static io::SchemaOptions* options = new io::SchemaOptions(sub, mesh_schema());
  register_scene({&mesh_schema(), run_mesh});
  on_run(sub, [] {
    const nlohmann::json summary = run_mesh(options->apply());
    emit_json(json_path, summary);
    return 0;
  });
}
} // namespace rollcheck::cli
