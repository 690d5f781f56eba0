#include "fem/penalty_contact.h"
#include "core/error.h"
#include "fem/nodal_fields.h"
#include <chrono>
#include <map>
#include <cmath>
#include <dolfinx/fem/assembler.h>
#include <dolfinx/fem/petsc.h>
#include <dolfinx/fem/utils.h>
#include <dolfinx/la/petsc.h>
#include <dolfinx/mesh/MeshTags.h>
#include <fmt/format.h>
#include <spdlog/spdlog.h>
#include <sstream>
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
  const int bs = _V->dofmap()->index_map_bs();
  const std::vector<double> pressure = pair_pressures_pa();
  for (std::size_t i = 0; i < _pairs.size(); ++i)
  {
    array[_pairs[i].upper * bs + _z_component] -= pressure[i] * _pairs[i].area_m2;
    array[_pairs[i].lower * bs + _z_component] += pressure[i] * _pairs[i].area_m2;
  }
  b.scatter_rev(std::plus<T>());
  // The state satisfies the Dirichlet conditions, so the increment is zero there.
  dolfinx::fem::set_bc<T>(array, _bcs, _u->x()->array(), -1.0);
}

void PenaltyContact::assemble_jacobian()
{
  MatZeroEntries(_A);
  dolfinx::fem::assemble_matrix(dolfinx::la::petsc::Matrix::set_block_fn(_A, ADD_VALUES), *_jacobian, _bcs);
  const int bs = _V->dofmap()->index_map_bs();
  const std::vector<double> pressure = pair_pressures_pa();
  // Every pair's entries, zero where open: the first final assembly freezes
  // the matrix's nonzero structure to the entries set so far.
  for (std::size_t i = 0; i < _pairs.size(); ++i)
  {
    const PetscInt rows[2] = {_pairs[i].upper * bs + _z_component, _pairs[i].lower * bs + _z_component};
    const double k = pressure[i] > 0 ? _pairs[i].stiffness_pa_per_m * _pairs[i].area_m2 : 0.0;
    const PetscScalar values[4] = {k, -k, -k, k};
    MatSetValuesLocal(_A, 2, rows, 2, rows, values, ADD_VALUES);
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
  dolfinx::la::Vector<T> b(map, bs), du(map, bs);
  Vec b_petsc = dolfinx::la::petsc::create_vector_wrap(b);
  Vec du_petsc = dolfinx::la::petsc::create_vector_wrap(du);
  std::vector<T> u_before;
  std::string failure;
  for (int it = 1; it <= max_newton_iterations && failure.empty(); ++it)
  {
    auto start = Clock::now();
    assemble_residual(b);
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
  const auto map = _V->dofmap()->index_map;
  dolfinx::la::Vector<T> b(map, _V->dofmap()->index_map_bs());
  std::span<T> array = b.mutable_array();
  dolfinx::fem::assemble_vector<T>(array, *_residual);
  const int bs = _V->dofmap()->index_map_bs();
  const std::vector<double> pressure = pair_pressures_pa();
  for (std::size_t i = 0; i < _pairs.size(); ++i)
  {
    array[_pairs[i].upper * bs + _z_component] -= pressure[i] * _pairs[i].area_m2;
    array[_pairs[i].lower * bs + _z_component] += pressure[i] * _pairs[i].area_m2;
  }
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
  int processes = 1;
  MPI_Comm_size(_scene.mesh->comm(), &processes);
  if (processes > 1 && !pairs.empty())
    throw InputError("contact between two elastic bodies (node pairs) runs on one process");
  _pairs = std::move(pairs);
  dolfinx::la::SparsityPattern pattern = dolfinx::fem::create_sparsity_pattern(*_jacobian);
  for (const NodePair& pair : _pairs)
  {
    const std::int32_t blocks[2] = {pair.upper, pair.lower};
    pattern.insert(blocks, blocks);
  }
  pattern.assemble();
  MatDestroy(&_A);
  _A = dolfinx::la::petsc::create_matrix(_scene.mesh->comm(), pattern, "aij");
  MatSetNearNullSpace(_A, _near_nullspace);
}

std::vector<double> PenaltyContact::pair_pressures_pa() const
{
  const std::span<const T> u = _u->x()->array();
  const int bs = _V->dofmap()->index_map_bs();
  std::vector<double> pressure(_pairs.size());
  for (std::size_t i = 0; i < _pairs.size(); ++i)
  {
    const NodePair& pair = _pairs[i];
    const double gap = pair.initial_gap_m + u[pair.upper * bs + _z_component] - u[pair.lower * bs + _z_component];
    pressure[i] = gap < 0 ? -pair.stiffness_pa_per_m * gap : 0.0;
  }
  return pressure;
}

std::vector<NodePair> interface_node_pairs(const PenaltyContact& problem, double tol)
{
  const std::vector<double>& x = problem.dof_coordinates();
  const std::vector<double> area = recover_nodal_fields(problem).contact_weight;
  const int up = problem.mesh()->geometry().dim() - 1;
  std::map<std::pair<double, double>, std::vector<std::int32_t>> at_interface;
  for (std::size_t i = 0; i < x.size() / 3; ++i)
    if (std::abs(x[3 * i + up]) < tol)
      at_interface[{std::round(x[3 * i] / tol), std::round(x[3 * i + 1] / tol)}].push_back(
          static_cast<std::int32_t>(i));
  std::vector<NodePair> pairs;
  for (const auto& [where, blocks] : at_interface)
  {
    const bool first_upper = area[blocks[0]] > 0;
    if (blocks.size() == 1 && !first_upper)
      continue; // on the lower body's free face beyond the upper one
    if (blocks.size() != 2)
      throw ComputationError(fmt::format("node pairs: {} interface nodes at one place, not a pair", blocks.size()));
    if (!first_upper && !(area[blocks[1]] > 0))
      continue; // on the edge of the upper body's face, without contact area
    const std::int32_t upper = first_upper ? blocks[0] : blocks[1], lower = first_upper ? blocks[1] : blocks[0];
    pairs.push_back({upper, lower, area[upper], 0.0, 0.0});
  }
  return pairs;
}
} // namespace rollcheck::fem
