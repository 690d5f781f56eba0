// run_batch(): the set-up every rank shares (worker slots, the output folder,
// the plan of rank 0) and the results store at the end. Rank 0's loop is in
// batch_coordinator.cpp, the other ranks' and the case processes in
// batch_jobs.cpp, the messages between ranks in batch_messages.cpp.
#include "io/batch_run.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/output_manifest.h"
#include "io/batch_coordinator.h"
#include "io/batch_jobs.h"
#include "io/batch_messages.h"
#include "io/batch_progress.h"
#include "io/batch_record.h"
#include "io/results_store.h"
#include <algorithm>
#include <chrono>
#include <fmt/format.h>
#include <mpi.h>
#include <optional>
#include <sched.h>
#include <thread>

namespace rollcheck::io
{
namespace
{
namespace fs = std::filesystem;

/// Workers of this rank when -j is not given: the CPUs mpirun bound it to,
/// or, unbound (one rank alone, or `mpirun --bind-to none`), its share of
/// the node's CPUs among the ranks on the node. Collective.
int default_workers()
{
  const int node_cpus = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  cpu_set_t set;
  CPU_ZERO(&set);
  const int bound = sched_getaffinity(0, sizeof set, &set) == 0 ? CPU_COUNT(&set) : node_cpus;
  MPI_Comm node;
  MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &node);
  int ranks_on_node = 1;
  MPI_Comm_size(node, &ranks_on_node);
  MPI_Comm_free(&node);
  return std::max(1, bound < node_cpus ? bound : node_cpus / ranks_on_node);
}
/// Rank 0, before any case runs: what the batch writes in `out` is checked
/// against the manifest rule (core/output_manifest.h), then the folder is
/// created, locked (into `lock`) and the outputs listed; a killed batch's
/// work is removed.
void prepare_output(const fs::path& out, const batch::Plan& plan, std::optional<OutputLock>& lock)
{
  std::vector<std::string> hashes;
  for (const CaseOutcome& o : plan.outcomes) // skipped cases too: their folders are the store's
    if (!o.hash.empty() && std::find(hashes.begin(), hashes.end(), o.hash) == hashes.end())
      hashes.push_back(o.hash);
  const std::vector<std::string> outputs = batch_outputs(hashes);
  // What a rollcheck before manifests wrote is recognised by its content:
  // the store by its layout, a case's folder by the record of its hash.
  std::vector<std::string> unknown = outputs;
  if (is_results_store(out / results_store_file))
    std::erase(unknown, results_store_file);
  for (const std::string& hash : hashes)
    if (read_case_record(out, hash))
      std::erase(unknown, (fs::path("cases") / hash).generic_string());
  const std::string origin = fmt::format("batch --out '{}'", out.string());
  check_output_entries(out, unknown, origin);
  fs::create_directories(out / "cases");
  lock.emplace(out);
  check_output_entries(out, unknown, origin); // again, now that no other batch writes here
  claim_outputs(out, outputs);
  remove_stale_work(out);
}
} // namespace

std::string status_name(CaseStatus status)
{
  switch (status)
  {
  case CaseStatus::ok: return "ok";
  case CaseStatus::skipped: return "skipped";
  case CaseStatus::failed: return "FAILED";
  case CaseStatus::interrupted: return "interrupted";
  case CaseStatus::not_run: return "not run";
  }
  return "?";
}

int BatchResult::count(CaseStatus status) const
{
  return static_cast<int>(
      std::count_if(outcomes.begin(), outcomes.end(), [&](const CaseOutcome& o) { return o.status == status; }));
}

int BatchResult::exit_code() const
{
  if (interrupted)
    return 130;
  return std::min(count(CaseStatus::failed), 125);
}

nlohmann::json BatchResult::to_json() const
{
  nlohmann::json cases = nlohmann::json::array();
  for (const CaseOutcome& o : outcomes)
    cases.push_back(batch::outcome_json(o));
  return {{"cases", cases},
          {"store", store.string()},
          {"computed", count(CaseStatus::ok)},
          {"skipped", count(CaseStatus::skipped)},
          {"failed", count(CaseStatus::failed)},
          {"not_run", count(CaseStatus::interrupted) + count(CaseStatus::not_run)},
          {"interrupted", interrupted},
          {"wall_s", wall_s},
          {"ranks", ranks},
          {"workers_per_rank", jobs}};
}

BatchResult run_batch(const BatchSettings& options, const FindSchema& find_schema)
{
  const auto start = std::chrono::steady_clock::now();
  const batch::StopSignals signals;
  const int rank = batch::world_rank(), ranks = batch::world_size();
  if (options.out.empty()) // every rank alike, before anything collective
    throw InputError("batch --out: the folder is an empty path");
  const fs::path out = fs::absolute(options.out).lexically_normal();
  if (options.jobs < 0)
    throw InputError(fmt::format("batch -j {}: the number of workers must be at least 1 (0: one per CPU)",
                                 options.jobs));
  const int automatic = default_workers(); // collective: every rank calls it, -j given or not
  const int jobs = options.jobs > 0 ? options.jobs : automatic;
  std::vector<int> slots(ranks);
  MPI_Gather(&jobs, 1, MPI_INT, slots.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);

  // Rank 0 plans; the others wait for the verdict, so that a bad argument
  // ends every rank instead of leaving them waiting for work.
  batch::Plan plan;
  std::optional<OutputLock> lock;
  std::string setup_error;
  if (rank == 0)
  {
    try
    {
      // The cases are read and checked before the folder is touched: a batch
      // refused for bad input leaves nothing behind, no folder, no lock.
      plan = batch::make_plan(options, out, find_schema);
      check_output_location(options.out, fmt::format("batch --out '{}'", out.string()));
      prepare_output(out, plan, lock);
    }
    catch (const std::filesystem::filesystem_error& e)
    {
      setup_error = fmt::format("batch --out '{}': {}", out.string(), e.what());
    }
    catch (const InputError& e)
    {
      setup_error = e.what();
    }
  }
  int ready = setup_error.empty();
  MPI_Bcast(&ready, 1, MPI_INT, 0, MPI_COMM_WORLD);
  BatchResult result;
  result.ranks = ranks;
  result.jobs = jobs;
  if (!ready)
  {
    if (rank == 0)
      throw InputError(setup_error);
    return result;
  }
  if (rank != 0)
  {
    batch::serve_jobs(out, options.case_timeout_s);
    return result;
  }

  result.coordinator = true;
  BatchProgress progress(plan.jobs.size(), stderr);
  const int to_skip = static_cast<int>(
      std::count_if(plan.outcomes.begin(), plan.outcomes.end(), [](auto& o) { return o.status == CaseStatus::skipped; }));
  progress.note(fmt::format("batch: {} case(s), {} to compute, {} done earlier; {} rank(s) x {} worker(s); results in {}",
                            plan.outcomes.size(), plan.jobs.size(), to_skip, ranks, jobs, out.string()));
  for (const CaseOutcome& o : plan.outcomes)
    if (o.status == CaseStatus::failed)
      progress.note(fmt::format("FAILED      {}: {}", o.name, o.message));
  batch::coordinate(plan, slots, options, out, progress);
  progress.close();

  result.outcomes = std::move(plan.outcomes);
  result.interrupted = batch::stop_signal() != 0;
  result.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  result.store = out / results_store_file;
  const std::vector<StoreEntry> entries = batch::store_entries(result.outcomes, out);
  write_results_store(result.store, entries,
                      {{"created_utc", utc_now()},
                       {"n_cases", result.outcomes.size()},
                       {"n_ok", result.count(CaseStatus::ok) + result.count(CaseStatus::skipped)},
                       {"n_failed", result.count(CaseStatus::failed)},
                       {"n_not_run", result.count(CaseStatus::interrupted) + result.count(CaseStatus::not_run)},
                       {"interrupted", result.interrupted},
                       {"batch_wall_s", result.wall_s}});
  return result;
}
} // namespace rollcheck::io
