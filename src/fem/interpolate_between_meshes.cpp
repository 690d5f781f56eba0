#include "fem/interpolate_between_meshes.h"
#include "core/error.h"
#include "fem/all_gather.h"
#include <fmt/format.h>
#include <Eigen/Dense>
#include <dolfinx/geometry/BoundingBoxTree.h>
#include <dolfinx/geometry/utils.h>
#include <dolfinx/mesh/Mesh.h>
#include <algorithm>
#include <array>
#include <limits>
#include <map>
#include <mpi.h>

namespace rollcheck::fem
{
namespace
{
/// The part of every cell (local and ghost) of `mesh`, from its midpoint.
std::vector<int> cell_parts(const dolfinx::mesh::Mesh& mesh, const std::function<int(const double*)>& part)
{
  const int tdim = mesh.topology().dim();
  const auto cells = mesh.topology().index_map(tdim);
  const std::int32_t num_cells = cells->size_local() + cells->num_ghosts();
  std::vector<int> parts(num_cells, 0);
  if (!part)
    return parts;
  const auto& x_dofmap = mesh.geometry().dofmap();
  std::span<const double> x = mesh.geometry().x();
  for (std::int32_t c = 0; c < num_cells; ++c)
  {
    std::array<double, 3> midpoint{0, 0, 0};
    const auto nodes = x_dofmap.links(c);
    for (std::int32_t node : nodes)
      for (int i = 0; i < 3; ++i)
        midpoint[i] += x[3 * node + i] / nodes.size();
    parts[c] = part(midpoint.data());
  }
  return parts;
}

/// How far x lies outside the affine simplex `cell` (tdim + 1 nodes): the
/// most negative of its barycentric coordinates, negated (0 or less inside).
double outside_measure(const dolfinx::mesh::Mesh& mesh, std::int32_t cell, const double* x)
{
  const int tdim = mesh.topology().dim();
  const auto nodes = mesh.geometry().dofmap().links(cell);
  std::span<const double> coordinates = mesh.geometry().x();
  const double* x0 = &coordinates[3 * nodes[0]];
  Eigen::Matrix3d edges = Eigen::Matrix3d::Identity();
  Eigen::Vector3d offset;
  for (int i = 0; i < 3; ++i)
    offset[i] = i < tdim ? x[i] - x0[i] : 0.0;
  for (int k = 0; k < tdim; ++k)
    for (int i = 0; i < tdim; ++i)
      edges(i, k) = coordinates[3 * nodes[k + 1] + i] - x0[i];
  const Eigen::Vector3d lambda = edges.partialPivLu().solve(offset);
  double smallest = 1.0 - lambda.head(tdim).sum();
  for (int k = 0; k < tdim; ++k)
    smallest = std::min(smallest, lambda[k]);
  return -smallest;
}

/// How to find a point's cell on one rank: among the cells whose bounding
/// boxes hold it (measure: outside_measure, clamped at 0), or the nearest
/// cell wherever it lies (measure: squared distance).
enum class Search
{
  within_boxes,
  nearest_cell
};

/// Per point: the measure of the cell of its part on this rank that holds
/// it best (infinity when there is none) and the value there.
struct LocalEvaluation
{
  std::vector<double> measure;
  std::vector<double> values;
};

/// `cells_of_part`: this rank's cells of `from`'s mesh, by part.
LocalEvaluation evaluate_on_rank(const dolfinx::fem::Function<double>& from,
                                 const std::map<int, std::vector<std::int32_t>>& cells_of_part,
                                 const std::vector<double>& points, const std::vector<int>& point_parts,
                                 int value_size, Search search)
{
  const dolfinx::mesh::Mesh& mesh = *from.function_space()->mesh();
  const int tdim = mesh.topology().dim();
  const std::size_t num_points = point_parts.size();
  LocalEvaluation result{std::vector<double>(num_points, std::numeric_limits<double>::infinity()),
                         std::vector<double>(num_points * value_size, 0.0)};
  std::map<int, std::vector<std::size_t>> points_of_part;
  for (std::size_t i = 0; i < num_points; ++i)
    points_of_part[point_parts[i]].push_back(i);

  for (const auto& [label, indices] : points_of_part)
  {
    const auto found = cells_of_part.find(label);
    if (found == cells_of_part.end())
      continue;
    const std::vector<std::int32_t>& part_cells = found->second;
    std::vector<double> xs(3 * indices.size());
    for (std::size_t k = 0; k < indices.size(); ++k)
      std::copy_n(&points[3 * indices[k]], 3, &xs[3 * k]);
    const dolfinx::geometry::BoundingBoxTree tree(mesh, tdim, part_cells);
    std::vector<std::int32_t> cell(indices.size(), -1);
    std::vector<double> measure(indices.size(), std::numeric_limits<double>::infinity());
    if (search == Search::within_boxes)
    {
      const auto candidates = dolfinx::geometry::compute_collisions(tree, xs);
      for (std::size_t k = 0; k < indices.size(); ++k)
        for (std::int32_t c : candidates.links(k))
        {
          // Inside, or just outside the mesh (a finer mesh's node on a
          // curved face): the candidate nearest to holding it.
          const double outside = std::max(outside_measure(mesh, c, &xs[3 * k]), 0.0);
          if (outside < measure[k])
          {
            measure[k] = outside;
            cell[k] = c;
          }
        }
    }
    else
    {
      const dolfinx::geometry::BoundingBoxTree midpoints
          = dolfinx::geometry::create_midpoint_tree(mesh, tdim, part_cells);
      cell = dolfinx::geometry::compute_closest_entity(tree, midpoints, mesh, xs);
      measure = dolfinx::geometry::squared_distance(mesh, tdim, cell, xs);
    }
    // Function::eval skips a point of cell -1 (its value stays 0, its measure infinite).
    std::vector<double> values(indices.size() * value_size);
    from.eval(xs, {indices.size(), 3}, cell, values, {indices.size(), static_cast<std::size_t>(value_size)});
    for (std::size_t k = 0; k < indices.size(); ++k)
    {
      result.measure[indices[k]] = measure[k];
      std::copy_n(&values[k * value_size], value_size, &result.values[indices[k] * value_size]);
    }
  }
  return result;
}

/// Each point's value from the rank whose measure is least (every rank
/// returns the same); false for the points no rank holds.
std::vector<bool> take_best(MPI_Comm comm, LocalEvaluation& local, int value_size)
{
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  struct MeasureRank
  {
    double measure;
    int rank;
  };
  const std::size_t n = local.measure.size();
  std::vector<MeasureRank> best(n);
  for (std::size_t i = 0; i < n; ++i)
    best[i] = {local.measure[i], rank};
  MPI_Allreduce(MPI_IN_PLACE, best.data(), static_cast<int>(n), MPI_DOUBLE_INT, MPI_MINLOC, comm);
  std::vector<bool> held(n);
  for (std::size_t i = 0; i < n; ++i)
  {
    held[i] = best[i].measure < std::numeric_limits<double>::infinity();
    if (best[i].rank != rank)
      std::fill_n(&local.values[i * value_size], value_size, 0.0);
  }
  MPI_Allreduce(MPI_IN_PLACE, local.values.data(), static_cast<int>(local.values.size()), MPI_DOUBLE, MPI_SUM, comm);
  return held;
}
} // namespace

void interpolate_between_meshes(const dolfinx::fem::Function<double>& from, dolfinx::fem::Function<double>& to,
                                const std::function<int(const double* midpoint)>& part)
{
  const auto V = to.function_space();
  const int bs = V->dofmap()->index_map_bs();
  if (from.function_space()->element()->value_size() != bs || V->element()->value_size() != bs)
    throw ComputationError("interpolate_between_meshes: the two fields differ in their number of components");
  const dolfinx::mesh::Mesh& source = *from.function_space()->mesh();
  const int source_tdim = source.topology().dim();
  if (source.geometry().cmap().degree() != 1
      || (source.topology().index_map(source_tdim)->size_local() > 0
          && source.geometry().dofmap().links(0).size() != static_cast<std::size_t>(source_tdim + 1)))
    throw ComputationError("interpolate_between_meshes: the source mesh is not of affine simplices");
  const std::vector<double> x = V->tabulate_dof_coordinates(false);
  const std::size_t num_blocks = x.size() / 3;
  std::span<double> target = to.x()->mutable_array();
  if (target.size() != num_blocks * bs)
    throw ComputationError("interpolate_between_meshes: the target's layout is not one block per node");
  std::vector<double> block_part(num_blocks, 0.0);
  if (part)
  {
    const std::vector<int> parts = cell_parts(*V->mesh(), part);
    for (std::size_t c = 0; c < parts.size(); ++c)
      for (std::int32_t block : V->dofmap()->cell_dofs(static_cast<std::int32_t>(c)))
        block_part[block] = parts[c];
  }

  // Every rank searches every rank's nodes in its own cells.
  std::map<int, std::vector<std::int32_t>> cells_of_part;
  const std::vector<int> source_parts = cell_parts(source, part);
  for (std::int32_t c = 0; c < static_cast<std::int32_t>(source_parts.size()); ++c)
    cells_of_part[source_parts[c]].push_back(c);
  MPI_Comm comm = V->mesh()->comm();
  const std::vector<double> all_points = all_gather(comm, x);
  const std::vector<double> gathered_parts = all_gather(comm, block_part);
  const std::vector<int> all_parts(gathered_parts.begin(), gathered_parts.end());
  LocalEvaluation all = evaluate_on_rank(from, cells_of_part, all_points, all_parts, bs, Search::within_boxes);
  const std::vector<bool> held = take_best(comm, all, bs);

  // Nodes beyond every cell's bounding box (rare: a curved face's node just
  // past an axis-aligned facet): the nearest cell, searched for them alone.
  std::vector<std::size_t> beyond;
  for (std::size_t i = 0; i < held.size(); ++i)
    if (!held[i])
      beyond.push_back(i);
  if (!beyond.empty())
  {
    std::vector<double> points(3 * beyond.size());
    std::vector<int> parts(beyond.size());
    for (std::size_t j = 0; j < beyond.size(); ++j)
    {
      std::copy_n(&all_points[3 * beyond[j]], 3, &points[3 * j]);
      parts[j] = all_parts[beyond[j]];
    }
    LocalEvaluation nearest = evaluate_on_rank(from, cells_of_part, points, parts, bs, Search::nearest_cell);
    const std::vector<bool> held_nearest = take_best(comm, nearest, bs);
    for (std::size_t j = 0; j < beyond.size(); ++j)
    {
      if (!held_nearest[j])
        throw ComputationError(fmt::format("interpolate_between_meshes: the source mesh has no cell of part {} for "
                                           "the node at ({:.6g}, {:.6g}, {:.6g})",
                                           parts[j], points[3 * j], points[3 * j + 1], points[3 * j + 2]));
      std::copy_n(&nearest.values[j * bs], bs, &all.values[beyond[j] * bs]);
    }
  }

  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  std::int64_t offset = 0;
  const std::int64_t mine = static_cast<std::int64_t>(num_blocks);
  MPI_Exscan(&mine, &offset, 1, MPI_INT64_T, MPI_SUM, comm);
  if (rank == 0)
    offset = 0; // MPI_Exscan leaves rank 0's undefined
  std::copy_n(&all.values[offset * bs], num_blocks * bs, target.begin());
}
} // namespace rollcheck::fem
