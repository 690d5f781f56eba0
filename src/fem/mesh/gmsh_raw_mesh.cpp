// The mesh gmsh holds as DOLFINx input (fem/mesh/gmsh_raw_mesh.h).
#include "fem/mesh/gmsh_raw_mesh.h"
#include "core/error.h"
#include <algorithm>
#include <dolfinx/fem/CoordinateElement.h>
#include <dolfinx/graph/AdjacencyList.h>
#include <dolfinx/io/cells.h>
#include <dolfinx/mesh/cell_types.h>
#include <dolfinx/mesh/utils.h>
#include <fmt/format.h>
#include <gmsh.h>
#include <unordered_map>
#include <utility>

namespace rollcheck::fem
{
RawMesh read_gmsh_mesh(int dim)
{
  RawMesh raw;
  std::vector<std::size_t> node_tags;
  std::vector<double> coords, parametric;
  gmsh::model::mesh::getNodes(node_tags, coords, parametric, -1, -1, false, false);
  std::unordered_map<std::size_t, std::int64_t> index;
  index.reserve(node_tags.size());
  for (std::size_t i = 0; i < node_tags.size(); ++i)
    index[node_tags[i]] = static_cast<std::int64_t>(i);
  raw.x.reserve(node_tags.size() * dim);
  for (std::size_t i = 0; i < node_tags.size(); ++i)
    for (int j = 0; j < dim; ++j)
      raw.x.push_back(coords[3 * i + j]);

  const int gmsh_type = dim == 3 ? 4 : 2; // 4-node tetrahedron, 3-node triangle
  std::vector<int> types;
  gmsh::model::mesh::getElementTypes(types, dim);
  for (const int type : types)
    if (type != gmsh_type)
      throw ComputationError(fmt::format("gmsh made elements of type {} in dimension {}, not simplices", type, dim));
  gmsh::vectorpair volumes;
  gmsh::model::getEntities(volumes, dim);
  std::vector<std::pair<double, int>> by_height;
  for (const auto& [d, tag] : volumes)
  {
    double x0, y0, z0, x1, y1, z1;
    gmsh::model::getBoundingBox(d, tag, x0, y0, z0, x1, y1, z1);
    by_height.push_back({-(dim == 3 ? z1 : y1), tag});
  }
  std::sort(by_height.begin(), by_height.end());
  std::unordered_map<std::size_t, int> owner; // node tag -> the volume that met it first
  for (const auto& [height, volume] : by_height)
  {
    std::vector<std::size_t> element_tags, element_nodes;
    gmsh::model::mesh::getElementsByType(gmsh_type, element_tags, element_nodes, volume);
    std::unordered_map<std::size_t, std::int64_t> twin;
    for (std::size_t tag : element_nodes)
    {
      const int first = owner.emplace(tag, volume).first->second;
      if (first == volume)
      {
        raw.cells.push_back(index.at(tag));
        continue;
      }
      auto [entry, inserted] = twin.emplace(tag, static_cast<std::int64_t>(raw.x.size() / dim));
      if (inserted)
      {
        const std::int64_t original = index.at(tag);
        for (int j = 0; j < dim; ++j)
        {
          const double coordinate = raw.x[original * dim + j]; // push_back may move raw.x
          raw.x.push_back(coordinate);
        }
      }
      raw.cells.push_back(entry->second);
    }
  }
  return raw;
}

int add_threshold_field(int distance_field, double size_min, double size_max, double dist_min, double growth)
{
  namespace field = gmsh::model::mesh::field;
  const int threshold = field::add("Threshold");
  field::setNumber(threshold, "InField", distance_field);
  field::setNumber(threshold, "SizeMin", size_min);
  field::setNumber(threshold, "SizeMax", size_max);
  field::setNumber(threshold, "DistMin", dist_min);
  field::setNumber(threshold, "DistMax", dist_min + (size_max - size_min) / growth);
  return threshold;
}

void sizes_from_fields_alone()
{
  gmsh::option::setNumber("Mesh.MeshSizeExtendFromBoundary", 0);
  gmsh::option::setNumber("Mesh.MeshSizeFromPoints", 0);
  gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", 0);
}

RawMesh run_gmsh_session(const std::string& model_name, const std::string& what, const std::function<RawMesh()>& make)
{
  gmsh::initialize();
  RawMesh raw;
  try
  {
    gmsh::option::setNumber("General.Terminal", 0);
    gmsh::option::setNumber("General.NumThreads", 1);
    gmsh::model::add(model_name);
    raw = make();
  }
  catch (const InputError&)
  {
    gmsh::finalize();
    throw;
  }
  catch (const std::exception& e)
  {
    gmsh::finalize();
    throw ComputationError("gmsh failed to mesh the " + what + ": " + e.what());
  }
  catch (...)
  {
    std::string last;
    gmsh::logger::getLastError(last);
    gmsh::finalize();
    throw ComputationError("gmsh failed to mesh the " + what + (last.empty() ? std::string() : ": " + last));
  }
  gmsh::finalize();
  return raw;
}

std::shared_ptr<dolfinx::mesh::Mesh> distribute_raw_mesh(MPI_Comm comm, int gdim, const RawMesh& raw)
{
  const auto cell_type = gdim == 3 ? dolfinx::mesh::CellType::tetrahedron : dolfinx::mesh::CellType::triangle;
  const int nodes_per_cell = gdim + 1;
  const std::size_t num_cells = raw.cells.size() / nodes_per_cell;
  const std::vector<std::uint8_t> perm = dolfinx::io::cells::perm_gmsh(cell_type, nodes_per_cell);
  std::vector<std::int64_t> cells
      = dolfinx::io::cells::apply_permutation(raw.cells, {num_cells, std::size_t(nodes_per_cell)}, perm);
  const dolfinx::fem::CoordinateElement cmap(cell_type, 1);
  auto mesh = std::make_shared<dolfinx::mesh::Mesh>(dolfinx::mesh::create_mesh(
      comm, dolfinx::graph::regular_adjacency_list(std::move(cells), nodes_per_cell), cmap, raw.x,
      {raw.x.size() / gdim, std::size_t(gdim)}, dolfinx::mesh::GhostMode::none));
  const int tdim = mesh->topology().dim();
  mesh->topology_mutable().create_entities(tdim - 1);
  mesh->topology_mutable().create_connectivity(tdim - 1, tdim);
  return mesh;
}
} // namespace rollcheck::fem
