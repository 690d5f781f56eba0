#include "fem/mortar_pairs.h"
#include "core/error.h"
#include "fem/all_gather.h"
#include "fem/clip_to_triangle.h"
#include <algorithm>
#include <chrono>
#include <cmath>
#include <fmt/format.h>
#include <map>
#include <mpi.h>
#include <spdlog/spdlog.h>

namespace rollcheck::fem
{
namespace
{
using Triangle = std::array<Point2, 3>;
using Gap = std::function<double(const double* x)>;
using Zone = std::function<bool(const double* x)>;

/// Horizontal bounding box as (min x, min y, -max x, -max y): one MPI_MIN
/// reduces all four.
using Box = std::array<double, 4>;

/// D. A. Dunavant, Int. J. Numer. Meth. Engng 21, 1985, 1129: the symmetric
/// 6-point rule of degree 4 on a triangle, barycentric points (a, a, 1 - 2a)
/// and permutations, weights over the area.
constexpr std::array<std::array<double, 2>, 2> dunavant_degree_4
    = {{{0.445948490915965, 0.223381589678011}, {0.091576213509771, 0.109951743655322}}};

/// A facet of the lower body's interface: its nodes' global blocks and
/// horizontal coordinates (x, y).
struct InterfaceFacet
{
  std::array<std::int64_t, 3> node{};
  Triangle x{};
};

/// An upper contact facet in the zone, projected onto the interface: its
/// nodes' global blocks, which of them are in the zone, its triangle and
/// the triangle's area.
struct UpperFacet
{
  std::array<std::int64_t, 3> node{};
  std::array<bool, 3> selected{};
  Triangle t{};
  double area = 0;
};

/// The mortar sums of one upper node (fem::NodePair): A = int N_i,
/// int psi_i g0 and int psi_i phi_j, over the projection onto the interface.
struct MortarSums
{
  double area = 0, gap_area = 0;
  std::map<std::int64_t, double> lower;
};
using SumsByNode = std::map<std::int64_t, MortarSums>;

/// The upper body's contact facets with a node in the zone (their local
/// blocks), and the horizontal box of every process's.
std::pair<std::vector<std::array<std::int32_t, 3>>, Box> upper_zone_facets(const PairingInput& in, const Zone& zone)
{
  const auto& topology = in.mesh.topology();
  const auto facet_cells = topology.connectivity(2, 3);
  const auto cell_facets = topology.connectivity(3, 2);
  if (!facet_cells || !cell_facets)
    throw ComputationError("node pairs: the mesh lacks its facet-cell connectivity");
  const auto& layout = in.dofmap.element_dof_layout();
  auto in_zone = [&](std::int32_t d) { return zone(&in.x[3 * d]); };
  std::vector<std::array<std::int32_t, 3>> facets;
  Box box{1e300, 1e300, 1e300, 1e300};
  for (std::int32_t f : in.contact_facets)
  {
    const std::int32_t c = facet_cells->links(f)[0];
    const auto facets_of_cell = cell_facets->links(c);
    const int local_facet
        = static_cast<int>(std::find(facets_of_cell.begin(), facets_of_cell.end(), f) - facets_of_cell.begin());
    const std::vector<int>& closure = layout.entity_closure_dofs(2, local_facet);
    if (closure.size() != 3)
      throw InputError("node pairs: the mortar pairs need linear elements");
    const auto cell_dofs = in.dofmap.cell_dofs(c);
    const std::array<std::int32_t, 3> dof{cell_dofs[closure[0]], cell_dofs[closure[1]], cell_dofs[closure[2]]};
    if (std::none_of(dof.begin(), dof.end(), in_zone))
      continue;
    facets.push_back(dof);
    for (std::int32_t d : dof)
      for (int k = 0; k < 2; ++k)
      {
        box[k] = std::min(box[k], in.x[3 * d + k]);
        box[2 + k] = std::min(box[2 + k], -in.x[3 * d + k]);
      }
  }
  MPI_Allreduce(MPI_IN_PLACE, box.data(), 4, MPI_DOUBLE, MPI_MIN, in.mesh.comm());
  return {std::move(facets), box};
}

/// Every process's lower interface facets overlapping the box: the whole
/// facets on the interface of the cells below it (the free part of the
/// lower face and the conforming part alike).
std::vector<InterfaceFacet> lower_interface_facets(const PairingInput& in, double tol, const Box& box)
{
  const std::span<const double> x = in.x;
  const std::int32_t cells = in.mesh.topology().index_map(3)->size_local();
  std::vector<double> local;
  for (std::int32_t c = 0; c < cells; ++c)
  {
    std::vector<std::int32_t> on;
    double below = 0;
    for (std::int32_t d : in.dofmap.cell_dofs(c))
    {
      if (std::abs(x[3 * d + 2]) < tol)
        on.push_back(d);
      else
        below = x[3 * d + 2];
    }
    if (on.size() != 3 || !(below < 0))
      continue;
    bool overlaps = true;
    for (int k = 0; k < 2; ++k)
    {
      const double lo = std::min({x[3 * on[0] + k], x[3 * on[1] + k], x[3 * on[2] + k]});
      const double hi = std::max({x[3 * on[0] + k], x[3 * on[1] + k], x[3 * on[2] + k]});
      overlaps = overlaps && hi >= box[k] - tol && lo <= -box[2 + k] + tol;
    }
    if (overlaps)
      for (std::int32_t d : on)
        local.insert(local.end(), {static_cast<double>(in.global_block(d)), x[3 * d], x[3 * d + 1]});
  }
  const std::vector<double> gathered = all_gather(in.mesh.comm(), local);
  std::vector<InterfaceFacet> facets(gathered.size() / 9);
  for (std::size_t f = 0; f < facets.size(); ++f)
    for (int k = 0; k < 3; ++k)
    {
      facets[f].node[k] = static_cast<std::int64_t>(gathered[9 * f + 3 * k]);
      facets[f].x[k] = {gathered[9 * f + 3 * k + 1], gathered[9 * f + 3 * k + 2]};
    }
  return facets;
}

/// The lower facets by the buckets of a grid over the box, n by n with
/// n = floor(sqrt(facets)): those that may lie beneath a triangle.
class FacetBuckets
{
public:
  FacetBuckets(const std::vector<InterfaceFacet>& facets, const Box& box)
      : _box(box), _n(std::max(1, static_cast<int>(std::sqrt(facets.size())))),
        _buckets(static_cast<std::size_t>(_n) * _n), _seen(facets.size(), -1)
  {
    for (std::size_t f = 0; f < facets.size(); ++f)
    {
      const std::array<int, 4> r = range(facets[f].x);
      for (int i = r[0]; i <= r[2]; ++i)
        for (int j = r[1]; j <= r[3]; ++j)
          _buckets[static_cast<std::size_t>(i) * _n + j].push_back(static_cast<std::int32_t>(f));
    }
  }

  /// The facets in the buckets the triangle's box touches, each once, in
  /// bucket order.
  std::vector<std::int32_t> beneath(const Triangle& t)
  {
    ++_stamp;
    std::vector<std::int32_t> found;
    const std::array<int, 4> r = range(t);
    for (int i = r[0]; i <= r[2]; ++i)
      for (int j = r[1]; j <= r[3]; ++j)
        for (std::int32_t m : _buckets[static_cast<std::size_t>(i) * _n + j])
          if (_seen[m] != _stamp)
          {
            _seen[m] = _stamp;
            found.push_back(m);
          }
    return found;
  }

private:
  int bucket(double v, int d) const
  {
    const double span = -_box[2 + d] - _box[d];
    const int b = span > 0 ? static_cast<int>((v - _box[d]) / span * _n) : 0;
    return std::clamp(b, 0, _n - 1);
  }
  /// First x, first y, last x, last y bucket of a triangle's box.
  std::array<int, 4> range(const Triangle& t) const
  {
    std::array<int, 4> r{_n, _n, -1, -1};
    for (const Point2& p : t)
      for (int d = 0; d < 2; ++d)
      {
        r[d] = std::min(r[d], bucket(p[d], d));
        r[2 + d] = std::max(r[2 + d], bucket(p[d], d));
      }
    return r;
  }

  Box _box;
  int _n;
  std::vector<std::vector<std::int32_t>> _buckets;
  std::vector<std::int32_t> _seen; ///< the stamp of the last search that found each facet
  std::int32_t _stamp = -1;
};

/// The upper facet of local blocks `dof`, projected; ComputationError if it
/// is seen edge-on from the interface: its nodes would get no area to weigh
/// their gaps by (the scene's tagging must not pass one).
UpperFacet project_upper_facet(const PairingInput& in, const std::array<std::int32_t, 3>& dof, const Zone& zone)
{
  UpperFacet u;
  for (int k = 0; k < 3; ++k)
  {
    u.node[k] = in.global_block(dof[k]);
    u.selected[k] = zone(&in.x[3 * dof[k]]);
    u.t[k] = {in.x[3 * dof[k]], in.x[3 * dof[k] + 1]};
  }
  const Triangle& t = u.t;
  u.area = 0.5 * std::abs(cross(t[0], t[1], t[2]));
  double longest = 0;
  for (int k = 0; k < 3; ++k)
    longest = std::max(longest, std::hypot(t[k][0] - t[(k + 1) % 3][0], t[k][1] - t[(k + 1) % 3][1]));
  if (!(u.area > 1e-12 * longest * longest))
    throw ComputationError(fmt::format("node pairs: a contact facet in the mortar zone at ({:.6g}, {:.6g}) m is "
                                       "seen edge-on from the interface (no projected area)",
                                       t[0][0], t[0][1]));
  return u;
}

/// Adds the integrals over `piece` (a triangle of the upper facet's overlap
/// with the lower facet, of area `piece_area`) to the sums of the upper
/// facet's selected nodes.
void integrate_piece(const Triangle& piece, double piece_area, const UpperFacet& upper, const InterfaceFacet& lower,
                     const Gap& initial_gap, SumsByNode& sums)
{
  for (const auto& [a, weight] : dunavant_degree_4)
    for (int perm = 0; perm < 3; ++perm)
    {
      std::array<double, 3> lambda{a, a, a};
      lambda[perm] = 1 - 2 * a;
      const Point2 q{lambda[0] * piece[0][0] + lambda[1] * piece[1][0] + lambda[2] * piece[2][0],
                     lambda[0] * piece[0][1] + lambda[1] * piece[1][1] + lambda[2] * piece[2][1]};
      const double dA = weight * piece_area;
      const std::array<double, 3> N = barycentric(upper.t, q), phi = barycentric(lower.x, q);
      const double point[3] = {q[0], q[1], 0.0};
      const double g0 = initial_gap(point);
      for (int s = 0; s < 3; ++s)
      {
        if (!upper.selected[s])
          continue;
        // The dual shape function, biorthogonal to N on the facet.
        const double psi = 4 * N[s] - 1;
        MortarSums& to = sums[upper.node[s]];
        to.area += N[s] * dA;
        to.gap_area += psi * g0 * dA;
        for (int k = 0; k < 3; ++k)
          to.lower[lower.node[k]] += psi * phi[k] * dA;
      }
    }
}

/// Each upper facet's projection cut by the lower facets beneath it, the
/// pieces' integrals summed by node. Collective: ComputationError on every
/// process where a facet is not wholly over the lower facets.
SumsByNode integrate_upper_facets(const PairingInput& in, const std::vector<std::array<std::int32_t, 3>>& upper_facets,
                                  const std::vector<InterfaceFacet>& lower, FacetBuckets& buckets,
                                  const Gap& initial_gap, const Zone& zone)
{
  SumsByNode sums;
  int uncovered = 0;
  for (const std::array<std::int32_t, 3>& dof : upper_facets)
  {
    const UpperFacet upper = project_upper_facet(in, dof, zone);
    const Triangle& t = upper.t;
    double covered = 0;
    for (std::int32_t m : buckets.beneath(t))
    {
      const std::vector<Point2> piece = clip_to_triangle({t[0], t[1], t[2]}, lower[m].x);
      for (std::size_t v = 1; v + 1 < piece.size(); ++v)
      {
        const Triangle sub{piece[0], piece[v], piece[v + 1]};
        const double sub_area = 0.5 * std::abs(cross(sub[0], sub[1], sub[2]));
        covered += sub_area;
        integrate_piece(sub, sub_area, upper, lower[m], initial_gap, sums);
      }
    }
    if (std::abs(covered - upper.area) > 1e-6 * upper.area)
      ++uncovered;
  }
  MPI_Allreduce(MPI_IN_PLACE, &uncovered, 1, MPI_INT, MPI_SUM, in.mesh.comm());
  if (uncovered > 0)
    throw ComputationError(fmt::format("node pairs: {} upper contact facets in the mortar zone are not wholly over "
                                       "the lower body's interface",
                                       uncovered));
  return sums;
}

/// A node's facets may lie on several processes: the sums of the nodes other
/// processes own go to them (node, kind, block, value: kind 0 the area, 1 the
/// gap's, 2 a lower weight) and are added to theirs. Collective.
void send_sums_to_owners(const PairingInput& in, SumsByNode& sums)
{
  std::vector<double> local;
  for (auto it = sums.begin(); it != sums.end();)
  {
    const auto& [node, s] = *it;
    if (in.owns(node))
    {
      ++it;
      continue;
    }
    const double i = static_cast<double>(node);
    local.insert(local.end(), {i, 0, -1, s.area, i, 1, -1, s.gap_area});
    for (const auto& [block, value] : s.lower)
      local.insert(local.end(), {i, 2, static_cast<double>(block), value});
    it = sums.erase(it);
  }
  const std::vector<double> shared = all_gather(in.mesh.comm(), local);
  for (std::size_t e = 0; e + 3 < shared.size(); e += 4)
  {
    const auto node = static_cast<std::int64_t>(shared[e]);
    if (!in.owns(node))
      continue;
    MortarSums& s = sums[node];
    const int kind = static_cast<int>(shared[e + 1]);
    const auto block = static_cast<std::int64_t>(shared[e + 2]);
    const double value = shared[e + 3];
    if (kind == 0)
      s.area += value;
    else if (kind == 1)
      s.gap_area += value;
    else
      s.lower[block] += value;
  }
}

/// The pairs of the owned nodes' sums: w_ij and g0_i over A_i.
std::vector<NodePair> pairs_from_sums(const PairingInput& in, const SumsByNode& sums)
{
  std::vector<NodePair> pairs;
  for (const auto& [node, s] : sums)
  {
    const double* p = &in.x[3 * (node - in.first_block())];
    NodePair pair;
    pair.node = node;
    // Where the faces match, psi_i's integrals against the other nodes'
    // phi_j vanish but for rounding: no Jacobian entries for those.
    for (const auto& [block, value] : s.lower)
      if (std::abs(value) > 1e-12 * s.area)
        pair.lower.push_back({block, value / s.area});
    pair.x = {p[0], p[1], p[2]};
    pair.area_m2 = s.area;
    pair.initial_gap_m = s.gap_area / s.area;
    pairs.push_back(std::move(pair));
  }
  return pairs;
}
} // namespace

std::vector<NodePair> mortar_node_pairs(const PairingInput& input, double tol, const Gap& initial_gap,
                                        const Zone& mortar_zone)
{
  const auto start = std::chrono::steady_clock::now();
  const auto [upper_facets, box] = upper_zone_facets(input, mortar_zone);
  const std::vector<InterfaceFacet> lower = lower_interface_facets(input, tol, box);
  FacetBuckets buckets(lower, box);
  SumsByNode sums = integrate_upper_facets(input, upper_facets, lower, buckets, initial_gap, mortar_zone);
  send_sums_to_owners(input, sums);
  std::vector<NodePair> pairs = pairs_from_sums(input, sums);
  spdlog::debug("node pairs: {} mortar pairs on this process from {} facets, {:.2f} s", pairs.size(),
                upper_facets.size(), std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  return pairs;
}
} // namespace rollcheck::fem
