// The rim loop's FEM end table (study/rims/end_table.h).
#include "study/rims/end_table.h"
#include "core/degree.h"
#include "contact/edge_on_elastic_block_exponent.h"
#include "contact/wedge_exponent.h"
#include "core/error.h"
#include "study/rims/table_nodes.h"
#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <span>

namespace rollcheck::study::rims
{
namespace
{

/// The table's columns: its runs of nodes of one R.
std::vector<std::span<const EndTableNode>> table_columns(const std::vector<EndTableNode>& table)
{
  std::vector<std::span<const EndTableNode>> columns;
  for (auto first = table.begin(); first != table.end();)
  {
    const auto last = std::find_if(first, table.end(), [&](const EndTableNode& n) {
      return n.sheet_radius_m != first->sheet_radius_m;
    });
    columns.emplace_back(first, last);
    first = last;
  }
  return columns;
}
} // namespace

double sharp_edge_exponent(const fem::RimEndSettings& end, double wedge_angle_rad)
{
  return end.counter_face == fem::CounterFace::rigid
             ? contact::edge_on_rigid_plane_exponent(wedge_angle_rad)
             : contact::edge_on_elastic_block_exponent(wedge_angle_rad, end.youngs_modulus_pa, end.poisson_ratio,
                                                       end.youngs_modulus_pa, end.poisson_ratio);
}

double largest_modelled_angle(const fem::RimEndSettings& end)
{
  return end.edge_radius_m > 0 ? largest_rounded_angle_rad : largest_modelled_angle_rad;
}

double singular_from_angle(const fem::RimEndSettings& end)
{
  if (end.edge_radius_m > 0)
    return std::numbers::pi;
  // Singular as the end model calls it (fem/scenes/rim_end_contact.h): any negative exponent.
  auto singular = [&](double a) { return sharp_edge_exponent(end, a) < 0; };
  double lo = smallest_modelled_angle_rad, hi = largest_modelled_angle_rad;
  if (singular(lo))
    return lo;
  if (!singular(hi))
    return std::numbers::pi;
  while (hi - lo > singular_angle_tolerance_rad)
  {
    const double mid = 0.5 * (lo + hi);
    (singular(mid) ? hi : lo) = mid;
  }
  return hi;
}

std::vector<double> end_table_angles(double lo, double hi, double step_rad, double acute_step_rad)
{
  constexpr double square = std::numbers::pi / 2;
  if (!(acute_step_rad > 0) || lo >= square - 1e-9)
    return even_nodes(lo, hi, step_rad);
  if (hi <= square + 1e-9)
    return even_nodes(lo, hi, acute_step_rad);
  std::vector<double> angles = even_nodes(lo, square, acute_step_rad);
  const std::vector<double> obtuse = even_nodes(square, hi, step_rad);
  angles.insert(angles.end(), obtuse.begin() + 1, obtuse.end());
  return angles;
}

namespace
{
/// A look-up's reads: per column about R, its weight and its nodes about the
/// angle (indices into the table) with theirs.
struct ColumnRead
{
  double weight;
  std::vector<std::pair<std::size_t, double>> nodes;
};

std::vector<ColumnRead> table_reads(const std::vector<EndTableNode>& table, int stride, double dihedral_angle_rad,
                                    double radius_m)
{
  if (table.empty())
    throw ComputationError("rim loop: a non-singular loaded end, but the end table is empty");
  const std::vector<std::span<const EndTableNode>> columns = table_columns(table);
  if (columns.size() > 1 && !(radius_m > 0))
    throw ComputationError(fmt::format("rim loop: the end table's ratio needs R > 0, got {} m", radius_m));
  std::vector<double> column_positions;
  for (const std::span<const EndTableNode> column : columns)
    column_positions.push_back(columns.size() > 1 ? std::log(column.front().sheet_radius_m) : 0.0);
  std::vector<ColumnRead> reads;
  for (const auto& [c, weight] : held_bracket(column_positions, own_stride(stride, columns.size()),
                                              columns.size() > 1 ? std::log(radius_m) : 0.0))
  {
    const std::span<const EndTableNode> column = columns[c];
    std::vector<double> angles;
    for (const EndTableNode& n : column)
      angles.push_back(n.dihedral_angle_rad);
    ColumnRead read{weight, {}};
    const auto first = static_cast<std::size_t>(&column.front() - table.data());
    for (const auto& [k, node_weight] : held_bracket(angles, own_stride(stride, column.size()), dihedral_angle_rad))
      read.nodes.emplace_back(first + k, node_weight);
    reads.push_back(std::move(read));
  }
  return reads;
}
} // namespace

std::optional<double> end_table_ratio(const std::vector<EndTableNode>& table, int stride, double singular_from_rad,
                                      double dihedral_angle_rad, double radius_m)
{
  if (dihedral_angle_rad > singular_from_rad)
    return std::nullopt;
  // Summed as interpolate_held sums: (1 - t) left + t right, a held node alone.
  auto weighted = [](const std::vector<std::pair<double, double>>& terms) {
    return terms.size() == 1 ? terms[0].second : terms[0].first * terms[0].second + terms[1].first * terms[1].second;
  };
  std::vector<std::pair<double, double>> across;
  for (const ColumnRead& read : table_reads(table, stride, dihedral_angle_rad, radius_m))
  {
    std::vector<std::pair<double, double>> along;
    for (const auto& [k, weight] : read.nodes)
    {
      const EndTableNode& n = table[k];
      if (!n.reached)
        throw ComputationError(fmt::format("rim loop: the end table's node at {:.2f} deg, R = {:.4g} m was left "
                                           "unsolved, but a look-up at {:.2f} deg, R = {:.4g} m reads it",
                                           n.dihedral_angle_rad / degree, n.sheet_radius_m,
                                           dihedral_angle_rad / degree, radius_m));
      if (!n.study.end_to_interior)
        throw ComputationError(fmt::format("rim loop: the end table's node at {:.2f} deg, R = {:.4g} m has no "
                                           "end/interior ratio (its rounded edge is not resolved)",
                                           n.dihedral_angle_rad / degree, n.sheet_radius_m));
      along.emplace_back(weight, *n.study.end_to_interior);
    }
    across.emplace_back(read.weight, weighted(along));
  }
  return weighted(across);
}

std::vector<std::size_t> end_table_nodes_read(const std::vector<EndTableNode>& table, int stride,
                                              double singular_from_rad, double dihedral_angle_rad, double radius_m)
{
  std::vector<std::size_t> nodes;
  if (dihedral_angle_rad > singular_from_rad)
    return nodes;
  for (const ColumnRead& read : table_reads(table, stride, dihedral_angle_rad, radius_m))
    for (const auto& [k, weight] : read.nodes)
      nodes.push_back(k);
  return nodes;
}
} // namespace rollcheck::study::rims
