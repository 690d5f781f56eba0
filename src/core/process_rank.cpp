// The process that speaks (core/process_rank.h).
#include "core/process_rank.h"
#include <mpi.h>

namespace rollcheck
{
int process_rank()
{
  int initialised = 0, finalised = 0;
  MPI_Initialized(&initialised);
  MPI_Finalized(&finalised);
  if (!initialised || finalised)
    return 0;
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  return rank;
}
} // namespace rollcheck
