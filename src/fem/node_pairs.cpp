#include "fem/node_pairs.h"
#include "core/error.h"
#include "fem/all_gather.h"
#include "fem/mortar_pairs.h"
#include <cmath>
#include <fmt/format.h>
#include <iterator>
#include <map>

namespace rollcheck::fem
{
namespace
{
/// Every process's interface nodes (height within `tol` of 0) as (x, y,
/// global block, contact area), gathered: twins may lie on different
/// processes.
std::vector<double> gather_interface_nodes(const PairingInput& in, double tol)
{
  const int up = in.mesh.geometry().dim() - 1;
  const std::int64_t first = in.first_block();
  std::vector<double> local;
  for (std::int32_t i = 0; i < in.owned_blocks(); ++i)
    if (std::abs(in.x[3 * i + up]) < tol)
      local.insert(local.end(), {in.x[3 * i], in.x[3 * i + 1], static_cast<double>(first + i), in.contact_area[i]});
  return all_gather(in.mesh.comm(), local);
}

/// This process's upper interface nodes outside the mortar zone, each paired
/// with its twin (weight 1).
std::vector<NodePair> node_to_node_pairs(const PairingInput& in, double tol,
                                         const std::function<double(const double* x)>& initial_gap,
                                         const std::function<bool(const double* x)>& mortar_zone)
{
  std::vector<NodePair> pairs;
  for (const std::vector<std::pair<std::int64_t, double>>& nodes :
       interface_twins(gather_interface_nodes(in, tol), tol))
  {
    const bool first_upper = nodes[0].second > 0;
    if (nodes.size() == 1 && !first_upper)
      continue; // on the lower body's free face beyond the upper one
    if (nodes.size() != 2)
      throw ComputationError(fmt::format("node pairs: {} interface nodes at one place, not a pair", nodes.size()));
    if (!first_upper && !(nodes[1].second > 0))
      continue; // on the edge of the upper body's face, without contact area
    const auto& [upper, upper_area] = first_upper ? nodes[0] : nodes[1];
    const std::int64_t lower = first_upper ? nodes[1].first : nodes[0].first;
    if (!in.owns(upper))
      continue; // another process's
    const double* p = &in.x[3 * (upper - in.first_block())];
    if (mortar_zone && mortar_zone(p))
      continue;
    NodePair pair;
    pair.node = upper;
    pair.lower = {{lower, 1.0}};
    pair.x = {p[0], p[1], p[2]};
    pair.area_m2 = upper_area;
    pair.initial_gap_m = initial_gap(p);
    pairs.push_back(pair);
  }
  return pairs;
}
} // namespace

std::vector<std::vector<std::pair<std::int64_t, double>>> interface_twins(std::span<const double> nodes, double tol)
{
  // By their place rounded to `tol`. Twins within tol of each other whose
  // rounding falls on either side of a cell's boundary land in neighbouring
  // cells: the lone nodes of neighbouring cells within tol of each other are
  // joined (the U optimum's 170 deg end on steel met one such pair at
  // h_e = b/64).
  using Cell = std::pair<double, double>;
  struct AtPlace
  {
    std::array<double, 2> place; // the first node's
    std::vector<std::pair<std::int64_t, double>> nodes;
  };
  std::map<Cell, AtPlace> at_place;
  for (std::size_t i = 0; i + 3 < nodes.size(); i += 4)
  {
    AtPlace& at = at_place.try_emplace({std::round(nodes[i] / tol), std::round(nodes[i + 1] / tol)},
                                       AtPlace{{nodes[i], nodes[i + 1]}, {}})
                      .first->second;
    at.nodes.push_back({static_cast<std::int64_t>(nodes[i + 2]), nodes[i + 3]});
  }
  for (auto it = at_place.begin(); it != at_place.end(); ++it)
    for (int dx = -1; dx <= 1 && it->second.nodes.size() == 1; ++dx)
      for (int dy = -1; dy <= 1 && it->second.nodes.size() == 1; ++dy)
      {
        const auto other = at_place.find({it->first.first + dx, it->first.second + dy});
        if (other == at_place.end() || other == it || other->second.nodes.size() != 1)
          continue;
        const std::array<double, 2>& a = it->second.place;
        const std::array<double, 2>& b = other->second.place;
        if (std::hypot(a[0] - b[0], a[1] - b[1]) < tol)
        {
          it->second.nodes.push_back(other->second.nodes.front());
          at_place.erase(other);
        }
      }
  std::vector<std::vector<std::pair<std::int64_t, double>>> twins;
  for (auto& [cell, at] : at_place)
    twins.push_back(std::move(at.nodes));
  return twins;
}

std::vector<NodePair> interface_node_pairs(const PairingInput& input, double tol,
                                           const std::function<double(const double* x)>& initial_gap,
                                           const std::function<bool(const double* x)>& mortar_zone)
{
  std::vector<NodePair> pairs = node_to_node_pairs(input, tol, initial_gap, mortar_zone);
  if (!mortar_zone)
    return pairs;
  if (input.mesh.geometry().dim() != 3)
    throw InputError("node pairs: the mortar pairs are 3D only");
  std::vector<NodePair> mortar = mortar_node_pairs(input, tol, initial_gap, mortar_zone);
  pairs.insert(pairs.end(), std::make_move_iterator(mortar.begin()), std::make_move_iterator(mortar.end()));
  return pairs;
}
} // namespace rollcheck::fem
