#include "geometry/tetrahedralize.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "geometry/mass_properties.h"
#include "geometry/write_mesh.h"
#include <cmath>
#include <fmt/format.h>
#include <gmsh.h>
#include <numbers>
#include <numeric>

namespace rollcheck::geometry
{
VolumeMeshInfo write_tetrahedral_mesh(const SurfaceMesh& surface, double mesh_size_m,
                                      const std::filesystem::path& path)
{
  if (!std::isfinite(mesh_size_m) || mesh_size_m <= 0)
    throw InputError(fmt::format("volume mesh: element size must be positive and finite, got {} m", mesh_size_m));
  // gmsh 4.8 cannot tell whether it is initialised; this function owns one
  // gmsh session from start to end.
  gmsh::initialize();
  gmsh::option::setNumber("General.Terminal", 0);
  gmsh::model::add("body");
  VolumeMeshInfo info{};
  try
  {
    const int s = gmsh::model::addDiscreteEntity(2);
    std::vector<std::size_t> node_tags(static_cast<std::size_t>(surface.vertices.rows()));
    std::iota(node_tags.begin(), node_tags.end(), 1);
    std::vector<double> coords(surface.vertices.data(), surface.vertices.data() + surface.vertices.size());
    gmsh::model::mesh::addNodes(2, s, node_tags, coords);
    std::vector<std::size_t> tri_nodes;
    for (Eigen::Index f = 0; f < surface.faces.rows(); ++f)
      for (int j = 0; j < 3; ++j)
        tri_nodes.push_back(static_cast<std::size_t>(surface.faces(f, j)) + 1);
    gmsh::model::mesh::addElementsByType(s, 2, {}, tri_nodes);
    const int loop = gmsh::model::geo::addSurfaceLoop({s});
    gmsh::model::geo::addVolume({loop});
    gmsh::model::geo::synchronize();
    gmsh::option::setNumber("Mesh.MeshSizeMax", mesh_size_m);
    // Sizes inside come from mesh_size_m alone, not from the surface's spacing
    // (else every size coarser than that spacing gives the same mesh).
    gmsh::option::setNumber("Mesh.MeshSizeExtendFromBoundary", 0);
    gmsh::model::mesh::generate(3);
    std::vector<std::size_t> tags;
    std::vector<double> xyz, param;
    gmsh::model::mesh::getNodes(tags, xyz, param);
    info.nodes = tags.size();
    std::vector<std::size_t> tets, tet_nodes;
    gmsh::model::mesh::getElementsByType(4, tets, tet_nodes);
    info.tetrahedra = tets.size();
    if (info.tetrahedra == 0)
      throw ComputationError("gmsh produced no tetrahedra");
    // gmsh refines inside only where the surface's triangles allow it: a body
    // of long thin triangles (an oloid's rulings) gets none at any size. A
    // size that asks for several times the tetrahedra made is then refused,
    // not written as if honoured (a regular tetrahedron of edge h: h^3 / (6 sqrt 2)).
    const double asked = mass_properties(surface).volume_m3 * 6 * std::numbers::sqrt2 / std::pow(mesh_size_m, 3);
    if (info.nodes == static_cast<std::size_t>(surface.vertices.rows()) && asked > 2.0 * info.tetrahedra)
      throw InputError(fmt::format("volume mesh: size {:g} m asks for about {:.3g} tetrahedra, but gmsh inserted no "
                                   "node inside this surface ({} tetrahedra): refine the surface (--points) or give "
                                   "a larger size",
                                   mesh_size_m, asked, info.tetrahedra));
    write_atomically(path, [&](const std::filesystem::path& tmp) {
      gmsh::write(tmp.string());
      check_gmsh_file_complete(tmp, path);
    });
  }
  catch (const std::exception&)
  {
    gmsh::finalize();
    throw;
  }
  catch (...)
  {
    // gmsh's API throws plain values on failure.
    gmsh::finalize();
    throw ComputationError("gmsh failed to mesh the volume of the body");
  }
  gmsh::finalize();
  return info;
}
} // namespace rollcheck::geometry
