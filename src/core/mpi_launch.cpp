// How this process was started (core/mpi_launch.h).
#include "core/mpi_launch.h"
#include <cstdlib>

namespace rollcheck
{
bool launched_by_mpi()
{
  return std::getenv("OMPI_COMM_WORLD_SIZE") || std::getenv("PMIX_RANK") || std::getenv("PMI_RANK");
}

void prefer_isolated_mpi_singleton()
{
  if (!launched_by_mpi())
    ::setenv("OMPI_MCA_ess_singleton_isolated", "1", 0);
}
} // namespace rollcheck
