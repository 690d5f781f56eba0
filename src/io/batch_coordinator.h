#pragma once
// Rank 0 of a batch (batch_run.h has the scheduling): the plan made before
// anything runs, the loop that hands out the jobs and collects their
// outcomes, and the store's entries at the end.
#include "io/batch_cases.h"
#include "io/batch_jobs.h"
#include "io/batch_progress.h"
#include "io/batch_run.h"
#include "io/results_store.h"
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace rollcheck::io::batch
{
/// Rank 0's view of the batch before anything runs.
struct Plan
{
  std::vector<CaseOutcome> outcomes;          ///< one per case, in order
  std::vector<Job> jobs;                      ///< one per distinct hash to compute
  std::map<std::string, std::vector<std::size_t>> cases_of_hash;
};

/// Resolves the cases; those with an ok record under `out` are skipped
/// (unless --force), cases of one hash share one job. InputError for bad
/// case arguments.
Plan make_plan(const BatchSettings& options, const std::filesystem::path& out, const FindSchema& find_schema);

/// Hands out the jobs to the ranks with free slots (`slots[r]` of rank r),
/// runs rank 0's share, and fills the plan's outcomes until every job ended
/// or the batch was stopped.
void coordinate(Plan& plan, const std::vector<int>& slots, const BatchSettings& options,
                const std::filesystem::path& out, BatchProgress& progress);

/// The store's entries: every case with a record on disk (or, for a case
/// that could not be resolved, its message), in the batch's order. A case an
/// interrupt stopped is in it with its earlier record, if one exists, so that
/// an interrupted `--force` never leaves a store of the finished cases alone.
std::vector<StoreEntry> store_entries(const std::vector<CaseOutcome>& outcomes, const std::filesystem::path& out);
} // namespace rollcheck::io::batch
