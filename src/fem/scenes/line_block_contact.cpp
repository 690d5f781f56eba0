#include "fem/scenes/line_block_contact.h"
#include "contact/hertz.h"
#include "core/error.h"
#include "fem/all_gather.h"
#include "fem/contact_measures.h"
#include "fem/scenes/hertz_setup.h"
#include "fem/load_control.h"
#include "fem/penalty_contact.h"
#include "fem/petsc_session.h"
#include "fem/mesh/scene_mesh.h"
#include <chrono>
#include <spdlog/spdlog.h>
#include <cmath>

namespace rollcheck::fem
{
LineBlockResult solve_line_block(MPI_Comm comm, const LineBlockSettings& s)
{
  const auto start = std::chrono::steady_clock::now();
  ensure_petsc();
  LineBlockResult r;
  const double E_star = contact::effective_modulus(s.youngs_modulus_pa, s.poisson_ratio, true);
  const contact::LineHertz hertz = contact::line_contact(s.load_n_per_m, s.radius_m, E_star, s.poisson_ratio);
  r.hertz_half_width_m = hertz.half_width_m;
  r.hertz_peak_pressure_pa = hertz.peak_pressure_pa;
  const double b = hertz.half_width_m, W = s.size_over_half_width * b, h_c = b / s.contact_elements;
  const SceneMesh scene = build_line_block_mesh(comm, W, contact_grading(b, h_c, W));
  PenaltyContact problem(scene, Model::plane_strain, 1, s.youngs_modulus_pa, s.poisson_ratio,
                         s.penalty_c * s.youngs_modulus_pa / h_c, "");
  problem.set_penalty_scale([](const double*) { return 0.0; }); // no rigid plane
  problem.set_approach_profile([](const double* x) { return x[1] > 0 ? 1.0 : 0.0; });
  std::vector<NodePair> pairs
      = interface_node_pairs(problem, 1e-9 * W, [&](const double* x) { return x[0] * x[0] / (2 * s.radius_m); });
  for (NodePair& pair : pairs)
    pair.stiffness_pa_per_m = s.penalty_c * s.youngs_modulus_pa / h_c;
  problem.set_node_pairs(std::move(pairs));
  r.pairs = static_cast<int>(gather_pair_pressures(problem).size());
  r.dofs = problem.num_dofs();
  // Start: the profile's height at b as the shift, plus a line contact's approach.
  const double shift = 0.5 * b * b / s.radius_m;
  const LineApproach line = line_contact_approach(s.load_n_per_m, W, b, E_star);
  // The force the pairs carry (both bodies' faces are "top" faces, whose
  // reactions cancel), both halves.
  auto pair_force = [&] {
    double force = 0;
    for (const PairPressure& pair : gather_pair_pressures(problem))
      force += pair.pressure_pa * pair.area_m2;
    return force * scene.symmetry_multiplicity;
  };
  const LoadControlReport load = reach_force(problem, s.load_n_per_m, shift + line.approach_m, shift, line.exponent,
                                             1e-6, spdlog::level::debug, pair_force);
  r.force_n_per_m = load.force;
  std::vector<SurfaceNode> nodes;
  double peak = 0;
  for (const PairPressure& pair : gather_pair_pressures(problem))
  {
    nodes.push_back({pair.x[0], pair.pressure_pa, 0.0});
    peak = std::max(peak, pair.pressure_pa);
  }
  const ProfileFit fit = fit_hertz_profile(nodes, peak);
  if (fit.nodes_used < 2)
    throw ComputationError("line block: too few loaded pairs to fit the Hertz profile");
  r.half_width_m = fit.contact_size_m;
  r.peak_pressure_pa = fit.peak_pressure_pa;
  r.wall_s = wall_seconds_since(comm, start);
  return r;
}
} // namespace rollcheck::fem
