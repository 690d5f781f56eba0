#pragma once
// A step that can fail on some ranks only (a write that meets a full disk or
// a file-size limit in one process, a file refused to one process) must end
// the same way on every rank. A rank that throws out of a sequence of
// collective calls leaves the others waiting in the next one, and itself
// waits in MPI_Finalize for them: the run hangs without a message. Each rank
// passes its own outcome here instead, and every rank learns the first
// failure (the lowest failing rank's exit code and message) and can raise it.
//
// Contract: collective over `comm` (an MPI_Allreduce, then broadcasts from
// the failing rank when there is one); every rank of `comm` calls it at the
// same point of its sequence of collective calls. `exit_code` 0 means this
// rank did not fail; `message` is read only where exit_code != 0.
#include <mpi.h>
#include <optional>
#include <string>

namespace rollcheck::fem
{
struct RankFailure
{
  int rank = 0;      ///< the lowest rank of `comm` that failed
  int exit_code = 1; ///< that rank's: 1 a failed computation, 2 bad input
  std::string message;
};

/// The lowest failing rank's failure on every rank, or nullopt if no rank failed.
std::optional<RankFailure> first_failure(MPI_Comm comm, int exit_code, const std::string& message);
} // namespace rollcheck::fem
