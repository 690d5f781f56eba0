#include "fem/first_failure.h"

namespace rollcheck::fem
{
std::optional<RankFailure> first_failure(MPI_Comm comm, int exit_code, const std::string& message)
{
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  const int mine = exit_code != 0 ? rank : size;
  int first = size;
  MPI_Allreduce(&mine, &first, 1, MPI_INT, MPI_MIN, comm);
  if (first == size)
    return std::nullopt;
  RankFailure failure{first, exit_code, rank == first ? message : std::string()};
  MPI_Bcast(&failure.exit_code, 1, MPI_INT, first, comm);
  int length = static_cast<int>(failure.message.size());
  MPI_Bcast(&length, 1, MPI_INT, first, comm);
  failure.message.resize(static_cast<std::size_t>(length));
  MPI_Bcast(failure.message.data(), length, MPI_CHAR, first, comm);
  return failure;
}
} // namespace rollcheck::fem
