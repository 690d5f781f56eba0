#pragma once
// A step that can fail on some ranks only (a write that meets a full disk or
// a file-size limit in one process, a file refused to one process) must end
// the same way on every rank. A rank that throws out of a sequence of
// collective calls leaves the others waiting in the next one, and itself
// waits in MPI_Finalize for them: the run hangs without a message. Each rank
// passes its own outcome here instead, and every rank learns the first
// failure (the lowest failing rank's exit code and message) and can raise it.
//
// A failure inside a library's own sequence of collective calls (DOLFINx's
// XDMF writer: HDF5 reduces over the ranks inside each dataset write) leaves
// the ranks that did not fail inside that sequence, where they cannot reach
// this call. Given `patience`, a failed rank waits that long for the others;
// if they do not come, it logs its message and ends every rank with
// MPI_Abort(MPI_COMM_WORLD, exit_code): exit code and message, never a hang.
//
// Contract: collective over `comm` (a non-blocking reduction, then
// broadcasts from the failing rank when there is one); every rank of `comm`
// calls it at the same point of its sequence of collective calls, with the
// same `patience`. `exit_code` 0 means this rank did not fail; `message` is
// read only where exit_code != 0.
#include <chrono>
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

/// The lowest failing rank's failure on every rank, or nullopt if no rank
/// failed; with `patience`, a failed rank that waits longer for the others
/// aborts every rank (above).
std::optional<RankFailure> first_failure(MPI_Comm comm, int exit_code, const std::string& message,
                                         std::optional<std::chrono::seconds> patience = std::nullopt);
} // namespace rollcheck::fem
