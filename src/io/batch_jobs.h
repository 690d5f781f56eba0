#pragma once
// The cases a rank of a batch runs (batch_run.h has the scheduling): a job is
// what rank 0 hands out, sent as JSON to the rank that takes it; it runs as a
// child process (batch_process.h) in its work folder (batch_record.h); its
// ending is recorded on disk and reported as a CaseOutcome. Ranks other than
// 0 do nothing else: serve_jobs().
#include "io/batch_process.h"
#include "io/batch_run.h"
#include <exception>
#include <filesystem>
#include <functional>
#include <list>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace rollcheck::io::batch
{
/// What a rank needs to run a case.
struct Job
{
  std::size_t index;
  std::string name, kind, file, hash;
  nlohmann::json parameters;
  nlohmann::json inputs; ///< the input files and their SHA-256 (BatchCase::inputs)
  std::vector<std::string> overrides;
  int mpi_ranks;
};

nlohmann::json job_json(const Job& j);
Job job_from_json(const nlohmann::json& j);

struct RunningJob
{
  Job job;
  ChildProcess process;
};

/// Starts the job's process (`rollcheck run FILE`, under mpirun for several
/// ranks) in a fresh work folder under `out`.
RunningJob start_job(const Job& job, const std::filesystem::path& out);

/// A job that could not even start, as an outcome.
CaseOutcome start_failure(const Job& job, const std::exception& e);

/// Polls the running jobs of this rank; calls `done` with each that ended
/// (or was stopped: timed out, or all of them on a stop signal).
void poll_jobs(std::list<RunningJob>& running, const std::filesystem::path& out, double timeout_s,
               const std::function<void(const RunningJob&, const CaseOutcome&)>& done);

/// An outcome as JSON (in the batch's summary and in a worker's tag_done
/// message), and back.
nlohmann::json outcome_json(const CaseOutcome& o);
CaseOutcome outcome_from_json(const nlohmann::json& j);

/// Ranks other than 0: run what rank 0 hands out until it says stop.
void serve_jobs(const std::filesystem::path& out, double timeout_s);
} // namespace rollcheck::io::batch
