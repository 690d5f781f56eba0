#pragma once
// PETSc (and with it MPI) must be initialised before any DOLFINx object is
// built and finalised once at exit. The CLI's main() knows nothing of PETSc,
// so the fem layer does it on first use.
#include <mpi.h>

namespace rollcheck::fem
{
/// Initialises PETSc (and MPI, if nobody did) once per process; registers
/// PetscFinalize to run at normal exit. Reads PETSC_OPTIONS from the
/// environment like any PETSc program. Safe to call repeatedly.
void ensure_petsc();

/// This process's rank in MPI_COMM_WORLD (after ensure_petsc()).
int world_rank();
} // namespace rollcheck::fem
