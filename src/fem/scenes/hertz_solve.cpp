#include "fem/scenes/hertz_solve.h"
#include "core/seconds_since.h"
#include "contact/hertz.h"
#include "fem/all_gather.h"
#include "fem/consistent_pressure.h"
#include "fem/load_control.h"
#include "fem/nodal_fields.h"
#include "fem/penalty_pressure.h"
#include "fem/petsc_session.h"
#include "fem/mesh/scene_mesh.h"
#include "fem/write_fields.h"
#include "core/error.h"
#include <chrono>
#include <cmath>
#include <fmt/format.h>
#include <numbers>
#include <optional>
#include <set>
#include <spdlog/spdlog.h>
#include <sys/resource.h>

namespace rollcheck::fem
{
namespace
{
using Clock = std::chrono::steady_clock;

void flag(HertzResult& result, const std::string& name, const std::string& warning, int rank)
{
  result.flags.push_back(name);
  // A loop solves hundreds of slices and table nodes alike: each kind of
  // warning once per process, the first one's text (the result carries its
  // flags). Processes solve alone (MPI_COMM_SELF slices) or together, never
  // in threads.
  static std::set<std::string> warned;
  if (rank == 0 && warned.insert(name).second)
    spdlog::warn("{}", warning);
}
/// The result's setup, Hertz reference and mesh grading, and the flags the
/// setup alone raises.
HertzResult start_result(MPI_Comm comm, const HertzSettings& setup, int rank)
{
  HertzResult result;
  MPI_Comm_size(comm, &result.ranks);
  result.setup = setup;
  result.hertz = hertz_reference(setup);
  result.grading = mesh_grading(setup, result.hertz);
  const double c_H = result.hertz.contact_size_m;
  result.elements_across_contact = c_H / result.grading.contact_size_m;
  if (setup.elastic_plane)
    flag(result, "elastic_plane",
         "--elastic-plane: compared with the E* of two identical bodies, E / (2 (1 - nu^2)); the FEM body gets "
         "E / 2 against the rigid plane (Hertz-equivalent for identical materials)",
         rank);
  if (result.elements_across_contact < 3)
    flag(result, "mesh_coarser_than_contact",
         fmt::format("the contact-zone elements ({:.3g} m) are coarse against the Hertz contact size {:.3g} m "
                     "({:.2g} elements across): the contact is not resolved and the comparison is not a verification",
                     result.grading.contact_size_m, c_H, result.elements_across_contact),
         rank);
  if (setup.degree == 1 && setup.poisson_ratio > 0.45)
    flag(result, "volumetric_locking",
         fmt::format("nu = {} with P1 elements: linear triangles and tetrahedra lock as nu -> 1/2 and the body "
                     "comes out too stiff; use --degree 2",
                     setup.poisson_ratio),
         rank);
  return result;
}

/// The penalty stiffness kappa = c E / h_c.
double penalty_stiffness(const HertzResult& result)
{
  return result.setup.penalty_c * result.hertz.body_modulus_pa / result.grading.contact_size_m;
}

/// The nodal fields, the contact pressure by the setup's recovery.
NodalFields hertz_fields(const PenaltyContact& problem, PressureRecovery recovery)
{
  NodalFields fields = recover_nodal_fields(problem);
  auto& pressure = static_cast<ContactPressure&>(fields);
  if (recovery == PressureRecovery::consistent)
    pressure = consistent_contact_pressure(problem);
  if (recovery == PressureRecovery::penalty)
    pressure = penalty_nodal_pressure(problem);
  if (recovery == PressureRecovery::touching)
    pressure = touching_lumped_pressure(problem);
  return fields;
}

/// The scene's mesh, graded towards the contact.
SceneMesh mesh_hertz_scene(MPI_Comm comm, HertzResult& result, spdlog::level::level_enum progress, int rank)
{
  const HertzSettings& setup = result.setup;
  if (rank == 0)
    spdlog::log(progress, "hertz {} P{}: meshing with gmsh (h_c = {:.4g} m)", model_name(setup.model), setup.degree,
                result.grading.contact_size_m);
  SceneMesh scene = build_scene_mesh(comm, setup.model, setup.radius_m, result.grading,
                                     contact_refinement(setup, result.hertz, result.grading));
  result.mesh_s = scene.wall_s;
  result.cells = scene.mesh->topology().index_map(scene.mesh->topology().dim())->size_global();
  return scene;
}

/// Load control to the Hertz load. Start: the Hertz approach, the body
/// shifted by the height of its surface at the Hertz contact edge, so that
/// the first active set is the Hertz contact; a line contact starts from the
/// classical approach of a cylinder's centre (line_contact_approach). Both
/// only start the load control, which corrects them.
/// `series` (if any) receives the fields of every load step.
void reach_hertz_load(PenaltyContact& problem, HertzResult& result, spdlog::level::level_enum progress, int rank,
                      FieldSeries* series)
{
  const HertzSettings& setup = result.setup;
  const HertzReference& ref = result.hertz;
  const bool line = setup.model == Model::plane_strain;
  const double R = setup.radius_m, c_H = ref.contact_size_m;
  const double edge_height = c_H * c_H / (2 * R);
  const LineApproach line_start = line_contact_approach(ref.load, R, c_H, ref.effective_modulus_pa);
  const double first_approach = line ? line_start.approach_m : *ref.approach_m;
  const double exponent = line ? line_start.exponent : 1.5;
  if (rank == 0)
    spdlog::log(progress, "hertz {} P{}: load control to {:.6g} {} (Newton iterations with -v)", model_name(setup.model),
                setup.degree, ref.load, line ? "N/m" : "N");
  int step = 0;
  const auto write_step = [&](double) { series->write(hertz_fields(problem, setup.pressure_recovery), ++step); };
  const LoadControlReport load = reach_force(problem, ref.load, first_approach, edge_height, exponent,
                                             setup.force_rtol, rank == 0 ? progress : spdlog::level::debug, {},
                                             series ? std::function<void(double)>(write_step) : nullptr);
  result.load_steps = load.load_steps;
  result.newton_iterations = load.newton.newton_iterations;
  result.krylov_iterations = load.newton.krylov_iterations;
  result.preconditioner_setups = load.newton.preconditioner_setups;
  result.assembly_s = load.newton.assembly_s;
  result.solve_s = load.newton.solve_s;
  result.approach_m = load.approach_m;
  result.load_reaction = load.force;
  result.load_contact = problem.contact_force_n();
}

/// Every rank's contact-surface nodes (s, pressure, gap) and the nodes within
/// two contact-zone elements of the axis (depth, s, max shear, von Mises),
/// whose fits give the subsurface maxima (contact_measures.h).
struct GatheredNodes
{
  std::vector<double> surface, axis;
};

GatheredNodes gather_surface_and_axis(MPI_Comm comm, const NodalFields& fields, const HertzResult& result)
{
  const Model model = result.setup.model;
  const std::vector<double> xq = fields.pressure->function_space()->tabulate_dof_coordinates(false);
  const int zi = model == Model::solid ? 2 : 1;
  const int gdim = zi + 1;
  std::span<const double> p = fields.pressure->x()->array();
  std::span<const double> u1 = fields.displacement->x()->array();
  std::span<const double> tau = fields.max_shear->x()->array();
  std::span<const double> vm = fields.von_mises->x()->array();
  std::vector<double> surface_local, axis_local;
  const double near_axis = 2 * result.grading.contact_size_m;
  for (std::size_t i = 0; i < fields.contact_weight.size(); ++i)
  {
    const double* x = &xq[3 * i];
    const double s = model == Model::solid ? std::hypot(x[0], x[1]) : std::abs(x[0]);
    if (fields.contact_weight[i] > 0)
      surface_local.insert(surface_local.end(), {s, p[i], x[zi] + u1[gdim * i + zi]});
    if (s < near_axis)
      axis_local.insert(axis_local.end(), {x[zi], s, tau[i], vm[i]});
  }
  return {all_gather(comm, surface_local), all_gather(comm, axis_local)};
}

/// Contact size, peak pressure, contact edge and the pressure profile against
/// Hertz's, from the surface nodes. ComputationError where the mesh does not
/// resolve the contact.
void measure_contact(const std::vector<double>& surface, HertzResult& result)
{
  const HertzReference& ref = result.hertz;
  const double c_H = ref.contact_size_m, h_c = result.grading.contact_size_m;
  std::vector<SurfaceNode> nodes;
  for (std::size_t i = 0; i < surface.size(); i += 3)
  {
    nodes.push_back({surface[i], surface[i + 1], surface[i + 2]});
    result.max_nodal_pressure_pa = std::max(result.max_nodal_pressure_pa, surface[i + 1]);
    result.touching_nodes += surface[i + 2] < 0;
  }
  if (result.touching_nodes < 2)
    throw ComputationError(fmt::format(
        "unresolved contact: only {} surface node(s) touch the plane (contact-zone element {:.3g} m against a "
        "Hertz contact size of {:.3g} m); refine the mesh or raise the load",
        result.touching_nodes, h_c, c_H));
  const ProfileFit fit = fit_hertz_profile(nodes, result.max_nodal_pressure_pa);
  if (fit.nodes_used < 2)
    throw ComputationError(fmt::format("unresolved contact: fewer than two nodes carry half the peak pressure "
                                       "(contact-zone element {:.3g} m, Hertz contact size {:.3g} m)",
                                       h_c, c_H));
  result.contact_size_m = fit.contact_size_m;
  result.peak_pressure_pa = fit.peak_pressure_pa;
  result.contact_edge_m = contact_edge(nodes);

  std::sort(nodes.begin(), nodes.end(), [](const auto& a, const auto& b) { return a.s < b.s; });
  double squares = 0, interior_squares = 0;
  std::size_t interior = 0;
  for (const SurfaceNode& node : nodes)
    if (node.s < 1.5 * c_H)
    {
      result.profile.push_back(node);
      const double d = (node.pressure - contact::pressure_profile(ref.peak_pressure_pa, c_H, node.s)) / ref.peak_pressure_pa;
      squares += d * d;
      if (node.s < 0.9 * c_H)
      {
        interior_squares += d * d;
        ++interior;
      }
    }
  result.profile_rms_error = std::sqrt(squares / std::max<std::size_t>(1, result.profile.size()));
  result.profile_rms_error_interior = std::sqrt(interior_squares / std::max<std::size_t>(1, interior));
}

/// The largest maximum shear and von Mises stress on the axis and their
/// depths, from the nodes near it.
void measure_axis_maxima(const std::vector<double>& axis, HertzResult& result)
{
  std::vector<AxisNode> shear_axis, mises_axis;
  for (std::size_t i = 0; i < axis.size(); i += 4)
  {
    shear_axis.push_back({axis[i], axis[i + 1], axis[i + 2]});
    mises_axis.push_back({axis[i], axis[i + 1], axis[i + 3]});
  }
  const double axis_tol = 1e-9 * result.setup.radius_m;
  result.max_shear = maximum_along_axis(shear_axis, axis_tol);
  result.max_von_mises = maximum_along_axis(mises_axis, axis_tol);
}

/// Error estimates, calibrated by the penalty and convergence studies
/// (README): the penalty adds a compliant layer whose penetration p0 / kappa,
/// against the approach c^2 / R, lowers p0 by about half that ratio; the
/// mesh error of a and p0 is of the order (h_c / c)^2. Flags where the
/// penalty's dominates or the contact leaves Hertz's small-strain range.
void estimate_errors(HertzResult& result, int rank)
{
  const HertzSettings& setup = result.setup;
  const double R = setup.radius_m, c_H = result.hertz.contact_size_m;
  const double c = result.contact_size_m;
  result.penalty_error_estimate = result.peak_pressure_pa / penalty_stiffness(result) * R / (c * c);
  result.discretisation_error_estimate = std::pow(result.grading.contact_size_m / c, 2);
  if (result.penalty_error_estimate > result.discretisation_error_estimate)
    flag(result, "penalty_error_dominates",
         fmt::format("penalty c = {}: its estimated error {:.2e} exceeds the mesh's {:.2e}; raise --penalty-c",
                     setup.penalty_c, result.penalty_error_estimate, result.discretisation_error_estimate),
         rank);
  if (std::max(c, c_H) / R > 0.1)
    flag(result, "small_strain_range_exceeded",
         fmt::format("contact size / radius = {:.3g} > 0.1: beyond Hertz's small-strain, half-space assumptions",
                     std::max(c, c_H) / R),
         rank);
}

/// The largest resident set of one rank and the sum over ranks.
void record_peak_memory(MPI_Comm comm, HertzResult& result)
{
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  const double rss_mb = usage.ru_maxrss / 1024.0;
  MPI_Allreduce(&rss_mb, &result.peak_memory_mb, 1, MPI_DOUBLE, MPI_MAX, comm);
  MPI_Allreduce(&rss_mb, &result.total_peak_memory_mb, 1, MPI_DOUBLE, MPI_SUM, comm);
}
} // namespace

HertzResult solve_hertz(MPI_Comm comm, const HertzSettings& given)
{
  const auto start = Clock::now();
  const HertzSettings setup = with_model_defaults(given);
  validate(setup);
  ensure_petsc();
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  HertzResult result = start_result(comm, setup, rank);

  // Mesh and problem. Progress lines mark the long steps (3D: seconds each).
  // Slices of a loop solve hundreds of these: their progress goes to -v.
  const auto progress = setup.log_progress ? spdlog::level::info : spdlog::level::debug;
  const SceneMesh scene = mesh_hertz_scene(comm, result, progress, rank);
  const double kappa = penalty_stiffness(result);
  PenaltyContact problem(scene, setup.model, setup.degree, result.hertz.body_modulus_pa, setup.poisson_ratio, kappa,
                         setup.petsc_options);
  problem.reuse_preconditioner_within_solve(setup.model == Model::solid && setup.reuse_preconditioner);
  result.dofs = problem.num_dofs();
  if (rank == 0)
    spdlog::log(progress, "hertz {} P{}: {} cells, {} dofs, h_c = {:.4g} m ({:.3g} per {}), kappa = {:.4g} Pa/m",
                model_name(setup.model), setup.degree, result.cells, result.dofs, result.grading.contact_size_m,
                result.elements_across_contact, setup.model == Model::plane_strain ? "b" : "a", kappa);
  std::optional<FieldSeries> series;
  if (!setup.xdmf_path.empty())
    series.emplace(comm, setup.xdmf_path);
  reach_hertz_load(problem, result, progress, rank, series ? &*series : nullptr);

  // Post-processing against Hertz, then the fields.
  const auto post_start = Clock::now();
  const NodalFields fields = hertz_fields(problem, setup.pressure_recovery);
  const GatheredNodes gathered = gather_surface_and_axis(comm, fields, result);
  measure_contact(gathered.surface, result);
  measure_axis_maxima(gathered.axis, result);
  estimate_errors(result, rank);
  if (series)
    series->close();
  result.postprocess_s = seconds_since(post_start);

  record_peak_memory(comm, result);
  result.wall_s = wall_seconds_since(comm, start);
  return result;
}
} // namespace rollcheck::fem
