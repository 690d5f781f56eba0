#include "fem/penalty_contact.h"
#include "core/error.h"
#include "fem/all_gather.h"
#include "fem/interpolate_between_meshes.h"
#include "fem/nodal_fields.h"
#include <algorithm>
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
#include <sstream>
#include <unordered_map>
#include <xtensor/xarray.hpp>
#include <xtensor/xtensor.hpp>

namespace rollcheck::fem
{
namespace
{
using T = PenaltyContact::T;
using Clock = std::chrono::steady_clock;
constexpr const char* prefix = "hertz_"; ///< of every solver option
constexpr int max_newton_iterations = 40;
constexpr double newton_rtol = 1e-10;  ///< on ||du|| / ||u||
constexpr double converged_residual = 1e-8; ///< ||F|| over the solve's largest after a full step
constexpr int max_line_search_halvings = 12;

double seconds_since(Clock::time_point start)
{
  return std::chrono::duration<double>(Clock::now() - start).count();
}

/// A PETSc error handler that keeps the first message (the innermost: what
/// was rejected) in `context`, a std::string, and passes the error code up.
PetscErrorCode keep_first_message(MPI_Comm, int, const char*, const char*, PetscErrorCode code, PetscErrorType,
                                  const char* message, void* context)
{
  auto& kept = *static_cast<std::string*>(context);
  if (kept.empty() && message)
    kept = message;
  return code;
}

/// Default solvers, set on the KSP before KSPSetFromOptions so that any
/// -hertz_* option overrides them.
void set_default_solver(KSP ksp, Model model)
{
  PC pc;
  KSPGetPC(ksp, &pc);
  if (model == Model::solid)
  {
    // GMRES rather than CG: the Jacobian is symmetric positive definite, but
    // GAMG's Chebyshev smoothers under-estimate the largest eigenvalue of the
    // penalty rows and CG then stops with DIVERGED_INDEFINITE_PC (c >= 300).
    KSPSetType(ksp, KSPGMRES);
    KSPSetTolerances(ksp, 1e-10, PETSC_DEFAULT, PETSC_DEFAULT, 1000);
    PCSetType(pc, PCGAMG);
  }
  else
  {
    KSPSetType(ksp, KSPPREONLY);
    PCSetType(pc, PCLU);
    PCFactorSetMatSolverType(pc, MATSOLVERMUMPS);
  }
}

/// Option names ("-hertz_ksp_type") in a PETSc options string.
std::vector<std::string> option_names(const std::string& options)
{
  std::vector<std::string> names;
  std::istringstream tokens(options);
  for (std::string token; tokens >> token;)
    if (token.size() > 1 && token[0] == '-' && std::isalpha(static_cast<unsigned char>(token[1])))
      names.push_back(token);
  return names;
}

/// Rigid-body modes of the displacement space: translations and, where the
/// model allows them, rotations (none axisymmetric: u_r = const strains the
/// hoop direction).
std::vector<dolfinx::la::Vector<T>> rigid_body_modes(const dolfinx::fem::FunctionSpace& V, Model model)
{
  const auto map = V.dofmap()->index_map;
  const int bs = V.dofmap()->index_map_bs();
  const std::vector<double> x = V.tabulate_dof_coordinates(false);
  const std::size_t n = map->size_local() + map->num_ghosts();
  std::vector<dolfinx::la::Vector<T>> modes;
  auto add_mode = [&](auto&& value) {
    dolfinx::la::Vector<T> mode(map, bs);
    std::span<T> m = mode.mutable_array();
    for (std::size_t i = 0; i < n; ++i)
      for (int c = 0; c < bs; ++c)
        m[i * bs + c] = value(&x[3 * i], c);
    modes.push_back(std::move(mode));
  };
  if (model == Model::axisymmetric)
    add_mode([](const double*, int c) { return c == 1 ? 1.0 : 0.0; });
  else if (model == Model::plane_strain)
  {
    for (int d = 0; d < 2; ++d)
      add_mode([d](const double*, int c) { return c == d ? 1.0 : 0.0; });
    add_mode([](const double* p, int c) { return c == 0 ? -p[1] : p[0]; });
  }
  else
  {
    for (int d = 0; d < 3; ++d)
      add_mode([d](const double*, int c) { return c == d ? 1.0 : 0.0; });
    add_mode([](const double* p, int c) { return c == 0 ? -p[1] : c == 1 ? p[0] : 0.0; });
    add_mode([](const double* p, int c) { return c == 0 ? p[2] : c == 2 ? -p[0] : 0.0; });
    add_mode([](const double* p, int c) { return c == 1 ? -p[2] : c == 2 ? p[1] : 0.0; });
  }
  dolfinx::la::orthonormalize(std::span(modes));
  return modes;
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
  if (!petsc_options.empty() && PetscOptionsInsertString(nullptr, petsc_options.c_str()) != 0)
    throw InputError(fmt::format("hertz: cannot parse PETSc options '{}'", petsc_options));
  _inserted_options = option_names(petsc_options);
  std::vector<dolfinx::la::Vector<T>> modes = rigid_body_modes(*_V, model);
  std::vector<Vec> mode_vecs;
  for (const auto& m : modes)
  {
    Vec wrapped = dolfinx::la::petsc::create_vector_wrap(m);
    Vec owned;
    VecDuplicate(wrapped, &owned);
    VecCopy(wrapped, owned);
    VecDestroy(&wrapped);
    mode_vecs.push_back(owned);
  }
  MatNullSpaceCreate(mesh->comm(), PETSC_FALSE, mode_vecs.size(), mode_vecs.data(), &_near_nullspace);
  for (Vec& v : mode_vecs)
    VecDestroy(&v);
  MatSetNearNullSpace(_A, _near_nullspace);
  _model = model;
  KSPCreate(mesh->comm(), &_ksp);
  KSPSetOptionsPrefix(_ksp, prefix);
  set_default_solver(_ksp, model);
  // A value PETSc rejects (an unknown KSP or PC type) is bad input, not a
  // silently kept default. PETSc's default handler would print it on rank 0
  // and exit(0) every other rank without MPI_Finalize, so mpirun reported an
  // improper exit instead of the exit code 2: the message is kept here and
  // every rank throws.
  std::string rejection;
  PetscPushErrorHandler(keep_first_message, &rejection);
  const PetscErrorCode set = KSPSetFromOptions(_ksp);
  PetscPopErrorHandler();
  if (set != 0)
    throw InputError(fmt::format("PETSc rejected the solver options (prefix {}){}: {}", prefix,
                                 petsc_options.empty() ? "" : fmt::format(" '{}'", petsc_options), rejection));
}

PenaltyContact::~PenaltyContact()
{
  // The setup's options were for this problem only (a study runs many).
  for (const std::string& name : _inserted_options)
    PetscOptionsClearValue(nullptr, name.c_str());
  KSPDestroy(&_ksp);
  MatNullSpaceDestroy(&_near_nullspace);
  MatDestroy(&_A);
}

std::int64_t PenaltyContact::num_dofs() const
{
  return _V->dofmap()->index_map->size_global() * _V->dofmap()->index_map_bs();
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
  // scale, the others stayed above 7.9e-6 (docs/rims.md, "Speed").
  double largest_residual = 0;
  bool full_step = false;
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
    VecZeroEntries(du_petsc);
    KSPSolve(_ksp, b_petsc, du_petsc);
    report.solve_s += seconds_since(start);
    KSPConvergedReason reason;
    KSPGetConvergedReason(_ksp, &reason);
    PetscInt its = 0;
    KSPGetIterationNumber(_ksp, &its);
    report.krylov_iterations += its;
    report.newton_iterations = it;
    if (reason < 0)
    {
      failure = fmt::format("linear solve diverged ({}) after {} iterations in Newton iteration {}",
                            KSPConvergedReasons[reason], its, it);
      break;
    }
    du.scatter_fwd();

    // Energy line search: full step unless it raises the (convex) energy.
    start = Clock::now();
    std::span<T> u = _u->x()->mutable_array();
    u_before.assign(u.begin(), u.end());
    std::span<const T> step = du.array();
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
    const double du_norm = dolfinx::la::norm(du), u_norm = dolfinx::la::norm(*_u->x());
    report.final_relative_increment = u_norm > 0 ? alpha * du_norm / u_norm : 0.0;
    spdlog::debug("Newton {}: |du|/|u| = {:.3e}, step {}, {} Krylov its", it, report.final_relative_increment,
                  alpha, its);
    if (alpha == 1.0 && report.final_relative_increment <= newton_rtol)
      break;
    if (it == max_newton_iterations)
      failure = fmt::format("Newton did not converge in {} iterations (|du|/|u| = {:.3e})", it,
                            report.final_relative_increment);
  }
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
  if (_model == Model::solid)
    use_pair_solver_defaults();
}

void PenaltyContact::use_pair_solver_defaults()
{
  // The pairs join two bodies by springs of c E h against an element's E h
  // (c = 10), a near-constraint GAMG's smoothed aggregation handles badly:
  // measured on the rounded 120 deg end on steel at 38k DOFs, GMRES + GAMG
  // took about 90 iterations a solve (rigid plane: 18), 370 at 98k DOFs, and
  // diverged at 1000 on another mesh; each body's rigid modes in the
  // near-nullspace did not help (83). Classical AMG (hypre BoomerAMG) with
  // the usual 3D settings (HMIS coarsening, ext+i interpolation, strong
  // threshold 0.5, one level of aggressive coarsening) took 24 and halved
  // the solve time (20.6 s against 37.9 s). Defaults only: any -hertz_pc_*
  // option given still wins.
  PetscBool has_pc = PETSC_FALSE;
  PetscOptionsHasName(nullptr, prefix, "-pc_type", &has_pc);
  if (has_pc)
    return;
  const std::pair<const char*, const char*> options[]
      = {{"-hertz_pc_hypre_boomeramg_strong_threshold", "0.5"},
         {"-hertz_pc_hypre_boomeramg_coarsen_type", "HMIS"},
         {"-hertz_pc_hypre_boomeramg_interp_type", "ext+i"},
         {"-hertz_pc_hypre_boomeramg_P_max", "4"},
         {"-hertz_pc_hypre_boomeramg_agg_nl", "1"}};
  for (const auto& [name, value] : options)
  {
    PetscBool set = PETSC_FALSE;
    PetscOptionsHasName(nullptr, nullptr, name, &set);
    if (set)
      continue;
    PetscOptionsSetValue(nullptr, name, value);
    _inserted_options.push_back(name); // cleared at destruction, as the setup's options
  }
  PC pc;
  KSPGetPC(_ksp, &pc);
  PCSetType(pc, PCHYPRE);
  PCHYPRESetType(pc, "boomeramg");
  KSPSetFromOptions(_ksp);
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

namespace
{
using Point2 = std::array<double, 2>;

/// A facet of the lower body's interface: its nodes' global blocks and
/// horizontal coordinates (x, y).
struct InterfaceFacet
{
  std::array<std::int64_t, 3> node{};
  std::array<Point2, 3> x{};
};

/// Twice the signed area of the triangle (o, a, b).
double cross(const Point2& o, const Point2& a, const Point2& b)
{
  return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
}

std::array<double, 3> barycentric(const std::array<Point2, 3>& t, const Point2& q)
{
  const double area = cross(t[0], t[1], t[2]);
  const double w1 = cross(t[0], q, t[2]) / area, w2 = cross(t[0], t[1], q) / area;
  return {1 - w1 - w2, w1, w2};
}

/// The part of the convex polygon `subject` inside the triangle `clip`
/// (Sutherland-Hodgman: clipped by each edge's half-plane in turn).
std::vector<Point2> clip_to_triangle(std::vector<Point2> subject, std::array<Point2, 3> clip)
{
  if (cross(clip[0], clip[1], clip[2]) < 0)
    std::swap(clip[1], clip[2]); // counter-clockwise: inside is left of each edge
  for (int e = 0; e < 3 && !subject.empty(); ++e)
  {
    const Point2& a = clip[e];
    const Point2& b = clip[(e + 1) % 3];
    std::vector<Point2> kept;
    for (std::size_t i = 0; i < subject.size(); ++i)
    {
      const Point2& p = subject[i];
      const Point2& q = subject[(i + 1) % subject.size()];
      const double sp = cross(a, b, p), sq = cross(a, b, q);
      if (sp >= 0)
        kept.push_back(p);
      if ((sp >= 0) != (sq >= 0))
      {
        const double t = sp / (sp - sq);
        kept.push_back({p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])});
      }
    }
    subject = std::move(kept);
  }
  return subject;
}

/// D. A. Dunavant, Int. J. Numer. Meth. Engng 21, 1985, 1129: the symmetric
/// 6-point rule of degree 4 on a triangle, barycentric points (a, a, 1 - 2a)
/// and permutations, weights over the area.
constexpr std::array<std::array<double, 2>, 2> dunavant_degree_4
    = {{{0.445948490915965, 0.223381589678011}, {0.091576213509771, 0.109951743655322}}};

/// The mortar sums of one upper node (fem::NodePair): A = int N_i,
/// int psi_i g0 and int psi_i phi_j, over the projection onto the interface.
struct MortarSums
{
  double area = 0, gap_area = 0;
  std::map<std::int64_t, double> lower;
};
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

std::vector<NodePair> interface_node_pairs(const PenaltyContact& problem, double tol,
                                           const std::function<double(const double* x)>& initial_gap,
                                           const std::function<bool(const double* x)>& mortar_zone)
{
  const MPI_Comm comm = problem.mesh()->comm();
  const auto& V = *problem.displacement()->function_space();
  const auto map = V.dofmap()->index_map;
  const std::int32_t owned = map->size_local();
  const std::int64_t first = map->local_range()[0];
  const std::vector<double>& x = problem.dof_coordinates(); // owned blocks, then ghosts
  const std::vector<double> area = recover_contact_pressure(problem).contact_weight; // owned blocks
  const int gdim = problem.mesh()->geometry().dim();
  const int up = gdim - 1;
  auto global = [&](std::int32_t i) { return i < owned ? first + i : map->ghosts()[i - owned]; };

  // Every process's interface nodes (x, y, block, area), gathered: twins may
  // lie on different processes.
  std::vector<double> local;
  for (std::int32_t i = 0; i < owned; ++i)
    if (std::abs(x[3 * i + up]) < tol)
      local.insert(local.end(), {x[3 * i], x[3 * i + 1], static_cast<double>(first + i), area[i]});
  const std::vector<double> all = all_gather(comm, local);
  std::vector<NodePair> pairs;
  for (const std::vector<std::pair<std::int64_t, double>>& nodes : interface_twins(all, tol))
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
    if (upper < first || upper >= first + owned)
      continue; // another process's
    const double* p = &x[3 * (upper - first)];
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
  if (!mortar_zone)
    return pairs;
  if (gdim != 3)
    throw InputError("node pairs: the mortar pairs are 3D only");

  const auto mortar_start = Clock::now();
  // Mortar: the upper body's contact facets with a node in the zone, and
  // the lower body's interface facets beneath their horizontal bounding
  // box, gathered from every process.
  const auto& mesh = *problem.mesh();
  const auto facet_cells = mesh.topology().connectivity(2, 3);
  const auto cell_facets = mesh.topology().connectivity(3, 2);
  if (!facet_cells || !cell_facets)
    throw ComputationError("node pairs: the mesh lacks its facet-cell connectivity");
  const auto& dofmap = *V.dofmap();
  const auto& layout = dofmap.element_dof_layout();
  auto in_zone = [&](std::int32_t d) { return mortar_zone(&x[3 * d]); };
  std::vector<std::array<std::int32_t, 3>> upper_facets;
  std::array<double, 4> box{1e300, 1e300, 1e300, 1e300}; // min x, min y, -max x, -max y
  for (std::int32_t f : problem.scene().contact_facets)
  {
    const std::int32_t c = facet_cells->links(f)[0];
    const auto facets_of_cell = cell_facets->links(c);
    const int local_facet
        = static_cast<int>(std::find(facets_of_cell.begin(), facets_of_cell.end(), f) - facets_of_cell.begin());
    const std::vector<int>& closure = layout.entity_closure_dofs(2, local_facet);
    if (closure.size() != 3)
      throw InputError("node pairs: the mortar pairs need linear elements");
    const auto cell_dofs = dofmap.cell_dofs(c);
    const std::array<std::int32_t, 3> dof{cell_dofs[closure[0]], cell_dofs[closure[1]], cell_dofs[closure[2]]};
    if (std::none_of(dof.begin(), dof.end(), in_zone))
      continue;
    upper_facets.push_back(dof);
    for (std::int32_t d : dof)
      for (int k = 0; k < 2; ++k)
      {
        box[k] = std::min(box[k], x[3 * d + k]);
        box[2 + k] = std::min(box[2 + k], -x[3 * d + k]);
      }
  }
  MPI_Allreduce(MPI_IN_PLACE, box.data(), 4, MPI_DOUBLE, MPI_MIN, comm);
  const std::int32_t cells = mesh.topology().index_map(3)->size_local();
  local.clear();
  for (std::int32_t c = 0; c < cells; ++c)
  {
    // A lower cell with a whole facet on the interface (the free part of the
    // lower face and the conforming part alike).
    std::vector<std::int32_t> on;
    double below = 0;
    for (std::int32_t d : dofmap.cell_dofs(c))
    {
      if (std::abs(x[3 * d + up]) < tol)
        on.push_back(d);
      else
        below = x[3 * d + up];
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
        local.insert(local.end(), {static_cast<double>(global(d)), x[3 * d], x[3 * d + 1]});
  }
  const std::vector<double> gathered = all_gather(comm, local);
  std::vector<InterfaceFacet> facets(gathered.size() / 9);
  for (std::size_t f = 0; f < facets.size(); ++f)
    for (int k = 0; k < 3; ++k)
    {
      facets[f].node[k] = static_cast<std::int64_t>(gathered[9 * f + 3 * k]);
      facets[f].x[k] = {gathered[9 * f + 3 * k + 1], gathered[9 * f + 3 * k + 2]};
    }
  // Buckets over the box, n per horizontal direction.
  const int n = std::max(1, static_cast<int>(std::sqrt(facets.size())));
  auto bucket = [&](double v, int d) {
    const double span = -box[2 + d] - box[d];
    const int b = span > 0 ? static_cast<int>((v - box[d]) / span * n) : 0;
    return std::clamp(b, 0, n - 1);
  };
  auto bucket_range = [&](const std::array<Point2, 3>& t) {
    std::array<int, 4> range{n, n, -1, -1}; // first x, first y, last x, last y
    for (const Point2& p : t)
      for (int d = 0; d < 2; ++d)
      {
        range[d] = std::min(range[d], bucket(p[d], d));
        range[2 + d] = std::max(range[2 + d], bucket(p[d], d));
      }
    return range;
  };
  std::vector<std::vector<std::int32_t>> buckets(static_cast<std::size_t>(n) * n);
  for (std::size_t f = 0; f < facets.size(); ++f)
  {
    const std::array<int, 4> r = bucket_range(facets[f].x);
    for (int i = r[0]; i <= r[2]; ++i)
      for (int j = r[1]; j <= r[3]; ++j)
        buckets[static_cast<std::size_t>(i) * n + j].push_back(static_cast<std::int32_t>(f));
  }

  // Each upper facet's projection cut by the lower facets beneath it; the
  // pieces' integrals go to the facet's selected nodes.
  std::map<std::int64_t, MortarSums> sums;
  std::vector<std::int32_t> seen(facets.size(), -1);
  int uncovered = 0;
  for (std::size_t u = 0; u < upper_facets.size(); ++u)
  {
    const std::array<std::int32_t, 3>& dof = upper_facets[u];
    std::array<Point2, 3> t;
    for (int k = 0; k < 3; ++k)
      t[k] = {x[3 * dof[k]], x[3 * dof[k] + 1]};
    const std::array<bool, 3> selected{in_zone(dof[0]), in_zone(dof[1]), in_zone(dof[2])};
    const double facet_area = 0.5 * std::abs(cross(t[0], t[1], t[2]));
    double longest = 0;
    for (int k = 0; k < 3; ++k)
      longest = std::max(longest, std::hypot(t[k][0] - t[(k + 1) % 3][0], t[k][1] - t[(k + 1) % 3][1]));
    // A contact facet seen edge-on from the interface gives its nodes no
    // area to weigh their gaps by (the scene's tagging must not pass one).
    if (!(facet_area > 1e-12 * longest * longest))
      throw ComputationError(fmt::format("node pairs: a contact facet in the mortar zone at ({:.6g}, {:.6g}) m is "
                                         "seen edge-on from the interface (no projected area)",
                                         t[0][0], t[0][1]));
    double covered = 0;
    const std::array<int, 4> r = bucket_range(t);
    for (int i = r[0]; i <= r[2]; ++i)
      for (int j = r[1]; j <= r[3]; ++j)
        for (std::int32_t m : buckets[static_cast<std::size_t>(i) * n + j])
        {
          if (seen[m] == static_cast<std::int32_t>(u))
            continue;
          seen[m] = static_cast<std::int32_t>(u);
          const std::vector<Point2> piece = clip_to_triangle({t[0], t[1], t[2]}, facets[m].x);
          for (std::size_t v = 1; v + 1 < piece.size(); ++v)
          {
            const std::array<Point2, 3> sub{piece[0], piece[v], piece[v + 1]};
            const double sub_area = 0.5 * std::abs(cross(sub[0], sub[1], sub[2]));
            covered += sub_area;
            for (const auto& [a, weight] : dunavant_degree_4)
              for (int perm = 0; perm < 3; ++perm)
              {
                std::array<double, 3> lambda{a, a, a};
                lambda[perm] = 1 - 2 * a;
                const Point2 q{lambda[0] * sub[0][0] + lambda[1] * sub[1][0] + lambda[2] * sub[2][0],
                               lambda[0] * sub[0][1] + lambda[1] * sub[1][1] + lambda[2] * sub[2][1]};
                const double dA = weight * sub_area;
                const std::array<double, 3> N = barycentric(t, q), phi = barycentric(facets[m].x, q);
                const double point[3] = {q[0], q[1], 0.0};
                const double g0 = initial_gap(point);
                for (int s = 0; s < 3; ++s)
                {
                  if (!selected[s])
                    continue;
                  // The dual shape function, biorthogonal to N on the facet.
                  const double psi = 4 * N[s] - 1;
                  MortarSums& to = sums[global(dof[s])];
                  to.area += N[s] * dA;
                  to.gap_area += psi * g0 * dA;
                  for (int k = 0; k < 3; ++k)
                    to.lower[facets[m].node[k]] += psi * phi[k] * dA;
                }
              }
          }
        }
    if (std::abs(covered - facet_area) > 1e-6 * facet_area)
      ++uncovered;
  }
  MPI_Allreduce(MPI_IN_PLACE, &uncovered, 1, MPI_INT, MPI_SUM, comm);
  if (uncovered > 0)
    throw ComputationError(fmt::format("node pairs: {} upper contact facets in the mortar zone are not wholly over "
                                       "the lower body's interface",
                                       uncovered));

  // A node's facets may lie on several processes: the sums of the nodes
  // other processes own go to them (node, kind, block, value: kind 0 the
  // area, 1 the gap's, 2 a lower weight).
  local.clear();
  for (auto it = sums.begin(); it != sums.end();)
  {
    const auto& [node, s] = *it;
    if (node >= first && node < first + owned)
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
  const std::vector<double> shared = all_gather(comm, local);
  for (std::size_t e = 0; e + 3 < shared.size(); e += 4)
  {
    const auto node = static_cast<std::int64_t>(shared[e]);
    if (node < first || node >= first + owned)
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
  for (const auto& [node, s] : sums)
  {
    const double* p = &x[3 * (node - first)];
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
  spdlog::debug("node pairs: {} mortar pairs on this process from {} facets, {:.2f} s", sums.size(),
                upper_facets.size(), std::chrono::duration<double>(Clock::now() - mortar_start).count());
  return pairs;
}
} // namespace rollcheck::fem
