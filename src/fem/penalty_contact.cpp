#include "fem/penalty_contact.h"
#include "core/seconds_since.h"
#include "core/error.h"
#include "fem/all_gather.h"
#include "fem/interpolate_between_meshes.h"
#include "fem/solver_defaults.h"
#include <algorithm>
#include <string>
#include <chrono>
#include <map>
#include <cmath>
#include <dolfinx/fem/assembler.h>
#include <dolfinx/fem/petsc.h>
#include <dolfinx/fem/sparsitybuild.h>
#include <dolfinx/la/SparsityPattern.h>
#include <dolfinx/fem/utils.h>
#include <dolfinx/la/petsc.h>
#include <dolfinx/mesh/MeshTags.h>
#include <fmt/format.h>
#include <spdlog/spdlog.h>
#include <unordered_map>
#include <xtensor/xarray.hpp>
#include <xtensor/xtensor.hpp>

namespace rollcheck::fem
{
namespace
{
using T = PenaltyContact::T;
using Clock = std::chrono::steady_clock;
constexpr int max_newton_iterations = 40;
constexpr double newton_rtol = 1e-10;  ///< on ||du|| / ||u||, or what the linear solve resolves (increment_tolerance)
constexpr double converged_residual = 1e-8; ///< ||F|| over the solve's largest after a full step
constexpr int max_line_search_halvings = 12;

/// The smallest Newton increment, relative to u, that the linear solve
/// resolves: newton_rtol, or ten times an iterative solve's relative
/// tolerance where that is looser. Below it an increment is the Krylov
/// solve's own error (1.0-1.2 times its rtol on the 3D P2 hemisphere), which
/// no Newton step removes: with -hertz_ksp_rtol 1e-8 against a fixed 1e-10
/// the line search halved such increments to 1/64 forty times and Newton
/// failed.
double increment_tolerance(KSP ksp)
{
  if (is_direct(ksp))
    return newton_rtol;
  PetscReal rtol = 0, abstol = 0, dtol = 0;
  PetscInt max_its = 0;
  KSPGetTolerances(ksp, &rtol, &abstol, &dtol, &max_its);
  return std::max(newton_rtol, 10 * rtol);
}

/// reuse_preconditioner_within_solve's state over one solve(): the first
/// Newton step's preconditioner and Krylov iterations, kept while the later
/// steps stay within twice those.
struct KeptPreconditioner
{
  bool managed = false; ///< this solve sets the KSP's reuse flag
  bool reuse = false;   ///< the later steps still keep the first's preconditioner
  PetscInt first_iterations = 0;
};

/// A direct solve's factors must follow the matrix, and a
/// -hertz_ksp_reuse_preconditioner given is the user's to keep.
KeptPreconditioner keep_preconditioner(KSP ksp, bool asked)
{
  const bool managed = asked && !solver_option_given("-ksp_reuse_preconditioner") && !is_direct(ksp);
  return {managed, managed, 0};
}

struct LinearStep
{
  KSPConvergedReason reason = KSP_CONVERGED_ITERATING;
  PetscInt iterations = 0;     ///< of the solve whose increment is taken
  PetscInt all_iterations = 0; ///< with those of a kept preconditioner's solve that gave up
  int setups = 0;              ///< preconditioners built afresh
};

/// Whether the Krylov solve's stop follows the problem's load scale (see
/// PenaltyContact::solve): an iterative solve whose -hertz_ksp_atol is not given.
bool scales_absolute_tolerance(KSP ksp)
{
  return !solver_option_given("-ksp_atol") && !is_direct(ksp);
}

/// The KSP stops once its residual is below rtol times its own initial
/// residual or min(rtol, newton_rtol) times `reference`, whichever is larger:
/// the load's scale at the Newton tolerance, not at a looser rtol (with
/// -hertz_ksp_rtol 1e-6 a load step's first correction, below 1e-6 of the
/// load's scale, was taken as zero and load control never met its force).
void set_absolute_tolerance(KSP ksp, double reference)
{
  PetscReal rtol = 0, abstol = 0, dtol = 0;
  PetscInt max_its = 0;
  KSPGetTolerances(ksp, &rtol, &abstol, &dtol, &max_its);
  KSPSetTolerances(ksp, rtol, std::max(std::min<double>(rtol, newton_rtol) * reference, 1e-50), dtol, max_its);
}

/// The last Krylov solve's initial residual, in the norm its convergence
/// test uses (preconditioned for left-preconditioned GMRES), from its
/// history; 0 if it logged none.
double initial_residual_norm(KSP ksp)
{
  const PetscReal* history = nullptr;
  PetscInt length = 0;
  KSPGetResidualHistory(ksp, &history, &length);
  return length > 0 ? history[0] : 0.0;
}

/// One Newton step's linear solve, du = J^-1 b, keeping the first step's
/// preconditioner as `kept` says.
LinearStep solve_step(KSP ksp, Vec b, Vec du, bool first, KeptPreconditioner& kept)
{
  const bool reused = kept.reuse && !first;
  if (kept.managed)
    KSPSetReusePreconditioner(ksp, reused ? PETSC_TRUE : PETSC_FALSE);
  LinearStep step;
  const auto solve = [&] {
    VecZeroEntries(du);
    solve_linear(ksp, b, du);
    KSPGetConvergedReason(ksp, &step.reason);
    KSPGetIterationNumber(ksp, &step.iterations);
    step.all_iterations += step.iterations;
  };
  solve();
  step.setups = reused ? 0 : 1;
  if (reused && (step.reason < 0 || step.iterations > 2 * kept.first_iterations))
  {
    // The kept preconditioner no longer fits: a fresh one from here on (and
    // for this step, if the kept one gave up: PCApply sets it up again, the
    // operator having changed since).
    kept.reuse = false;
    KSPSetReusePreconditioner(ksp, PETSC_FALSE);
    if (step.reason < 0)
    {
      solve();
      step.setups = 1;
    }
  }
  if (first)
    kept.first_iterations = step.iterations;
  return step;
}

/// f's values at the points of a scalar space (DG0: cell midpoints, P1: vertices).
void interpolate_scalar(dolfinx::fem::Function<double>& f, const std::function<double(const double* x)>& value)
{
  f.interpolate([&](const xt::xtensor<double, 2>& x) -> xt::xarray<double> {
    xt::xtensor<double, 1> values = xt::empty<double>({x.shape(1)});
    for (std::size_t i = 0; i < x.shape(1); ++i)
    {
      const double point[3] = {x(0, i), x(1, i), x(2, i)};
      values(i) = value(point);
    }
    return values;
  });
}
} // namespace

PenaltyContact::PenaltyContact(const SceneMesh& scene, Model model, int degree, double body_modulus_pa,
                               double poisson_ratio, double penalty_stiffness, const std::string& petsc_options)
    : _scene(scene), _forms(contact_forms(model, degree))
{
  namespace dfem = dolfinx::fem;
  const auto& mesh = _scene.mesh;
  const int tdim = mesh->topology().dim();
  const int fdim = tdim - 1;
  _z_component = model == Model::solid ? 2 : 1;

  _V = std::make_shared<dfem::FunctionSpace>(dfem::create_functionspace(_forms.displacement_space, "v_0", mesh));
  _u = std::make_shared<dfem::Function<T>>(_V);
  _u->name = "displacement";
  _dof_coordinates = _V->tabulate_dof_coordinates(false);

  const std::string& s = _forms.suffix;
  _constants = {{"youngs_modulus_" + s, std::make_shared<dfem::Constant<T>>(body_modulus_pa)},
                {"poisson_ratio_" + s, std::make_shared<dfem::Constant<T>>(poisson_ratio)},
                {"penalty_stiffness_" + s, std::make_shared<dfem::Constant<T>>(penalty_stiffness)}};
  std::vector<std::int32_t> facets = _scene.contact_facets;
  std::vector<int> values(facets.size(), 1); // CONTACT_SURFACE in forms/hertz.py
  _contact_tags = std::make_shared<dolfinx::mesh::MeshTags<int>>(mesh, fdim, std::move(facets), std::move(values));
  _subdomains = {{dfem::IntegralType::exterior_facet, _contact_tags.get()}};
  // The penalty's cellwise factor (forms/hertz.py), 1 until set_penalty_scale.
  auto Q0 = std::make_shared<dfem::FunctionSpace>(
      dfem::create_functionspace(_forms.displacement_space, ("penalty_scale_" + s).c_str(), mesh));
  _penalty_scale = std::make_shared<dfem::Function<T>>(Q0);
  _penalty_scale->x()->set(1.0);
  _initial_gap = std::make_shared<dfem::Function<T>>(std::make_shared<dfem::FunctionSpace>(
      dfem::create_functionspace(_forms.displacement_space, ("initial_gap_" + s).c_str(), mesh)));
  _coefficients = {{"u_" + s, _u}, {"penalty_scale_" + s, _penalty_scale}, {"initial_gap_" + s, _initial_gap}};
  const auto& coefficients = _coefficients;
  auto make_form = [&](ufcx_form* form, std::vector<std::shared_ptr<const dfem::FunctionSpace>> spaces) {
    return std::make_shared<dfem::Form<T>>(
        dfem::create_form<T>(*form, spaces, coefficients, _constants, _subdomains, mesh));
  };
  _residual = make_form(_forms.residual, {_V});
  _jacobian = make_form(_forms.jacobian, {_V, _V});
  _energy = make_form(_forms.energy, {});
  _contact_force = make_form(_forms.contact_force, {});

  // Dirichlet conditions: symmetry planes (normal component zero), top face
  // (whole displacement prescribed: bonded to a rigid loading plate).
  std::vector<std::pair<const std::vector<std::int32_t>*, int>> planes = {{&_scene.symmetry_x_facets, 0}};
  if (model == Model::solid)
    planes.push_back({&_scene.symmetry_y_facets, 1});
  for (const auto& [plane_facets, component] : planes)
  {
    auto Vc = _V->sub({component});
    std::vector<std::int32_t> dofs = dfem::locate_dofs_topological(*Vc, fdim, *plane_facets);
    _bcs.push_back(std::make_shared<const dfem::DirichletBC<T>>(T(0), std::move(dofs), Vc));
  }
  _top_displacement = std::make_shared<dfem::Function<T>>(_V);
  _top_blocks = dfem::locate_dofs_topological(*_V, fdim, _scene.top_facets);
  _top_weights.assign(_top_blocks.size(), 1.0);
  const std::int32_t owned_blocks = _V->dofmap()->index_map->size_local();
  const int bs = _V->dofmap()->index_map_bs();
  for (std::int32_t b : _top_blocks)
    if (b < owned_blocks)
      _top_z_dofs.push_back(b * bs + _z_component);
  _bcs.push_back(std::make_shared<const dfem::DirichletBC<T>>(
      std::shared_ptr<const dfem::Function<T>>(_top_displacement), _top_blocks));
  _pair_map = _V->dofmap()->index_map;

  // Linear solver.
  _A = dfem::petsc::create_matrix(*_jacobian, "aij");
  _inserted_options = insert_options(petsc_options);
  _near_nullspace = rigid_body_near_nullspace(*_V, model);
  MatSetNearNullSpace(_A, _near_nullspace);
  _model = model;
  _ksp = create_linear_solver(mesh->comm(), model, petsc_options);
  KSPSetResidualHistory(_ksp, nullptr, PETSC_DECIDE, PETSC_TRUE); // each solve's initial residual, for solve()
}

PenaltyContact::~PenaltyContact()
{
  // The setup's options were for this problem only (a study runs many).
  clear_options(_inserted_options);
  KSPDestroy(&_ksp);
  MatNullSpaceDestroy(&_near_nullspace);
  MatDestroy(&_A);
}

std::int64_t PenaltyContact::num_dofs() const
{
  return _V->dofmap()->index_map->size_global() * _V->dofmap()->index_map_bs();
}

void PenaltyContact::prefer_direct_solver(std::int64_t max_dofs)
{
  if (_model == Model::solid && num_dofs() <= max_dofs)
    use_direct_solver_default(_ksp);
}

void PenaltyContact::start_translated(double shift_m, double approach_m)
{
  std::span<T> u = _u->x()->mutable_array();
  const int bs = _V->dofmap()->index_map_bs();
  std::fill(u.begin(), u.end(), 0.0);
  for (std::size_t i = _z_component; i < u.size(); i += bs)
    u[i] = -shift_m;
  set_approach(approach_m);
}

void PenaltyContact::start_interpolated(const dolfinx::fem::Function<T>& solved, double approach_m,
                                        const std::function<int(const double* midpoint)>& part)
{
  const auto start = Clock::now();
  interpolate_between_meshes(solved, *_u, part);
  set_approach(approach_m);
  spdlog::debug("start interpolated from another mesh: {:.2f} s", seconds_since(start));
}

void PenaltyContact::set_approach_profile(const std::function<double(const double* x)>& weight)
{
  const std::vector<double> x = _V->tabulate_dof_coordinates(false);
  for (std::size_t i = 0; i < _top_blocks.size(); ++i)
    _top_weights[i] = weight(&x[3 * _top_blocks[i]]);
}

void PenaltyContact::set_approach(double approach_m)
{
  // The top face is bonded to the loading plate: its horizontal displacement is zero.
  _approach_m = approach_m;
  std::span<T> g = _top_displacement->x()->mutable_array();
  const int bs = _V->dofmap()->index_map_bs();
  for (std::size_t i = 0; i < _top_blocks.size(); ++i)
    g[_top_blocks[i] * bs + _z_component] = -approach_m * _top_weights[i];
  std::span<T> u = _u->x()->mutable_array();
  dolfinx::fem::set_bc(u, _bcs, 1.0);
  _u->x()->scatter_fwd();
}

void PenaltyContact::assemble_residual(dolfinx::la::Vector<T>& b) const
{
  std::span<T> array = b.mutable_array();
  std::fill(array.begin(), array.end(), 0.0);
  dolfinx::fem::assemble_vector<T>(array, *_residual);
  add_pair_forces(array);
  b.scatter_rev(std::plus<T>());
  // The state satisfies the Dirichlet conditions, so the increment is zero
  // there (b may be longer than u by the pairs' extra ghosts).
  std::span<const T> u = _u->x()->array();
  dolfinx::fem::set_bc<T>(array.first(u.size()), _bcs, u, -1.0);
}

void PenaltyContact::add_pair_forces(std::span<T> b) const
{
  // Pi = kappa <-g>_+^2 A / 2: dPi/du = -p A dg/du.
  const int bs = _V->dofmap()->index_map_bs();
  const std::vector<double> pressure = pair_pressures_pa();
  for (std::size_t i = 0; i < _pairs.size(); ++i)
  {
    const double force = pressure[i] * _pairs[i].area_m2;
    const PairBlocks& p = _pair_blocks[i];
    for (std::size_t k = 0; k < p.block.size(); ++k)
      b[p.block[k] * bs + _z_component] -= p.slope[k] * force;
  }
}

void PenaltyContact::assemble_jacobian()
{
  MatZeroEntries(_A);
  dolfinx::fem::assemble_matrix(dolfinx::la::petsc::Matrix::set_block_fn(_A, ADD_VALUES), *_jacobian, _bcs);
  const int bs = _V->dofmap()->index_map_bs();
  const std::vector<double> pressure = pair_pressures_pa();
  // Every pair's entries, zero where open: the first final assembly freezes
  // the matrix's nonzero structure to the entries set so far.
  // d2Pi/du du = kappa A (dg/du)(dg/du)^T where penetrating; rows another
  // process owns go to it at assembly.
  std::vector<PetscInt> rows;
  std::vector<PetscScalar> values;
  for (std::size_t i = 0; i < _pairs.size(); ++i)
  {
    const PairBlocks& p = _pair_blocks[i];
    const std::size_t m = p.block.size();
    rows.resize(m);
    for (std::size_t r = 0; r < m; ++r)
      rows[r] = p.block[r] * bs + _z_component;
    const double k = pressure[i] > 0 ? _pairs[i].stiffness_pa_per_m * _pairs[i].area_m2 : 0.0;
    values.resize(m * m);
    for (std::size_t r = 0; r < m; ++r)
      for (std::size_t c = 0; c < m; ++c)
        values[r * m + c] = k * p.slope[r] * p.slope[c];
    MatSetValuesLocal(_A, static_cast<PetscInt>(m), rows.data(), static_cast<PetscInt>(m), rows.data(), values.data(),
                      ADD_VALUES);
  }
  MatAssemblyBegin(_A, MAT_FLUSH_ASSEMBLY);
  MatAssemblyEnd(_A, MAT_FLUSH_ASSEMBLY);
  dolfinx::fem::set_diagonal<T>(dolfinx::la::petsc::Matrix::set_fn(_A, INSERT_VALUES), *_V, _bcs);
  MatAssemblyBegin(_A, MAT_FINAL_ASSEMBLY);
  MatAssemblyEnd(_A, MAT_FINAL_ASSEMBLY);
}

double PenaltyContact::energy() const
{
  double local = dolfinx::fem::assemble_scalar(*_energy);
  const std::vector<double> pressure = pair_pressures_pa();
  for (std::size_t i = 0; i < _pairs.size(); ++i)
    local += 0.5 * pressure[i] * pressure[i] / _pairs[i].stiffness_pa_per_m * _pairs[i].area_m2;
  double total = 0;
  MPI_Allreduce(&local, &total, 1, MPI_DOUBLE, MPI_SUM, _scene.mesh->comm());
  return total;
}

NewtonReport PenaltyContact::solve()
{
  NewtonReport report;
  const auto map = _V->dofmap()->index_map;
  const int bs = _V->dofmap()->index_map_bs();
  // On the pairs' map: their forces on other processes' blocks travel in its reverse scatter.
  dolfinx::la::Vector<T> b(_pair_map, bs), du(_pair_map, bs);
  Vec b_petsc = dolfinx::la::petsc::create_vector_wrap(b);
  Vec du_petsc = dolfinx::la::petsc::create_vector_wrap(du);
  std::vector<T> u_before;
  std::string failure;
  // Once the set of penetrating points stops changing, a full step leaves
  // only the linear solve's own residual (see the header): a residual below
  // converged_residual of the largest since the first iteration's ends the
  // solve there, without the solve that would confirm it by an increment of
  // the linear solve's tolerance. (The first residual, under the new
  // approach's jump, is left out of the scale: a stricter test.) On a rim
  // end on steel the converged residuals fell to 1e-15 to 2e-9 of that
  // scale, the others stayed above 7.9e-6 (docs/notes/rims-log.md#speed).
  double largest_residual = 0;
  bool full_step = false;
  KeptPreconditioner kept = keep_preconditioner(_ksp, _reuse_within_solve);
  const bool scaled_tolerance = scales_absolute_tolerance(_ksp);
  for (int it = 1; it <= max_newton_iterations && failure.empty(); ++it)
  {
    auto start = Clock::now();
    assemble_residual(b);
    const double residual = dolfinx::la::norm(b);
    spdlog::debug("Newton {}: residual {:.3e} of the largest {:.3e}", it, residual, largest_residual);
    if (it > 2 && full_step && residual <= converged_residual * largest_residual)
    {
      report.assembly_s += seconds_since(start);
      break;
    }
    if (it > 1)
      largest_residual = std::max(largest_residual, residual);
    assemble_jacobian();
    const double energy_before = energy();
    report.assembly_s += seconds_since(start);

    start = Clock::now();
    KSPSetOperators(_ksp, _A, _A);
    if (scaled_tolerance)
      set_absolute_tolerance(_ksp, _largest_initial_residual);
    const LinearStep linear = solve_step(_ksp, b_petsc, du_petsc, it == 1, kept);
    if (scaled_tolerance)
      _largest_initial_residual = std::max(_largest_initial_residual, initial_residual_norm(_ksp));
    const KSPConvergedReason reason = linear.reason;
    const PetscInt its = linear.iterations;
    report.preconditioner_setups += linear.setups;
    report.solve_s += seconds_since(start);
    report.krylov_iterations += linear.all_iterations;
    report.newton_iterations = it;
    if (reason < 0)
    {
      failure = fmt::format("linear solve diverged ({}) after {} iterations in Newton iteration {}",
                            KSPConvergedReasons[reason], its, it);
      break;
    }
    du.scatter_fwd();

    // A full Newton increment below what the linear solve resolves ends the
    // solve without a line search: at that size the energy's change is
    // round-off, and the search halved such steps (0.25, 0.25, 0.5 on the 3D
    // P2 hemisphere's 1.2e-10, 8.9e-11 and 6.7e-11 at the default rtol
    // 1e-10), each halving costing another linear solve.
    std::span<T> u = _u->x()->mutable_array();
    std::span<const T> step = du.array();
    const double du_norm = dolfinx::la::norm(du), u_norm = dolfinx::la::norm(*_u->x());
    if (u_norm > 0 && du_norm <= increment_tolerance(_ksp) * u_norm)
    {
      for (std::size_t i = 0; i < u.size(); ++i)
        u[i] -= step[i];
      report.final_relative_increment = du_norm / u_norm;
      spdlog::debug("Newton {}: |du|/|u| = {:.3e}, full step, {} Krylov its", it, report.final_relative_increment, its);
      break;
    }

    // Energy line search: full step unless it raises the (convex) energy.
    start = Clock::now();
    u_before.assign(u.begin(), u.end());
    double alpha = 1.0;
    for (int halving = 0;; ++halving)
    {
      for (std::size_t i = 0; i < u.size(); ++i)
        u[i] = u_before[i] - alpha * step[i];
      const double energy_after = energy();
      if (energy_after <= energy_before + 1e-12 * std::abs(energy_before) || halving == max_line_search_halvings)
        break;
      alpha /= 2;
      ++report.line_search_halvings;
    }
    report.assembly_s += seconds_since(start);

    full_step = alpha == 1.0;
    const double u_after_norm = dolfinx::la::norm(*_u->x());
    report.final_relative_increment = u_after_norm > 0 ? alpha * du_norm / u_after_norm : 0.0;
    spdlog::debug("Newton {}: |du|/|u| = {:.3e}, step {}, {} Krylov its", it, report.final_relative_increment,
                  alpha, its);
    if (alpha == 1.0 && report.final_relative_increment <= newton_rtol)
      break;
    if (it == max_newton_iterations)
      failure = fmt::format("Newton did not converge in {} iterations (|du|/|u| = {:.3e})", it,
                            report.final_relative_increment);
  }
  if (kept.managed)
    KSPSetReusePreconditioner(_ksp, PETSC_FALSE); // the next solve's first iteration sets its own up
  VecDestroy(&b_petsc);
  VecDestroy(&du_petsc);
  spdlog::debug("Newton: {} iterations, {} Krylov, assembly and line search {:.2f} s, linear solves {:.2f} s",
                report.newton_iterations, report.krylov_iterations, report.assembly_s, report.solve_s);
  if (!failure.empty())
    throw ComputationError(fmt::format("penalty contact at approach {:.6e} m: {}", approach_m(), failure));
  return report;
}

double PenaltyContact::contact_force_n() const
{
  const double local = dolfinx::fem::assemble_scalar(*_contact_force);
  double total = 0;
  MPI_Allreduce(&local, &total, 1, MPI_DOUBLE, MPI_SUM, _scene.mesh->comm());
  return total * _scene.symmetry_multiplicity;
}

double PenaltyContact::reaction_force_n() const
{
  // The residual without Dirichlet rows is the internal force; at the top
  // face it is the force the loading plate exerts, equal and opposite to the
  // contact force in equilibrium.
  dolfinx::la::Vector<T> b(_pair_map, _V->dofmap()->index_map_bs());
  std::span<T> array = b.mutable_array();
  dolfinx::fem::assemble_vector<T>(array, *_residual);
  add_pair_forces(array);
  b.scatter_rev(std::plus<T>());
  double local = 0;
  for (std::int32_t dof : _top_z_dofs)
    local += array[dof];
  double total = 0;
  MPI_Allreduce(&local, &total, 1, MPI_DOUBLE, MPI_SUM, _scene.mesh->comm());
  return -total * _scene.symmetry_multiplicity;
}

void PenaltyContact::set_penalty_scale(const std::function<double(const double* x)>& scale)
{
  interpolate_scalar(*_penalty_scale, scale);
}

void PenaltyContact::set_initial_gap(const std::function<double(const double* x)>& gap)
{
  interpolate_scalar(*_initial_gap, gap);
}

void PenaltyContact::set_node_pairs(std::vector<NodePair> pairs)
{
  const MPI_Comm comm = _scene.mesh->comm();
  const auto map = _V->dofmap()->index_map;
  const int bs = _V->dofmap()->index_map_bs();
  const std::int32_t owned = map->size_local();
  const std::int64_t first = map->local_range()[0];
  int processes = 1;
  MPI_Comm_size(comm, &processes);
  // Where each process's blocks start: a block's owner by bisection.
  std::vector<std::int64_t> starts(processes);
  MPI_Allgather(&first, 1, MPI_INT64_T, starts.data(), 1, MPI_INT64_T, comm);
  auto owner = [&](std::int64_t g) {
    return static_cast<int>(std::upper_bound(starts.begin(), starts.end(), g) - starts.begin()) - 1;
  };
  std::vector<std::int64_t> ghosts = map->ghosts();
  std::vector<int> owners = map->owners();
  std::unordered_map<std::int64_t, std::int32_t> ghost_local;
  for (std::size_t j = 0; j < ghosts.size(); ++j)
    ghost_local.emplace(ghosts[j], owned + static_cast<std::int32_t>(j));
  // The local block of a global one: owned, a ghost, or a new ghost after them.
  auto local = [&](std::int64_t g) {
    if (g >= first && g < first + owned)
      return static_cast<std::int32_t>(g - first);
    if (g < 0 || g >= map->size_global())
      throw InputError(fmt::format("node pairs: block {} outside the {} blocks", g, map->size_global()));
    const auto [where, added] = ghost_local.emplace(g, owned + static_cast<std::int32_t>(ghosts.size()));
    if (added)
    {
      ghosts.push_back(g);
      owners.push_back(owner(g));
    }
    return where->second;
  };
  std::string bad;
  std::vector<PairBlocks> blocks;
  for (const NodePair& pair : pairs)
  {
    double lower_sum = 0;
    for (const WeightedBlock& w : pair.lower)
      lower_sum += w.weight;
    if (!(pair.node >= first && pair.node < first + owned) || std::abs(lower_sum - 1) > 1e-9
        || !(pair.area_m2 >= 0) || !(pair.stiffness_pa_per_m > 0) || !std::isfinite(pair.initial_gap_m))
    {
      bad = fmt::format("node pairs: a pair must have its node owned here, lower weights summing to 1, area >= 0, "
                        "stiffness > 0 and a finite gap (node {}, lower weight sum {}, area {}, stiffness {}, gap {})",
                        pair.node, lower_sum, pair.area_m2, pair.stiffness_pa_per_m, pair.initial_gap_m);
      break;
    }
    PairBlocks b{{local(pair.node)}, {1.0}};
    for (const WeightedBlock& w : pair.lower)
    {
      b.block.push_back(local(w.block));
      b.slope.push_back(-w.weight);
    }
    blocks.push_back(std::move(b));
  }
  // Every process throws, or none (the rest is collective).
  int failed = bad.empty() ? 0 : 1;
  MPI_Allreduce(MPI_IN_PLACE, &failed, 1, MPI_INT, MPI_MAX, comm);
  if (failed)
    throw InputError(bad.empty() ? "node pairs: a bad pair on another process" : bad);
  spdlog::debug("node pairs: {} on this process, {} blocks of other processes added as ghosts", pairs.size(),
                ghosts.size() - map->ghosts().size());
  _pairs = std::move(pairs);
  _pair_blocks = std::move(blocks);
  _pair_map = std::make_shared<const dolfinx::common::IndexMap>(comm, owned, ghosts, owners);
  _pair_u = std::make_unique<dolfinx::la::Vector<T>>(_pair_map, bs);

  // The form's cell couplings (the space's local blocks are the pair map's
  // first ones) and every pair's.
  dolfinx::la::SparsityPattern pattern(comm, {_pair_map, _pair_map}, {bs, bs});
  dolfinx::fem::sparsitybuild::cells(pattern, _scene.mesh->topology(), {*_V->dofmap(), *_V->dofmap()});
  for (const PairBlocks& b : _pair_blocks)
    pattern.insert(b.block, b.block);
  pattern.assemble();
  MatDestroy(&_A);
  _A = dolfinx::la::petsc::create_matrix(comm, pattern, "aij");
  MatSetNearNullSpace(_A, _near_nullspace);
  _largest_initial_residual = 0; // a new operator and preconditioner: their own norms
  if (_model == Model::solid)
    for (std::string& name : use_pair_solver_defaults(_ksp))
      _inserted_options.push_back(std::move(name)); // cleared at destruction, as the setup's options
}

std::vector<double> PenaltyContact::pair_pressures_pa() const
{
  if (!_pair_u)
    return {};
  // The displacements of the pairs' blocks on other processes: a forward
  // scatter on the pair map (collective: every process calls this).
  const std::span<const T> u = _u->x()->array();
  const int bs = _V->dofmap()->index_map_bs();
  std::span<T> w = _pair_u->mutable_array();
  std::copy_n(u.begin(), _V->dofmap()->index_map->size_local() * bs, w.begin());
  _pair_u->scatter_fwd();
  std::vector<double> pressure(_pairs.size());
  for (std::size_t i = 0; i < _pairs.size(); ++i)
  {
    const PairBlocks& p = _pair_blocks[i];
    double gap = _pairs[i].initial_gap_m;
    for (std::size_t k = 0; k < p.block.size(); ++k)
      gap += p.slope[k] * w[p.block[k] * bs + _z_component];
    pressure[i] = gap < 0 ? -_pairs[i].stiffness_pa_per_m * gap : 0.0;
  }
  return pressure;
}

std::vector<PairPressure> gather_pair_pressures(const PenaltyContact& problem)
{
  const std::vector<double> pressure = problem.pair_pressures_pa();
  const std::vector<NodePair>& pairs = problem.node_pairs();
  std::vector<double> local;
  for (std::size_t i = 0; i < pairs.size(); ++i)
    local.insert(local.end(), {pairs[i].x[0], pairs[i].x[1], pairs[i].x[2], pressure[i], pairs[i].area_m2,
                               pairs[i].initial_gap_m});
  const std::vector<double> all = all_gather(problem.mesh()->comm(), local);
  std::vector<PairPressure> gathered;
  for (std::size_t i = 0; i < all.size(); i += 6)
    gathered.push_back({{all[i], all[i + 1], all[i + 2]}, all[i + 3], all[i + 4], all[i + 5]});
  return gathered;
}

std::vector<NodePair> interface_node_pairs(const PenaltyContact& problem, double tol,
                                           const std::function<double(const double* x)>& initial_gap,
                                           const std::function<bool(const double* x)>& mortar_zone)
{
  const FormBindings bound = problem.form_bindings();
  const std::vector<double> area = contact_surface_weight(bound, p1_space(bound, bound.forms.scalar_p1_space));
  const PairingInput input{*problem.mesh(), *problem.displacement()->function_space()->dofmap(),
                           problem.dof_coordinates(), area, problem.scene().contact_facets};
  return interface_node_pairs(input, tol, initial_gap, mortar_zone);
}
} // namespace rollcheck::fem
