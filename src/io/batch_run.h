#pragma once
// `rollcheck batch`: runs case files on worker processes, spread over the
// ranks of MPI_COMM_WORLD (one rank without mpirun), each case in its own
// process, resumable, and gathers the results into one HDF5 store.
//
// Scheduling: rank 0 resolves the cases, skips those already done, and hands
// the others out, first come first served, to the ranks with free worker
// slots (itself included). A case that asks for k MPI ranks (`mpi_ranks`)
// takes k slots and runs as `mpirun -n k rollcheck run ...`, its own
// MPI_COMM_WORLD of k processes on the node of the rank that took it; if k
// exceeds a rank's slots it runs there alone once the rank is idle. Results
// go to DIR/cases/<hash>/ (batch_record.h), which must be on a file system
// every rank sees; rank 0 writes DIR/results.h5 at the end.
#include "io/batch_cases.h"
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace rollcheck::io
{
struct BatchSettings
{
  std::vector<std::string> cases;     ///< files, folders, globs
  int jobs = 0;                       ///< worker processes per rank; 0: the rank's share of the CPUs
  std::filesystem::path out = "results";
  bool force = false;                 ///< recompute cases already done
  double case_timeout_s = 0;          ///< a case running longer fails; 0: no limit
};

enum class CaseStatus
{
  ok,          ///< computed now
  skipped,     ///< done by an earlier batch, result reused
  failed,      ///< could not be resolved, or its process failed
  interrupted, ///< was running when the batch was interrupted
  not_run      ///< the batch was interrupted before it started
};
std::string status_name(CaseStatus status);

struct CaseOutcome
{
  std::string name;
  std::string kind;
  std::string file;
  std::string hash;
  CaseStatus status = CaseStatus::not_run;
  double wall_s = 0;   ///< of its process (an earlier one's for skipped cases)
  std::string message; ///< why it failed
};

struct BatchResult
{
  bool coordinator = false;          ///< rank 0, which alone holds the outcomes
  std::vector<CaseOutcome> outcomes; ///< in the order given
  std::filesystem::path store;
  bool interrupted = false;
  double wall_s = 0;
  int ranks = 1;
  int jobs = 1;                      ///< worker slots of rank 0
  int count(CaseStatus status) const;
  /// 0 if every case is ok or skipped, else the number failed (at most 125);
  /// 130 if the batch was interrupted.
  int exit_code() const;
  nlohmann::json to_json() const;
};

/// Runs the batch on every rank of MPI_COMM_WORLD (collective). InputError
/// for bad arguments (nothing to run, an unusable --out); a failing case is
/// an outcome, not an exception. SIGINT or SIGTERM stop it cleanly: running
/// cases are terminated and dropped, finished ones kept, the store written.
BatchResult run_batch(const BatchSettings& options, const FindSchema& find_schema);
} // namespace rollcheck::io
