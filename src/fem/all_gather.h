#pragma once
// Every rank's values of a distributed post-processing quantity, concatenated
// in rank order on every rank (the scenes' surface and axis samples are small).
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
} // namespace rollcheck::fem
