#include "io/batch_coordinator.h"
#include "io/batch_messages.h"
#include "io/batch_record.h"
#include <algorithm>
#include <chrono>
#include <deque>
#include <fmt/format.h>
#include <list>
#include <mpi.h>
#include <optional>
#include <thread>

namespace rollcheck::io::batch
{
namespace fs = std::filesystem;

Plan make_plan(const BatchSettings& options, const fs::path& out, const FindSchema& find_schema)
{
  const std::vector<BatchCase> cases = resolve_batch_cases(expand_case_arguments(options.cases), find_schema);
  Plan plan;
  for (std::size_t i = 0; i < cases.size(); ++i)
  {
    const BatchCase& c = cases[i];
    CaseOutcome outcome{c.name, c.kind, c.file.string(), c.hash, CaseStatus::not_run, 0.0, c.error};
    if (!c.error.empty())
      outcome.status = CaseStatus::failed;
    else if (const std::optional<nlohmann::json> record = read_case_record(out, c.hash);
             !options.force && record && record->value("status", "") == "ok")
    {
      outcome.status = CaseStatus::skipped;
      outcome.wall_s = record->value("wall_s", 0.0);
    }
    else
    {
      auto& sharing = plan.cases_of_hash[c.hash];
      if (sharing.empty())
        plan.jobs.push_back({plan.jobs.size(), c.name, c.kind, c.file.string(), c.hash, c.parameters, c.inputs,
                             c.overrides, c.mpi_ranks});
      sharing.push_back(i);
    }
    plan.outcomes.push_back(outcome);
  }
  return plan;
}

std::vector<StoreEntry> store_entries(const std::vector<CaseOutcome>& outcomes, const fs::path& out)
{
  std::vector<StoreEntry> entries;
  for (const CaseOutcome& o : outcomes)
  {
    // A case the interrupt stopped keeps the result an earlier batch left
    // for its hash (`--force` replaces it only when the new one is done).
    std::optional<nlohmann::json> record = o.hash.empty() ? std::nullopt : read_case_record(out, o.hash);
    const bool stopped = o.status == CaseStatus::interrupted || o.status == CaseStatus::not_run;
    if (stopped && !record)
      continue;
    if (!record)
      record = nlohmann::json{{"status", "failed"}, {"message", o.message}, {"case_file", o.file}, {"kind", o.kind}};
    (*record)["case_file"] = o.file; // the file of this name; a shared result may have come from another
    entries.push_back({o.name, *record});
  }
  return entries;
}

void coordinate(Plan& plan, const std::vector<int>& slots, const BatchSettings& options, const fs::path& out,
                BatchProgress& progress)
{
  const int ranks = static_cast<int>(slots.size());
  std::deque<std::size_t> pending;
  for (const Job& job : plan.jobs)
    pending.push_back(job.index);
  std::vector<int> busy(ranks, 0);
  std::list<RunningJob> running;
  auto record = [&](std::size_t job_index, const CaseOutcome& outcome) {
    const Job& job = plan.jobs[job_index];
    for (std::size_t i : plan.cases_of_hash[job.hash])
    {
      const std::string name = plan.outcomes[i].name, file = plan.outcomes[i].file;
      plan.outcomes[i] = outcome;
      plan.outcomes[i].name = name;
      plan.outcomes[i].file = file;
    }
    progress.finished(outcome);
  };
  // A rank can take a job needing k slots if it has k free, or if it is idle
  // (then the job runs alone there, even with more processes than slots).
  auto pick_rank = [&](int k) {
    int best = -1;
    for (int r = 0; r < ranks; ++r)
      if ((busy[r] + k <= slots[r] || busy[r] == 0) && (best < 0 || slots[r] - busy[r] > slots[best] - busy[best]))
        best = r;
    return best;
  };
  const auto interrupt_deadline = std::chrono::seconds(10);
  std::optional<std::chrono::steady_clock::time_point> interrupted_at;
  while (true)
  {
    if (stop_signal() && !interrupted_at)
    {
      interrupted_at = std::chrono::steady_clock::now();
      for (int r = 1; r < ranks; ++r)
        send_text(r, tag_stop, "interrupt");
      pending.clear();
    }
    while (!pending.empty())
    {
      const Job& job = plan.jobs[pending.front()];
      const int r = pick_rank(job.mpi_ranks);
      if (r < 0)
        break;
      pending.pop_front();
      busy[r] += job.mpi_ranks;
      progress.started(job.name); // the name finished() erases
      if (r > 0)
      {
        send_text(r, tag_assign, job_json(job).dump());
        continue;
      }
      try
      {
        running.push_back(start_job(job, out));
      }
      catch (const std::exception& e)
      {
        busy[0] -= job.mpi_ranks;
        record(job.index, start_failure(job, e));
      }
    }
    poll_jobs(running, out, options.case_timeout_s, [&](const RunningJob& r, const CaseOutcome& outcome) {
      busy[0] -= r.job.mpi_ranks;
      record(r.job.index, outcome);
    });
    while (std::optional<Message> m = receive_text(MPI_ANY_SOURCE))
    {
      if (m->tag != tag_done)
        continue;
      const nlohmann::json j = nlohmann::json::parse(m->text);
      const Job& job = plan.jobs[j.at("index").get<std::size_t>()];
      busy[m->source] -= job.mpi_ranks;
      record(job.index, outcome_from_json(j));
    }
    const bool idle = std::all_of(busy.begin(), busy.end(), [](int b) { return b == 0; });
    if (pending.empty() && idle)
      break;
    // Other ranks may have died with the interrupt; do not wait for them forever.
    if (interrupted_at && std::chrono::steady_clock::now() - *interrupted_at > interrupt_deadline)
      break;
    progress.refresh();
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  if (!stop_signal())
    for (int r = 1; r < ranks; ++r)
      send_text(r, tag_stop, "done");
}
} // namespace rollcheck::io::batch
