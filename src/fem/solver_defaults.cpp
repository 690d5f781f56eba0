#include "fem/solver_defaults.h"
#include "core/error.h"
#include <cctype>
#include <dolfinx/common/IndexMap.h>
#include <dolfinx/fem/DofMap.h>
#include <dolfinx/la/Vector.h>
#include <dolfinx/mesh/Mesh.h>
#include <dolfinx/la/petsc.h>
#include <fmt/format.h>
#include <span>
#include <sstream>
#include <utility>

namespace rollcheck::fem
{
namespace
{
using T = double;

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

/// KSPSetFromOptions, with PETSc's rejection kept as the message it returns
/// (empty if none). PETSc's default handler would print a rejection on rank
/// 0 and exit(0) every other rank without MPI_Finalize, so mpirun reported
/// an improper exit instead of the exit code 2: the caller throws on every
/// rank.
std::string set_from_options(KSP ksp)
{
  std::string rejection;
  PetscPushErrorHandler(keep_first_message, &rejection);
  const PetscErrorCode set = KSPSetFromOptions(ksp);
  PetscPopErrorHandler();
  if (set != 0 && rejection.empty())
    rejection = fmt::format("PETSc error {}", static_cast<int>(set));
  return set != 0 ? rejection : std::string();
}

/// set_from_options for a solver the scene chose after the set-up: InputError if PETSc rejects an option.
void set_from_options_or_throw(KSP ksp)
{
  if (const std::string rejection = set_from_options(ksp); !rejection.empty())
    throw InputError(fmt::format("PETSc rejected the solver options (prefix {}): {}", solver_prefix, rejection));
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
} // namespace

std::vector<std::string> insert_options(const std::string& petsc_options)
{
  if (!petsc_options.empty() && PetscOptionsInsertString(nullptr, petsc_options.c_str()) != 0)
    throw InputError(fmt::format("hertz: cannot parse PETSc options '{}'", petsc_options));
  return option_names(petsc_options);
}

void clear_options(const std::vector<std::string>& names)
{
  for (const std::string& name : names)
    PetscOptionsClearValue(nullptr, name.c_str());
}

MatNullSpace rigid_body_near_nullspace(const dolfinx::fem::FunctionSpace& V, Model model)
{
  std::vector<Vec> mode_vecs;
  for (const auto& m : rigid_body_modes(V, model))
  {
    Vec wrapped = dolfinx::la::petsc::create_vector_wrap(m);
    Vec owned;
    VecDuplicate(wrapped, &owned);
    VecCopy(wrapped, owned);
    VecDestroy(&wrapped);
    mode_vecs.push_back(owned);
  }
  MatNullSpace near_nullspace = nullptr;
  MatNullSpaceCreate(V.mesh()->comm(), PETSC_FALSE, mode_vecs.size(), mode_vecs.data(), &near_nullspace);
  for (Vec& v : mode_vecs)
    VecDestroy(&v);
  return near_nullspace;
}

KSP create_linear_solver(MPI_Comm comm, Model model, const std::string& petsc_options)
{
  KSP ksp = nullptr;
  KSPCreate(comm, &ksp);
  KSPSetOptionsPrefix(ksp, solver_prefix);
  set_default_solver(ksp, model);
  if (const std::string rejection = set_from_options(ksp); !rejection.empty())
  {
    KSPDestroy(&ksp);
    throw InputError(fmt::format("PETSc rejected the solver options (prefix {}){}: {}", solver_prefix,
                                 petsc_options.empty() ? "" : fmt::format(" '{}'", petsc_options), rejection));
  }
  return ksp;
}

bool is_direct(KSP ksp)
{
  PetscBool direct = PETSC_FALSE;
  PetscObjectTypeCompareAny(reinterpret_cast<PetscObject>(ksp), &direct, KSPPREONLY, KSPNONE, "");
  return direct == PETSC_TRUE;
}

void solve_linear(KSP ksp, Vec b, Vec x)
{
  std::string rejection;
  PetscPushErrorHandler(keep_first_message, &rejection);
  const PetscErrorCode solved = KSPSolve(ksp, b, x);
  PetscPopErrorHandler();
  if (solved != 0)
    throw InputError(fmt::format("PETSc cannot run the linear solver the options chose (prefix {}): {}",
                                 solver_prefix, rejection));
}

bool solver_option_given(const char* option)
{
  PetscBool given = PETSC_FALSE;
  PetscOptionsHasName(nullptr, solver_prefix, option, &given);
  return given == PETSC_TRUE;
}

void use_direct_solver_default(KSP ksp)
{
  if (solver_option_given("-ksp_type") || solver_option_given("-pc_type"))
    return;
  PC pc;
  KSPGetPC(ksp, &pc);
  KSPSetType(ksp, KSPPREONLY);
  PCSetType(pc, PCLU);
  PCFactorSetMatSolverType(pc, MATSOLVERMUMPS);
  set_from_options_or_throw(ksp);
}

std::vector<std::string> use_pair_solver_defaults(KSP ksp)
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
  if (solver_option_given("-pc_type"))
    return {};
  const std::pair<const char*, const char*> options[]
      = {{"-hertz_pc_hypre_boomeramg_strong_threshold", "0.5"},
         {"-hertz_pc_hypre_boomeramg_coarsen_type", "HMIS"},
         {"-hertz_pc_hypre_boomeramg_interp_type", "ext+i"},
         {"-hertz_pc_hypre_boomeramg_P_max", "4"},
         {"-hertz_pc_hypre_boomeramg_agg_nl", "1"}};
  std::vector<std::string> inserted;
  for (const auto& [name, value] : options)
  {
    PetscBool set = PETSC_FALSE;
    PetscOptionsHasName(nullptr, nullptr, name, &set);
    if (set)
      continue;
    PetscOptionsSetValue(nullptr, name, value);
    inserted.push_back(name);
  }
  PC pc;
  KSPGetPC(ksp, &pc);
  PCSetType(pc, PCHYPRE);
  PCHYPRESetType(pc, "boomeramg");
  set_from_options_or_throw(ksp);
  return inserted;
}
} // namespace rollcheck::fem
