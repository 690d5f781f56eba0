// The mortar pairs of fem::interface_node_pairs (fem/penalty_contact.h
// NodePair) where a rounded edge's fillet lifts off the steel block, on the
// rim block scene (fem/mesh/scene_mesh.h build_rim_block_mesh) of the preprint's
// body's 60 deg end at coarse edge elements (b / 8). The contact patch test
// in its discrete form: a uniform traction t on the fillet's face reaches the
// block's nodes as its consistent loads, sum_i t A_i w_ij = t int phi_j dA,
// whatever the two faces' meshes (a node-to-segment pair, w_ij the
// barycentric weights of the point below node i and A_i its area, gives
// each block node what the fillet nodes above its facets happen to carry).
// And a displacement u_z linear in x and y, the same on both bodies, leaves
// every pair's gap at its g0. The dual weights make each pair read its own
// node above, and node to node where the faces match. CTest runs it on 1
// and on 2 processes (the facets of a node on two ranks).
#include "core/error.h"
#include "fem/all_gather.h"
#include "fem/penalty_contact.h"
#include "fem/petsc_session.h"
#include "fem/scenes/rim_end_contact.h"
#include "fem/mesh/scene_mesh.h"
#include "fem/steel_end_scene.h"
#include <dolfinx/mesh/utils.h>
#include <cmath>
#include <cstdio>
#include <gtest/gtest.h>
#include <algorithm>
#include <map>
#include <mpi.h>
#include <numbers>


namespace
{
/// Every rank's (block, value) pairs summed per block, on every rank.
std::map<std::int64_t, double> summed_over_ranks(const std::vector<double>& local)
{
  std::map<std::int64_t, double> sum;
  const std::vector<double> all = rollcheck::fem::all_gather(MPI_COMM_WORLD, local);
  for (std::size_t i = 0; i < all.size(); i += 2)
    sum[static_cast<std::int64_t>(all[i])] += all[i + 1];
  return sum;
}

/// The loads a unit traction puts through the pairs on the upper body's
/// nodes: A_i on each pair's node.
std::map<std::int64_t, double> upper_unit_traction_loads(const std::vector<rollcheck::fem::NodePair>& pairs)
{
  std::vector<double> local;
  for (const rollcheck::fem::NodePair& pair : pairs)
    local.insert(local.end(), {static_cast<double>(pair.node), pair.area_m2});
  return summed_over_ranks(local);
}

/// The same on the lower body's nodes: sum_i A_i w_j.
std::map<std::int64_t, double> lower_unit_traction_loads(const std::vector<rollcheck::fem::NodePair>& pairs)
{
  std::vector<double> local;
  for (const rollcheck::fem::NodePair& pair : pairs)
    for (const rollcheck::fem::WeightedBlock& w : pair.lower)
      local.insert(local.end(), {static_cast<double>(w.block), pair.area_m2 * w.weight});
  return summed_over_ranks(local);
}

/// `shares`: this rank's (block, a third of a facet's area, whether the
/// facet counts) for each node of each facet. Over the nodes whose facets
/// all count, the largest |load / int phi dA - 1|, and how many they are.
std::pair<double, int> largest_load_error(const std::vector<double>& shares,
                                          const std::map<std::int64_t, double>& load)
{
  std::map<std::int64_t, std::pair<double, bool>> consistent;
  const std::vector<double> all = rollcheck::fem::all_gather(MPI_COMM_WORLD, shares);
  for (std::size_t i = 0; i < all.size(); i += 3)
  {
    auto [it, added] = consistent.try_emplace(static_cast<std::int64_t>(all[i]), 0.0, true);
    it->second.first += all[i + 1];
    it->second.second = it->second.second && all[i + 2] > 0;
  }
  double worst = 0;
  int counted = 0;
  for (const auto& [block, c] : consistent)
    if (c.second)
    {
      ++counted;
      const auto it = load.find(block);
      worst = std::max(worst, std::abs((it == load.end() ? 0.0 : it->second) / c.first - 1));
    }
  return {worst, counted};
}

/// Half the cross product's z of (q - p) and (r - p): the projected area.
double projected_area(const double* p, const double* q, const double* r)
{
  return 0.5 * std::abs((q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0]));
}
} // namespace

TEST(MortarPairs, UniformTractionReachesTheBlockAsItsConsistentLoads)
{
  rollcheck::fem::ensure_petsc();
  const SteelEndScene end = mesh_preprint_steel_end();
  const double edge_radius = end.edge_radius_m, fillet_start = end.fillet_start_m;
  const rollcheck::fem::RimEndSizes& sizes = end.sizes;
  const rollcheck::fem::SceneMesh& scene = end.scene;
  const double E = 200e9;
  rollcheck::fem::PenaltyContact problem(scene, rollcheck::fem::Model::solid, 1, E, 0.3, 10 * E / sizes.contact_m, "");
  const double tol = rollcheck::fem::rim_interface_tolerance(end.depth_m, sizes.edge_m, edge_radius);
  // The body's contact face up to r_e / 8 above the block, as the rim scene pairs it.
  auto mortar_zone = [&](const double* x) { return x[2] <= edge_radius / 8; };
  auto no_gap = [](const double*) { return 0.0; };
  const std::vector<rollcheck::fem::NodePair> pairs = rollcheck::fem::interface_node_pairs(problem, tol, no_gap, mortar_zone);

  int on_fillet = 0;
  for (const rollcheck::fem::NodePair& pair : pairs)
    on_fillet += pair.x[2] >= tol ? 1 : 0;
  MPI_Allreduce(MPI_IN_PLACE, &on_fillet, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD);
  ASSERT_GT(on_fillet, 100) << "the fillet's nodes above the block";

  // The dual weights: on the sheet, where the two faces' meshes match, each
  // pair reads one block node below (its twin) with weight 1: the
  // node-to-node pair.
  int matched = 0, not_node_to_node = 0;
  for (const rollcheck::fem::NodePair& pair : pairs)
  {
    if (pair.x[0] < -fillet_start - end.half_width_m)
    {
      ++matched;
      not_node_to_node += pair.lower.size() == 1 && std::abs(pair.lower.front().weight - 1) < 1e-9 ? 0 : 1;
    }
  }
  MPI_Allreduce(MPI_IN_PLACE, &matched, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD);
  MPI_Allreduce(MPI_IN_PLACE, &not_node_to_node, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD);
  EXPECT_GT(matched, 1000);
  EXPECT_EQ(not_node_to_node, 0) << "of " << matched << " pairs on the sheet";

  // The contact facets whose nodes all take mortar pairs: a unit traction
  // covers their projections onto the block (beyond the zone a facet shares
  // its area with nodes without pairs).
  const auto& topology = scene.mesh->topology();
  const std::vector<std::int32_t> facet_nodes
      = dolfinx::mesh::entities_to_geometry(*scene.mesh, 2, scene.contact_facets, false);
  std::span<const double> X = scene.mesh->geometry().x();
  std::vector<double> local_facets;
  for (std::size_t f = 0; f < scene.contact_facets.size(); ++f)
  {
    std::vector<double> corners;
    for (int k = 0; k < 3; ++k)
      if (const double* v = &X[3 * facet_nodes[3 * f + k]]; mortar_zone(v))
        corners.insert(corners.end(), {v[0], v[1]});
    if (corners.size() == 6)
      local_facets.insert(local_facets.end(), corners.begin(), corners.end());
  }
  const std::vector<double> covered = rollcheck::fem::all_gather(MPI_COMM_WORLD, local_facets);
  auto under_fillet = [&](double px, double py) {
    for (std::size_t f = 0; f < covered.size(); f += 6)
    {
      const double* t = &covered[f];
      const double area = (t[2] - t[0]) * (t[5] - t[1]) - (t[3] - t[1]) * (t[4] - t[0]);
      const double w1 = ((px - t[0]) * (t[5] - t[1]) - (py - t[1]) * (t[4] - t[0])) / area;
      const double w2 = ((t[2] - t[0]) * (py - t[1]) - (t[3] - t[1]) * (px - t[0])) / area;
      if (std::min({w1, w2, 1 - w1 - w2}) >= -1e-9)
        return true;
    }
    return false;
  };

  // The block's top facets (from the mesh alone: the cells with a face on
  // z = 0 below it): int phi_j dA, a third of each facet's area to each of
  // its nodes; a node counts if every facet of it lies under the zone's
  // (sampled on a grid of 15 points each) and one reaches under the fillet.
  const auto& V = *problem.displacement()->function_space();
  const auto map = V.dofmap()->index_map;
  const std::int64_t first = map->local_range()[0];
  const std::int32_t owned = map->size_local();
  const std::vector<double>& x = problem.dof_coordinates();
  std::vector<double> local;
  for (std::int32_t c = 0; c < topology.index_map(3)->size_local(); ++c)
  {
    std::vector<std::int32_t> top;
    bool below = false;
    for (std::int32_t d : V.dofmap()->cell_dofs(c))
    {
      if (std::abs(x[3 * d + 2]) < tol)
        top.push_back(d);
      else
        below = x[3 * d + 2] < 0;
    }
    if (top.size() != 3 || !below)
      continue;
    const double* p = &x[3 * top[0]];
    const double* q = &x[3 * top[1]];
    const double* r = &x[3 * top[2]];
    const double area = projected_area(p, q, r);
    bool inside = std::max({p[0], q[0], r[0]}) > -fillet_start;
    for (int i = 0; i <= 4 && inside; ++i)
      for (int j = 0; i + j <= 4 && inside; ++j)
      {
        const double a = i / 4.0, e = j / 4.0;
        inside = under_fillet((1 - a - e) * p[0] + a * q[0] + e * r[0], (1 - a - e) * p[1] + a * q[1] + e * r[1]);
      }
    for (std::int32_t d : top)
    {
      const std::int64_t g = d < owned ? first + d : map->ghosts()[d - owned];
      local.insert(local.end(), {static_cast<double>(g), area / 3, inside ? 1.0 : 0.0});
    }
  }
  const auto [worst, checked] = largest_load_error(local, lower_unit_traction_loads(pairs));
  std::printf("%d pairs on the fillet; %d block nodes under it: largest |load / int phi - 1| %.3g\n", on_fillet, checked,
              worst);
  ASSERT_GT(checked, 20);
  EXPECT_LT(worst, 1e-9);

  // And the body's nodes: sum_i t A_i a_ik = t int N_k dA where every
  // contact facet of node k has its nodes paired (a node-to-node pair
  // beside a mortar pair would take the shared facets' load twice).
  const auto facet_cells = topology.connectivity(2, 3);
  const auto cell_facets = topology.connectivity(3, 2);
  local.clear();
  for (std::int32_t f : scene.contact_facets)
  {
    const std::int32_t c = facet_cells->links(f)[0];
    const auto facets_of_cell = cell_facets->links(c);
    const int k = static_cast<int>(std::find(facets_of_cell.begin(), facets_of_cell.end(), f) - facets_of_cell.begin());
    const auto cell_dofs = V.dofmap()->cell_dofs(c);
    std::vector<std::int32_t> dofs;
    for (int i : V.dofmap()->element_dof_layout().entity_closure_dofs(2, k))
      dofs.push_back(cell_dofs[i]);
    const double* p = &x[3 * dofs[0]];
    const double* q = &x[3 * dofs[1]];
    const double* r = &x[3 * dofs[2]];
    const double area = projected_area(p, q, r);
    // Every node paired: node to node on the interface, or by the mortar.
    auto paired = [&](const double* v) { return std::abs(v[2]) < tol || mortar_zone(v); };
    const bool zone = paired(p) && paired(q) && paired(r);
    for (std::int32_t d : dofs)
    {
      const std::int64_t g = d < owned ? first + d : map->ghosts()[d - owned];
      local.insert(local.end(), {static_cast<double>(g), area / 3, zone ? 1.0 : 0.0});
    }
  }
  const auto [body_worst, body_checked] = largest_load_error(local, upper_unit_traction_loads(pairs));
  std::printf("%d body nodes in the zone: largest |load / int N - 1| %.3g\n", body_checked, body_worst);
  ASSERT_GT(body_checked, 100);
  EXPECT_LT(body_worst, 1e-9);

  // u_z linear in x and y on the block and the same less d on the body:
  // every pair's gap is then g0 - d = -d, whatever its weights.
  std::vector<rollcheck::fem::NodePair> stiff = pairs;
  const double kappa = 10 * E / sizes.contact_m, d = 1e-9;
  for (rollcheck::fem::NodePair& pair : stiff)
    pair.stiffness_pa_per_m = kappa;
  problem.set_node_pairs(std::move(stiff));
  std::vector<bool> on_body(x.size() / 3, false);
  for (std::int32_t c = 0; c < scene.mesh->topology().index_map(3)->size_local(); ++c)
  {
    const auto dofs = V.dofmap()->cell_dofs(c);
    double z = 0;
    for (std::int32_t i : dofs)
      z += x[3 * i + 2] / dofs.size();
    if (z > 0)
      for (std::int32_t i : dofs)
        on_body[i] = true;
  }
  // The problem's own state (its start), set here to the test's field.
  std::span<double> u = std::const_pointer_cast<dolfinx::fem::Function<double>>(problem.displacement())
                            ->x()
                            ->mutable_array();
  for (std::size_t i = 0; i < on_body.size(); ++i)
    u[3 * i + 2] = 1e-6 + 3e-3 * x[3 * i] - 2e-3 * x[3 * i + 1] - (on_body[i] ? d : 0.0);
  double worst_pressure = 0;
  for (double p : problem.pair_pressures_pa())
    worst_pressure = std::max(worst_pressure, std::abs(p / (kappa * d) - 1));
  MPI_Allreduce(MPI_IN_PLACE, &worst_pressure, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  std::printf("largest |p / (kappa d) - 1| under a linear field %.3g\n", worst_pressure);
  EXPECT_LT(worst_pressure, 1e-6);
}
