// `rollcheck mesh`: build or read a body, check it, report its mass
// properties, and write it as a surface mesh or a gmsh tetrahedral mesh.
// Also the scene "mesh" of case files.
#include "cli/cli.h"
#include "cli/scenes.h"
#include "core/error.h"
#include "geometry/body.h"
#include "geometry/mass_properties.h"
#include "geometry/mesh_checks.h"
#include "geometry/write_mesh.h"
#include <cmath>
#include <fmt/format.h>
#include <numbers>
#include <spdlog/spdlog.h>

namespace rollcheck::cli
{
namespace
{
struct MeshScene
{
  geometry::BodySpec body;
  std::string out;                  ///< "" writes nothing
  double volume_mesh_size_m = 0.1;  ///< tetrahedron size of a .msh volume mesh
};

const SceneSchema<MeshScene>& mesh_schema()
{
  return kept_schema<MeshScene>("mesh",
                                "Build or read a body, check it and write its mesh",
                                [](auto& s) {
    s.include(body_schema(), &MeshScene::body)
        .text("out", "--out", &MeshScene::out,
              "Write the mesh here: .obj/.stl/.ply/.off (surface) or .msh (gmsh tetrahedra)")
        .real("volume_mesh_size_m", "--size", &MeshScene::volume_mesh_size_m, "m",
              "Tetrahedron size of a .msh volume mesh", io::positive);
  });
}

/// Tetrahedra a volume mesh may have: gmsh takes about 1 kB per tetrahedron
/// while meshing, so a million stays well inside the 2 GB work budget.
constexpr double max_tetrahedra = 1e6;

/// The tetrahedron size S is honoured between the body's size (above it every
/// S gives the same mesh, the surface's alone) and the size at which the volume
/// would need more than max_tetrahedra (a regular tetrahedron of edge S has
/// volume S^3 / (6 sqrt 2)); InputError naming --size outside.
void check_volume_mesh_size(const geometry::SurfaceMesh& mesh, double volume_m3, double size_m)
{
  const double diameter_m = (mesh.vertices.colwise().maxCoeff() - mesh.vertices.colwise().minCoeff()).norm();
  const double tetrahedra = volume_m3 / (std::pow(size_m, 3) / (6 * std::numbers::sqrt2));
  if (size_m > diameter_m)
    throw InputError(fmt::format("option --size (size_m): {:g} m is larger than the body ({:g} m across), "
                                 "where every size gives the same mesh",
                                 size_m, diameter_m));
  if (tetrahedra > max_tetrahedra)
    throw InputError(fmt::format("option --size (size_m): {:g} m asks for about {:.3g} tetrahedra, more "
                                 "than the {:g} of the work budget",
                                 size_m, tetrahedra, max_tetrahedra));
}

nlohmann::json run_mesh(const io::Parameters& params)
{
  const MeshScene scene = mesh_schema().bind(params);
  const std::string label = geometry::body_label(scene.body);
  const geometry::SurfaceMesh mesh = geometry::make_body(scene.body);
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
  if (!scene.out.empty())
  {
    const std::filesystem::path path(scene.out);
    if (path.extension() == ".msh")
    {
      check_volume_mesh_size(mesh, mp.volume_m3, scene.volume_mesh_size_m);
      summary["volume_mesh"] = write_volume_mesh(mesh, scene.volume_mesh_size_m, path);
    }
    else
      geometry::write_mesh(mesh, path);
    summary["out"] = scene.out;
  }
  print_summary(fmt::format("| {} | faces | area [m^2] | volume [m^3] | watertight | convex |\n|---|---|---|---|---|---|\n"
                            "| | {} | {:.9g} | {:.9g} | {} | {} |\n",
                            label, mesh.faces.rows(), mp.area_m2, mp.volume_m3, checks.watertight, checks.convex));
  return summary;
}
} // namespace

void add_mesh_command(CLI::App& app)
{
  add_scene_command(app, mesh_schema(), run_mesh);
  declare_outputs(mesh_schema().schema(), {{"out", OutputKind::file}});
}
} // namespace rollcheck::cli
