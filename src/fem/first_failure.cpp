#include "fem/first_failure.h"
#include <spdlog/spdlog.h>
#include <thread>

namespace rollcheck::fem
{
namespace
{
/// Waits for `request`; after `patience` without it, logs `message` and aborts every rank.
void wait_or_abort(MPI_Request& request, std::chrono::seconds patience, int exit_code, const std::string& message)
{
  const auto deadline = std::chrono::steady_clock::now() + patience;
  for (int done = 0;;)
  {
    MPI_Test(&request, &done, MPI_STATUS_IGNORE);
    if (done)
      return;
    if (std::chrono::steady_clock::now() > deadline)
      break;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  spdlog::error("{} (the other ranks did not reach the check of this step within {} s: they wait in a collective "
                "call of their own; every rank is ended)",
                message, patience.count());
  MPI_Abort(MPI_COMM_WORLD, exit_code);
}
} // namespace

std::optional<RankFailure> first_failure(MPI_Comm comm, int exit_code, const std::string& message,
                                         std::optional<std::chrono::seconds> patience)
{
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  const int mine = exit_code != 0 ? rank : size;
  int first = size;
  MPI_Request request;
  MPI_Iallreduce(&mine, &first, 1, MPI_INT, MPI_MIN, comm, &request);
  if (exit_code != 0 && patience)
    wait_or_abort(request, *patience, exit_code, message);
  else
    MPI_Wait(&request, MPI_STATUS_IGNORE);
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
