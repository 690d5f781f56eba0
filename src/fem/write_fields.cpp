#include "fem/write_fields.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include <dolfinx/fem/FunctionSpace.h>
#include <dolfinx/mesh/Mesh.h>
#include <fmt/format.h>
#include <fstream>
#include <numeric>
#include <span>

namespace rollcheck::fem
{
namespace
{
struct Field
{
  std::string name;
  std::string attribute_type; ///< XDMF: Scalar, Vector, Tensor
  int width;                  ///< values written per node (vectors padded to 3)
  const dolfinx::fem::Function<double>* function;
};

/// Per owned geometry node: global index, x, y, z, then each field's values;
/// per owned cell: its nodes' global indices. A P1 field's dof k of a cell
/// sits on the cell's geometry node k (both follow the reference vertices).
std::pair<std::vector<double>, std::vector<double>> local_rows(const dolfinx::mesh::Mesh& mesh,
                                                               const std::vector<Field>& fields, int row_width)
{
  const auto& geometry = mesh.geometry();
  const auto& x_dofmap = geometry.dofmap();
  const std::int32_t owned_nodes = geometry.index_map()->size_local();
  const std::int32_t all_nodes = static_cast<std::int32_t>(geometry.x().size() / 3);
  std::vector<double> values(static_cast<std::size_t>(all_nodes) * row_width, 0.0);
  const int tdim = mesh.topology().dim();
  const std::int32_t owned_cells = mesh.topology().index_map(tdim)->size_local();
  const std::int32_t all_cells = owned_cells + mesh.topology().index_map(tdim)->num_ghosts();
  for (std::int32_t c = 0; c < all_cells; ++c)
  {
    const auto nodes = x_dofmap.links(c);
    int column = 4;
    for (const Field& f : fields)
    {
      const auto dofs = f.function->function_space()->dofmap()->cell_dofs(c);
      const int bs = f.function->function_space()->dofmap()->bs();
      const auto& u = f.function->x()->array();
      for (std::size_t k = 0; k < nodes.size(); ++k)
        for (int j = 0; j < bs; ++j)
          values[nodes[k] * row_width + column + j] = u[dofs[k] * bs + j];
      column += f.width;
    }
  }
  std::vector<std::int32_t> locals(all_nodes);
  std::iota(locals.begin(), locals.end(), 0);
  std::vector<std::int64_t> globals(all_nodes);
  geometry.index_map()->local_to_global(locals, globals);
  std::vector<double> node_rows(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(owned_nodes) * row_width);
  for (std::int32_t i = 0; i < owned_nodes; ++i)
  {
    node_rows[i * row_width] = static_cast<double>(globals[i]);
    for (int d = 0; d < 3; ++d)
      node_rows[i * row_width + 1 + d] = geometry.x()[3 * i + d];
  }
  std::vector<double> cell_rows;
  for (std::int32_t c = 0; c < owned_cells; ++c)
    for (std::int32_t node : x_dofmap.links(c))
      cell_rows.push_back(static_cast<double>(globals[node]));
  return {node_rows, cell_rows};
}

std::vector<double> gather_to_root(MPI_Comm comm, const std::vector<double>& local)
{
  int size = 1, rank = 0;
  MPI_Comm_size(comm, &size);
  MPI_Comm_rank(comm, &rank);
  int n = static_cast<int>(local.size());
  std::vector<int> counts(size), offsets(size + 1, 0);
  MPI_Gather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, comm);
  for (int r = 0; r < size; ++r)
    offsets[r + 1] = offsets[r] + counts[r];
  std::vector<double> all(rank == 0 ? offsets[size] : 0);
  MPI_Gatherv(local.data(), n, MPI_DOUBLE, all.data(), counts.data(), offsets.data(), MPI_DOUBLE, 0, comm);
  return all;
}

void write_data_item(std::ostream& out, std::span<const double> rows, int row_width, int first, int width,
                     std::size_t count, const char* number_type)
{
  out << fmt::format("<DataItem Dimensions=\"{} {}\" NumberType=\"{}\" Precision=\"8\" Format=\"XML\">\n", count,
                     width, number_type);
  for (std::size_t i = 0; i < count; ++i)
  {
    for (int j = 0; j < width; ++j)
    {
      const double v = rows[i * row_width + first + j];
      out << (number_type[0] == 'I' ? fmt::format("{:.0f}", v) : fmt::format("{:.17g}", v))
          << (j + 1 < width ? ' ' : '\n');
    }
  }
  out << "</DataItem>\n";
}
} // namespace

void write_fields(const std::filesystem::path& xdmf_path, const NodalFields& fields)
{
  const auto mesh = fields.pressure->function_space()->mesh();
  MPI_Comm comm = mesh->comm();
  int rank = 0;
  MPI_Comm_rank(comm, &rank);

  const std::vector<Field> list = {{"displacement", "Vector", 3, fields.displacement.get()},
                                   {"stress", "Tensor", 9, fields.stress.get()},
                                   {"von_mises", "Scalar", 1, fields.von_mises.get()},
                                   {"max_shear", "Scalar", 1, fields.max_shear.get()},
                                   {"contact_pressure", "Scalar", 1, fields.pressure.get()}};
  int row_width = 4;
  for (const Field& f : list)
    row_width += f.width;
  const auto [local_nodes, local_cells] = local_rows(*mesh, list, row_width);
  const std::vector<double> node_rows = gather_to_root(comm, local_nodes);
  const std::vector<double> cell_rows = gather_to_root(comm, local_cells);

  int failed = 0;
  std::string message;
  if (rank == 0)
  {
    // Rows in global node order, so the cells' global indices address them.
    const std::size_t n_nodes = node_rows.size() / row_width;
    std::vector<double> ordered(node_rows.size());
    for (std::size_t i = 0; i < n_nodes; ++i)
    {
      const auto g = static_cast<std::size_t>(node_rows[i * row_width]);
      std::copy_n(node_rows.begin() + i * row_width, row_width, ordered.begin() + g * row_width);
    }
    const bool tets = mesh->topology().cell_type() == dolfinx::mesh::CellType::tetrahedron;
    const int per_cell = tets ? 4 : 3;
    const std::size_t n_cells = cell_rows.size() / per_cell;
    try
    {
      write_atomically(xdmf_path, [&](const std::filesystem::path& tmp) {
        std::ofstream out(tmp);
        out << "<?xml version=\"1.0\"?>\n<Xdmf Version=\"3.0\">\n<Domain>\n<Grid Name=\"fields\" GridType=\"Uniform\">\n";
        out << fmt::format("<Topology TopologyType=\"{}\" NumberOfElements=\"{}\">\n", tets ? "Tetrahedron" : "Triangle",
                           n_cells);
        write_data_item(out, cell_rows, per_cell, 0, per_cell, n_cells, "Int");
        out << "</Topology>\n<Geometry GeometryType=\"XYZ\">\n";
        write_data_item(out, ordered, row_width, 1, 3, n_nodes, "Float");
        out << "</Geometry>\n";
        int column = 4;
        for (const Field& f : list)
        {
          out << fmt::format("<Attribute Name=\"{}\" AttributeType=\"{}\" Center=\"Node\">\n", f.name,
                             f.attribute_type);
          write_data_item(out, ordered, row_width, column, f.width, n_nodes, "Float");
          out << "</Attribute>\n";
          column += f.width;
        }
        out << "</Grid>\n</Domain>\n</Xdmf>\n";
        if (!out)
          throw InputError(fmt::format("option --xdmf: cannot write '{}'", xdmf_path.string()));
      });
    }
    catch (const std::exception& e)
    {
      failed = 1;
      message = e.what();
    }
  }
  // Every rank learns of a failure, so none waits for the others.
  MPI_Bcast(&failed, 1, MPI_INT, 0, comm);
  if (failed)
    throw ComputationError(fmt::format("writing fields to '{}' failed: {}", xdmf_path.string(),
                                       rank == 0 ? message : "see rank 0"));
}
} // namespace rollcheck::fem
