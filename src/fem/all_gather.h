#pragma once
// Every rank's values of a distributed post-processing quantity, concatenated
// in rank order on every rank (the scenes' surface and axis samples are
// small), and the wall time of a collective step (its slowest rank's).
#include "core/seconds_since.h"
#include <chrono>
#include <mpi.h>
#include <vector>

namespace rollcheck::fem
{
inline std::vector<double> all_gather(MPI_Comm comm, const std::vector<double>& local)
{
  int size = 1;
  MPI_Comm_size(comm, &size);
  int n = static_cast<int>(local.size());
  std::vector<int> counts(size), offsets(size + 1, 0);
  MPI_Allgather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, comm);
  for (int r = 0; r < size; ++r)
    offsets[r + 1] = offsets[r] + counts[r];
  std::vector<double> all(offsets[size]);
  MPI_Allgatherv(local.data(), n, MPI_DOUBLE, all.data(), counts.data(), offsets.data(), MPI_DOUBLE, comm);
  return all;
}

/// Seconds since `start` on the slowest rank of `comm`.
inline double wall_seconds_since(MPI_Comm comm, std::chrono::steady_clock::time_point start)
{
  double wall = seconds_since(start);
  MPI_Allreduce(MPI_IN_PLACE, &wall, 1, MPI_DOUBLE, MPI_MAX, comm);
  return wall;
}
} // namespace rollcheck::fem
