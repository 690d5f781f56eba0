// The mortar pairs of fem::interface_node_pairs (fem/penalty_contact.h
// NodePair) where a rounded edge's fillet lifts off the steel block, on the
// rim block scene (fem/scene_mesh.h build_rim_block_mesh) of the preprint's
// body's 60 deg end at coarse edge elements (b / 8). The contact patch test
// in its discrete form: a uniform traction t on the fillet's face reaches the
// block's nodes as its consistent loads, sum_i t A_i w_ij = t int phi_j dA,
// whatever the two faces' meshes (a node-to-segment pair, w_ij the
// barycentric weights of the point below node i and A_i its area, gives
// each block node what the fillet nodes above its facets happen to carry).
// And a displacement u_z linear in x and y, the same on both bodies, leaves
// every pair's gap at its g0. CTest runs it on 1 and on 2 processes (the
// facets of a node on two ranks).
#include "core/error.h"
#include "fem/all_gather.h"
#include "fem/penalty_contact.h"
#include "fem/petsc_session.h"
#include "fem/rim_end_contact.h"
#include "fem/scene_mesh.h"
#include <cmath>
#include <cstdio>
#include <gtest/gtest.h>
#include <algorithm>
#include <map>
#include <mpi.h>
#include <numbers>


namespace
{
constexpr double degree = std::numbers::pi / 180;
}

TEST(MortarPairs, UniformTractionReachesTheBlockAsItsConsistentLoads)
{
  rollcheck::fem::ensure_petsc();
  const double b = 1.16e-4, H = 36.2 * b, edge_radius = 4e-4, angle = 60 * degree;
  const double fillet_start = rollcheck::fem::fillet_start_distance(edge_radius, angle);
  rollcheck::fem::RimEndSizes sizes;
  sizes.contact_m = b / 6;
  sizes.contact_zone_m = sizes.edge_zone_m = 1.5 * b;
  sizes.edge_m = b / 8;
  sizes.edge_x_m = -fillet_start;
  sizes.edge_band_m = 0.5 * b;
  sizes.far_m = H / 4;
  const rollcheck::fem::RimEndGeometry geometry{0.0224, angle, edge_radius, H, 3 * H, true};
  const rollcheck::fem::SceneMesh scene = rollcheck::fem::build_rim_block_mesh(MPI_COMM_WORLD, geometry, sizes);
  const double E = 200e9;
  rollcheck::fem::PenaltyContact problem(scene, rollcheck::fem::Model::solid, 1, E, 0.3, 10 * E / sizes.contact_m, "");
  const double tol = rollcheck::fem::rim_interface_tolerance(H, sizes.edge_m, edge_radius);
  // The body's contact face up to r_e / 8 above the block, as the rim scene pairs it.
  auto mortar_zone = [&](const double* x) { return x[2] <= edge_radius / 8; };
  auto no_gap = [](const double*) { return 0.0; };
  const std::vector<rollcheck::fem::NodePair> pairs = rollcheck::fem::interface_node_pairs(problem, tol, no_gap, mortar_zone);

  // The loads the pairs put on the block's nodes under a unit traction.
  std::vector<double> local;
  int on_fillet = 0;
  for (const rollcheck::fem::NodePair& pair : pairs)
  {
    if (pair.x[2] >= tol)
      ++on_fillet;
    for (const rollcheck::fem::WeightedBlock& w : pair.lower)
      local.insert(local.end(), {static_cast<double>(w.block), pair.area_m2 * w.weight});
  }
  MPI_Allreduce(MPI_IN_PLACE, &on_fillet, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD);
  ASSERT_GT(on_fillet, 100) << "the fillet's nodes above the block";
  std::map<std::int64_t, double> load;
  const std::vector<double> loads = rollcheck::fem::all_gather(MPI_COMM_WORLD, local);
  for (std::size_t i = 0; i < loads.size(); i += 2)
    load[static_cast<std::int64_t>(loads[i])] += loads[i + 1];

  // The contact facets whose nodes all take mortar pairs: a unit traction
  // covers their projections onto the block (beyond the zone a facet shares
  // its area with nodes without pairs).
  const auto& topology = scene.mesh->topology();
  const auto facet_vertices = topology.connectivity(2, 0);
  ASSERT_TRUE(facet_vertices);
  std::span<const double> X = scene.mesh->geometry().x();
  std::vector<double> local_facets;
  for (std::int32_t f : scene.contact_facets)
  {
    std::vector<double> corners;
    for (std::int32_t v : facet_vertices->links(f))
      if (mortar_zone(&X[3 * v]))
        corners.insert(corners.end(), {X[3 * v], X[3 * v + 1]});
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
  local.clear();
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
    const double area = 0.5 * std::abs((q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0]));
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
  std::map<std::int64_t, std::pair<double, bool>> consistent; // int phi_j, every facet under the fillet's
  const std::vector<double> shares = rollcheck::fem::all_gather(MPI_COMM_WORLD, local);
  for (std::size_t i = 0; i < shares.size(); i += 3)
  {
    auto [it, added] = consistent.try_emplace(static_cast<std::int64_t>(shares[i]), 0.0, true);
    it->second.first += shares[i + 1];
    it->second.second = it->second.second && shares[i + 2] > 0;
  }
  int checked = 0;
  double worst = 0;
  for (const auto& [block, c] : consistent)
  {
    if (!c.second)
      continue;
    ++checked;
    const auto it = load.find(block);
    worst = std::max(worst, std::abs((it == load.end() ? 0.0 : it->second) / c.first - 1));
  }
  std::printf("%d pairs on the fillet; %d block nodes under it: largest |load / int phi - 1| %.3g\n", on_fillet, checked,
              worst);
  ASSERT_GT(checked, 20);
  EXPECT_LT(worst, 1e-9);

  // And the body's nodes: sum_i t A_i a_ik = t int N_k dA where every
  // contact facet of node k has its nodes paired (a node-to-node pair
  // beside a mortar pair would take the shared facets' load twice).
  std::map<std::int64_t, double> body_load;
  local.clear();
  for (const rollcheck::fem::NodePair& pair : pairs)
    for (const rollcheck::fem::WeightedBlock& w : pair.upper)
      local.insert(local.end(), {static_cast<double>(w.block), pair.area_m2 * w.weight});
  const std::vector<double> body_loads = rollcheck::fem::all_gather(MPI_COMM_WORLD, local);
  for (std::size_t i = 0; i < body_loads.size(); i += 2)
    body_load[static_cast<std::int64_t>(body_loads[i])] += body_loads[i + 1];
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
    const double area = 0.5 * std::abs((q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0]));
    // Every node paired: node to node on the interface, or by the mortar.
    auto paired = [&](const double* v) { return std::abs(v[2]) < tol || mortar_zone(v); };
    const bool zone = paired(p) && paired(q) && paired(r);
    for (std::int32_t d : dofs)
    {
      const std::int64_t g = d < owned ? first + d : map->ghosts()[d - owned];
      local.insert(local.end(), {static_cast<double>(g), area / 3, zone ? 1.0 : 0.0});
    }
  }
  consistent.clear();
  const std::vector<double> body_shares = rollcheck::fem::all_gather(MPI_COMM_WORLD, local);
  for (std::size_t i = 0; i < body_shares.size(); i += 3)
  {
    auto [it, added] = consistent.try_emplace(static_cast<std::int64_t>(body_shares[i]), 0.0, true);
    it->second.first += body_shares[i + 1];
    it->second.second = it->second.second && body_shares[i + 2] > 0;
  }
  int body_checked = 0;
  double body_worst = 0;
  for (const auto& [block, c] : consistent)
  {
    if (!c.second)
      continue;
    ++body_checked;
    const auto it = body_load.find(block);
    body_worst = std::max(body_worst, std::abs((it == body_load.end() ? 0.0 : it->second) / c.first - 1));
  }
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
