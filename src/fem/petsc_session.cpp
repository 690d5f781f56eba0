#include "fem/petsc_session.h"
#include "core/blas_threads.h"
#include "core/error.h"
#include "core/mpi_launch.h"
#include <cstdlib>
#include <dolfinx/common/log.h>
#include <petscsys.h>
#include <spdlog/spdlog.h>

namespace rollcheck::fem
{
void ensure_petsc()
{
  PetscBool initialised = PETSC_FALSE;
  PetscInitialized(&initialised);
  if (initialised)
    return;
  // DOLFINx logs (loguru) at INFO by default; keep only its warnings unless
  // the user asked for trace output (-vv).
  loguru::g_stderr_verbosity = spdlog::get_level() <= spdlog::level::trace ? loguru::Verbosity_INFO
                                                                           : loguru::Verbosity_WARNING;
  prefer_isolated_mpi_singleton(); // read only if PETSc starts MPI here
  if (PetscInitializeNoArguments() != 0)
    throw ComputationError("PETSc failed to initialise");
  prefer_one_blas_thread(); // PETSc's BLAS: the ranks are the parallelism
  std::atexit([] {
    PetscBool finalised = PETSC_FALSE;
    PetscFinalized(&finalised);
    if (!finalised)
      PetscFinalize();
  });
}

int world_rank()
{
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  return rank;
}
} // namespace rollcheck::fem
