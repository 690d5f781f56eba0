#pragma once
// The linear solver of a penalty-contact problem (fem/penalty_contact.h) and
// its PETSc defaults. Every option has the prefix "hertz_"; a default is set
// before KSPSetFromOptions, so PETSC_OPTIONS or the scene's petsc_options
// override it:
// - 2D: MUMPS LU (KSPPREONLY + PCLU).
// - 3D: GMRES (rtol 1e-10, at most 1000 iterations) with GAMG on an aij
//   matrix whose near-nullspace holds the rigid-body modes; once node pairs
//   join two bodies, hypre BoomerAMG with the usual 3D settings instead
//   (use_pair_solver_defaults); a scene whose meshes GAMG serves poorly
//   asks for MUMPS LU up to a size (use_direct_solver_default).
// A value PETSc rejects is bad input (InputError), never a silently kept
// default.
#include "fem/model.h"
#include <dolfinx/fem/FunctionSpace.h>
#include <mpi.h>
#include <string>
#include <vector>
#include <petscksp.h>

namespace rollcheck::fem
{
/// The prefix of every linear-solver option ("-hertz_ksp_type").
inline constexpr const char* solver_prefix = "hertz_";

/// Inserts `petsc_options` ("-hertz_ksp_type cg ...") into PETSc's options
/// database and returns the names it sets, to clear with clear_options when
/// the problem ends. InputError if PETSc cannot parse them.
std::vector<std::string> insert_options(const std::string& petsc_options);

/// Removes the named options from PETSc's database (a study runs many
/// problems, each with its own options).
void clear_options(const std::vector<std::string>& names);

/// The rigid-body modes of the displacement space V, orthonormalised:
/// translations and, where the model allows them, rotations (none
/// axisymmetric: u_r = const strains the hoop direction). GAMG's near-nullspace.
/// The caller destroys it (MatNullSpaceDestroy).
MatNullSpace rigid_body_near_nullspace(const dolfinx::fem::FunctionSpace& V, Model model);

/// A KSP with the prefix, the model's default solver and then the options of
/// the database. InputError, with PETSc's first message (what it rejected,
/// e.g. an unknown KSP or PC type), on every rank if it rejects them;
/// `petsc_options` only names them in that message. The caller destroys it.
KSP create_linear_solver(MPI_Comm comm, Model model, const std::string& petsc_options);

/// Whether the linear-solver option named `option` after the prefix
/// ("-ksp_atol" for -hertz_ksp_atol) is in PETSc's options database: given
/// on the command line, in the scene's petsc_options or in PETSC_OPTIONS, it
/// wins over the tool's defaults.
bool solver_option_given(const char* option);
/// Whether the KSP applies its preconditioner once (KSPPREONLY or its alias
/// KSPNONE): a direct solve, exact to round-off, whose preconditioner must
/// follow the matrix.
bool is_direct(KSP ksp);

/// KSPSolve with PETSc's error kept as create_linear_solver keeps it: a solver
/// the options chose that cannot run here (PETSc's own LU on several ranks:
/// "MatSolverType petsc does not support matrix type mpiaij") raises
/// InputError with PETSc's message on every rank (the set-up is collective),
/// not PETSc's trace and an improper exit under mpirun. A solve that runs but
/// does not converge is the caller's to judge (KSPGetConvergedReason).
void solve_linear(KSP ksp, Vec b, Vec x);

/// MUMPS LU (KSPPREONLY + PCLU) instead of the 3D default, then the options
/// of the database again, so -hertz_pc_factor_* and -hertz_mat_mumps_*
/// options apply (InputError if PETSc rejects one); nothing changes if a
/// -hertz_ksp_type or -hertz_pc_type is given (the user's solver wins).
void use_direct_solver_default(KSP ksp);

/// 3D with node pairs: GMRES + hypre BoomerAMG unless a -hertz_pc_type is
/// given; each BoomerAMG setting is a default that a given option keeps.
/// Returns the names of the options it set (for clear_options).
std::vector<std::string> use_pair_solver_defaults(KSP ksp);
} // namespace rollcheck::fem
