// The whole body on the rigid plane under F through its centre of mass
// (fem/scenes/whole_body_contact.h): load control on approach and tilt, reading by
// node planes.
#include "fem/scenes/whole_body_contact.h"
#include "core/error.h"
#include "fem/all_gather.h"
#include "fem/nodal_fields.h"
#include "fem/penalty_contact.h"
#include "fem/petsc_session.h"
#include <algorithm>
#include <chrono>
#include <cmath>
#include <span>
#include <fmt/format.h>
#include <spdlog/spdlog.h>

namespace rollcheck::fem
{
namespace
{
constexpr int max_solves = 30;

/// Force, centre of pressure and the surface nodes of the current state.
struct Reading
{
  double reaction_n = 0;
  double centre_m = 0;
  std::vector<SurfacePressureNode> nodes;
};

Reading read_state(MPI_Comm comm, const PenaltyContact& problem)
{
  Reading r;
  r.reaction_n = problem.reaction_force_n();
  r.nodes = gather_surface_pressure(comm, recover_contact_pressure(problem));
  double moment = 0, total = 0;
  for (const SurfacePressureNode& n : r.nodes)
  {
    moment += n.x[0] * n.pressure_pa * n.weight;
    total += n.pressure_pa * n.weight;
  }
  if (!(total > 0))
    throw ComputationError(fmt::format("whole body: no contact pressure at approach {:.6e} m", problem.approach_m()));
  r.centre_m = moment / total;
  return r;
}

/// InputError unless F > 0, x_G lies inside the ruling and the sizes,
/// first approach and penalty are positive.
void check_load(const WholeBodyMesh& mesh, const WholeBodyLoad& load)
{
  const double L = mesh.length_m, x_G = load.centre_of_mass_along_m, F = load.force_n;
  if (!(F > 0) || !(x_G > 0 && x_G < L) || !(load.contact_element_m > 0) || !(load.first_approach_m > 0)
      || !(load.edge_half_width_m > 0) || !(load.penalty_c > 0))
    throw InputError(fmt::format("whole body: need F > 0 ({} N), the centre of mass's foot inside the ruling "
                                 "(x_G = {} m of L = {} m), and positive contact element ({} m), first approach "
                                 "({} m), edge half-width ({} m) and penalty c ({})",
                                 F, x_G, L, load.contact_element_m, load.first_approach_m, load.edge_half_width_m,
                                 load.penalty_c));
}

/// Load control (the header's): solves at approach delta and tilt
/// parameter tau until the force is F and the centre of pressure x_G, delta
/// by the secant on log F - log delta, tau by the secant on x_c - tau. Sets
/// result's approach, tilt, load steps and iteration counts; returns the
/// last reading. ComputationError when it does not converge in max_solves.
Reading control_load(MPI_Comm comm, PenaltyContact& problem, const WholeBodyLoad& load, double L,
                     WholeBodyFem& result)
{
  const double x_G = load.centre_of_mass_along_m, F = load.force_n;
  const bool log = world_rank() == 0;
  double tau = 0, delta = load.first_approach_m;
  auto set_profile = [&](double t) {
    problem.set_approach_profile([t, x_G, L](const double* x) { return 1 + t * (x[0] - x_G) / L; });
  };
  set_profile(tau);
  problem.start_translated(load.first_shift_m, delta);
  double exponent = load.approach_exponent;
  double slope = exponent * L / 12; // d x_c / d tau
  double previous_delta = 0, previous_force = 0, previous_tau = 0, previous_centre = 0;
  for (int solve = 1; solve <= max_solves; ++solve)
  {
    const NewtonReport newton = problem.solve();
    result.newton_iterations += newton.newton_iterations;
    result.krylov_iterations += newton.krylov_iterations;
    result.load_steps = solve;
    Reading reading = read_state(comm, problem);
    const double force = reading.reaction_n, centre = reading.centre_m;
    if (log)
      spdlog::info("whole body step {}: approach {:.9e} m, tilt {:.4e} rad, force {:.6g} of {:.6g} N, centre of "
                   "pressure {:.6f} L (centre of mass {:.6f} L), {} Newton iterations",
                   solve, delta, delta * tau / L, force, F, centre / L, x_G / L, newton.newton_iterations);
    if (!(force > 0))
      throw ComputationError(fmt::format("whole body: no reaction at approach {:.6e} m", delta));
    if (std::abs(force / F - 1) <= load.force_rtol && std::abs(centre - x_G) <= load.centre_rtol * L)
    {
      result.approach_m = delta;
      result.tilt_rad = delta * tau / L;
      return reading;
    }
    if (solve > 1 && delta != previous_delta && force != previous_force)
      exponent = std::clamp(std::log(force / previous_force) / std::log(delta / previous_delta), 0.5, 3.0);
    if (solve > 1 && tau != previous_tau && centre != previous_centre)
    {
      const double secant = (centre - previous_centre) / (tau - previous_tau);
      if (secant > 0)
        slope = secant;
    }
    previous_delta = delta;
    previous_force = force;
    previous_tau = tau;
    previous_centre = centre;
    delta *= std::pow(F / force, 1.0 / exponent);
    if (std::abs(centre - x_G) > load.centre_rtol * L)
      tau += (x_G - centre) / slope;
    set_profile(tau);
    problem.set_approach(delta);
  }
  throw ComputationError(fmt::format("whole body: load control did not reach F = {:.6g} N to {:.1e} with the "
                                     "centre of pressure at x_G to {:.1e} L in {} solves",
                                     F, load.force_rtol, load.centre_rtol, max_solves));
}

/// The reading by node plane: the nodes lie on the planes of the structured
/// layers (at their position along the ruling, where the layers are
/// sheared). Each plane's peak and line load q = sum p_i A_i / dx, and at
/// both end planes the mean pressure of the sheet's nodes with |y| <=
/// edge_half_width_m. ComputationError for a node on no plane or an end
/// plane without such a node.
void read_node_planes(const WholeBodyMesh& mesh, std::span<const SurfacePressureNode> nodes,
                      double edge_half_width_m, WholeBodyFem& result)
{
  const std::vector<double>& planes = mesh.planes_m;
  const std::size_t n = planes.size();
  result.plane_x_m = planes;
  result.plane_peak_pa.assign(n, 0.0);
  result.plane_load_n_per_m.assign(n, 0.0);
  std::array<double, 2> edge_sum{}, edge_count{};
  const double same_plane = 1e-6 * (planes[1] - planes[0]);
  for (const SurfacePressureNode& node : nodes)
  {
    const double a = mesh.along(node.x.data());
    const std::size_t k = std::lower_bound(planes.begin(), planes.end(), a - same_plane) - planes.begin();
    if (k >= n || std::abs(planes[k] - a) > same_plane)
      throw ComputationError(fmt::format("whole body: a contact node at x = {:.9g} m (a = {:.9g} m along the ruling) "
                                         "lies on no node plane",
                                         node.x[0], a));
    result.plane_peak_pa[k] = std::max(result.plane_peak_pa[k], node.pressure_pa);
    result.plane_load_n_per_m[k] += node.pressure_pa * node.weight;
    if ((k == 0 || k == n - 1) && std::abs(node.x[1]) <= edge_half_width_m && mesh.on_sheet(node.x.data()))
    {
      edge_sum[k == 0 ? 0 : 1] += node.pressure_pa;
      edge_count[k == 0 ? 0 : 1] += 1;
    }
  }
  for (std::size_t k = 0; k < n; ++k)
  {
    const double dx = 0.5 * (planes[std::min(k + 1, n - 1)] - planes[k == 0 ? 0 : k - 1]);
    result.plane_load_n_per_m[k] /= dx;
  }
  for (int e = 0; e < 2; ++e)
  {
    if (edge_count[e] == 0)
      throw ComputationError("whole body: no contact node within the edge half-width at an end plane");
    result.edge_pressure_pa[e] = edge_sum[e] / edge_count[e];
  }
}
} // namespace

double interpolate_planes(const std::vector<double>& xs, const std::vector<double>& ys, double x)
{
  if (xs.empty())
    return 0;
  if (x <= xs.front())
    return ys.front();
  if (x >= xs.back())
    return ys.back();
  const std::size_t i = std::upper_bound(xs.begin(), xs.end(), x) - xs.begin();
  const double t = (x - xs[i - 1]) / (xs[i] - xs[i - 1]);
  return ys[i - 1] + t * (ys[i] - ys[i - 1]);
}

WholeBodyFem solve_whole_body(MPI_Comm comm, const WholeBodyMesh& mesh, const WholeBodyLoad& load)
{
  const auto start = std::chrono::steady_clock::now();
  check_load(mesh, load);
  ensure_petsc();
  const double kappa = load.penalty_c * load.youngs_modulus_pa / load.contact_element_m;
  PenaltyContact problem(mesh.scene, Model::solid, 1, load.youngs_modulus_pa, load.poisson_ratio, kappa,
                         load.petsc_options);
  if (mesh.initial_gap)
    problem.set_initial_gap(mesh.initial_gap);
  WholeBodyFem result;
  result.dofs = problem.num_dofs();
  if (world_rank() == 0)
    spdlog::info("whole body: L = {:.4g} m, {} node planes, {} DOFs, kappa = {:.3g} Pa/m", mesh.length_m,
                 mesh.planes_m.size(), result.dofs, kappa);
  const Reading reading = control_load(comm, problem, load, mesh.length_m, result);
  result.reaction_n = reading.reaction_n;
  result.force_n = problem.contact_force_n();
  result.centre_of_pressure_m = reading.centre_m;
  read_node_planes(mesh, reading.nodes, load.edge_half_width_m, result);
  result.solve_s = wall_seconds_since(comm, start);
  return result;
}
} // namespace rollcheck::fem
