#include "io/batch_run.h"
#include "core/error.h"
#include "io/batch_process.h"
#include "io/batch_progress.h"
#include "io/batch_record.h"
#include "io/results_store.h"
#include "rollcheck_version.h"
#include <csignal>
#include <deque>
#include <fmt/format.h>
#include <fstream>
#include <list>
#include <map>
#include <mpi.h>
#include <sched.h>
#include <thread>
#include <unistd.h>

namespace rollcheck::io
{
namespace
{
namespace fs = std::filesystem;

volatile std::sig_atomic_t stop_signal = 0;
void on_stop_signal(int signal) { stop_signal = signal; }

/// SIGINT and SIGTERM set stop_signal while a batch runs; the loops check it.
class StopSignals
{
public:
  StopSignals()
  {
    stop_signal = 0;
    struct sigaction action{};
    action.sa_handler = on_stop_signal;
    sigemptyset(&action.sa_mask);
    sigaction(SIGINT, &action, &old_int_);
    sigaction(SIGTERM, &action, &old_term_);
  }
  StopSignals(const StopSignals&) = delete;
  StopSignals& operator=(const StopSignals&) = delete;
  ~StopSignals()
  {
    sigaction(SIGINT, &old_int_, nullptr);
    sigaction(SIGTERM, &old_term_, nullptr);
  }

private:
  struct sigaction old_int_{}, old_term_{};
};

enum Tag
{
  tag_assign = 1, ///< rank 0 -> worker: a job (JSON)
  tag_done = 2,   ///< worker -> rank 0: its outcome (JSON)
  tag_stop = 3    ///< rank 0 -> worker: "done" (no more jobs) or "interrupt"
};

int world_rank()
{
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  return rank;
}

int world_size()
{
  int size = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  return size;
}

void send_text(int destination, Tag tag, const std::string& text)
{
  MPI_Send(text.data(), static_cast<int>(text.size()), MPI_CHAR, destination, tag, MPI_COMM_WORLD);
}

struct Message
{
  int source;
  int tag;
  std::string text;
};

/// A message waiting from `source` (or any), without blocking.
std::optional<Message> receive_text(int source)
{
  int waiting = 0;
  MPI_Status status;
  MPI_Iprobe(source, MPI_ANY_TAG, MPI_COMM_WORLD, &waiting, &status);
  if (!waiting)
    return std::nullopt;
  int size = 0;
  MPI_Get_count(&status, MPI_CHAR, &size);
  Message m{status.MPI_SOURCE, status.MPI_TAG, std::string(static_cast<std::size_t>(size), '\0')};
  MPI_Recv(m.text.data(), size, MPI_CHAR, status.MPI_SOURCE, status.MPI_TAG, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  return m;
}

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

fs::path find_program(const std::string& name)
{
  const char* path = std::getenv("PATH");
  std::string_view dirs = path ? path : "/usr/bin:/bin";
  while (!dirs.empty())
  {
    const std::size_t colon = dirs.find(':');
    const fs::path candidate = fs::path(dirs.substr(0, colon)) / name;
    if (access(candidate.c_str(), X_OK) == 0)
      return candidate;
    dirs = colon == std::string_view::npos ? std::string_view() : dirs.substr(colon + 1);
  }
  throw ComputationError(fmt::format("batch: a case asks for several MPI ranks, but '{}' is not on PATH", name));
}

CaseStatus parse_status(const std::string& name)
{
  for (CaseStatus s : {CaseStatus::ok, CaseStatus::skipped, CaseStatus::failed, CaseStatus::interrupted})
    if (status_name(s) == name)
      return s;
  return CaseStatus::not_run;
}

/// What a rank needs to run a case: sent as JSON to the rank that takes it.
struct Job
{
  std::size_t index;
  std::string name, kind, file, hash;
  nlohmann::json parameters;
  std::vector<std::string> overrides;
  int mpi_ranks;
};

nlohmann::json job_json(const Job& j)
{
  return {{"index", j.index}, {"name", j.name},       {"kind", j.kind},           {"file", j.file},
          {"hash", j.hash},   {"parameters", j.parameters}, {"overrides", j.overrides}, {"mpi_ranks", j.mpi_ranks}};
}

Job job_from_json(const nlohmann::json& j)
{
  return {j.at("index"), j.at("name"), j.at("kind"), j.at("file"), j.at("hash"), j.at("parameters"),
          j.at("overrides"), j.at("mpi_ranks")};
}

struct RunningJob
{
  Job job;
  ChildProcess process;
};

RunningJob start_job(const Job& job, const fs::path& out)
{
  const fs::path work = start_case_work(out, job.hash);
  std::vector<std::string> argv;
  if (job.mpi_ranks > 1)
    argv = {find_program("mpirun").string(), "-n", std::to_string(job.mpi_ranks), "--oversubscribe"};
  for (const std::string& arg : {own_executable().string(), std::string("run"), job.file, std::string("--json"),
                                 std::string("summary.json")})
    argv.push_back(arg);
  for (const std::string& assignment : job.overrides)
  {
    argv.push_back("--set");
    argv.push_back(assignment);
  }
  return {job, ChildProcess(argv, work, work / "log.txt")};
}

/// A failed case's message: its logged errors, else the last line it wrote,
/// with how the process ended.
std::string failure_message(const fs::path& log, const ExitStatus& status)
{
  std::ifstream in(log);
  std::vector<std::string> errors;
  std::string line, last;
  while (std::getline(in, line))
  {
    if (line.empty())
      continue;
    last = line;
    if (const std::size_t at = line.find("[error] "); at != std::string::npos)
      if (const std::string e = line.substr(at + 8); std::find(errors.begin(), errors.end(), e) == errors.end())
        errors.push_back(e);
  }
  if (!errors.empty())
    return fmt::format("{}", fmt::join(errors, "; "));
  if (last.size() > 300)
    last = last.substr(0, 300) + "...";
  return last.empty() ? status.describe() : fmt::format("{} ({})", status.describe(), last);
}

/// Records a case's ending on disk and returns its outcome: kept if its
/// process ended by itself or timed out (`failure` says so), dropped if the
/// batch stopped it (`interrupted`).
CaseOutcome finish_job(RunningJob& running, const ExitStatus& status, const fs::path& out, const std::string& failure,
                       bool interrupted)
{
  const Job& job = running.job;
  CaseOutcome outcome{job.name, job.kind, job.file, job.hash, CaseStatus::ok, running.process.elapsed_s(), ""};
  const fs::path work = case_work_folder(out, job.hash);
  if (interrupted)
  {
    discard_case_work(out, job.hash);
    outcome.status = CaseStatus::interrupted;
    return outcome;
  }
  nlohmann::json record = {{"case_file", job.file},        {"kind", job.kind},
                           {"hash", job.hash},             {"rollcheck_version", ROLLCHECK_VERSION},
                           {"mpi_ranks", job.mpi_ranks},   {"wall_s", outcome.wall_s},
                           {"finished_utc", utc_now()},    {"rank", world_rank()},
                           {"exit", status.describe()},    {"parameters", job.parameters}};
  char host[256] = {};
  gethostname(host, sizeof host - 1);
  record["host"] = host;
  // The case file's text as it was run, so the store says what was computed.
  std::ifstream case_text(job.file);
  record["case_text"] = std::string(std::istreambuf_iterator<char>(case_text), std::istreambuf_iterator<char>());
  if (failure.empty() && status.success())
  {
    std::ifstream in(work / "summary.json");
    nlohmann::json summary = nlohmann::json::parse(in, nullptr, false);
    if (!in || summary.is_discarded() || !summary.is_object())
      outcome.message = "the case ended without writing its JSON summary";
    else
    {
      summary.erase("case"); // its parameters are the record's
      record["summary"] = summary;
      fs::remove(work / "summary.json");
    }
  }
  else
    outcome.message = failure.empty() ? failure_message(work / "log.txt", status) : failure;
  if (!outcome.message.empty())
  {
    outcome.status = CaseStatus::failed;
    record["message"] = outcome.message;
  }
  record["status"] = outcome.status == CaseStatus::ok ? "ok" : "failed";
  commit_case_work(out, job.hash, record);
  return outcome;
}

/// Polls the running jobs of this rank; calls `done` with each that ended
/// (or was stopped: timed out, or all of them on a stop signal).
void poll_jobs(std::list<RunningJob>& running, const fs::path& out, double timeout_s,
               const std::function<void(const RunningJob&, const CaseOutcome&)>& done)
{
  for (auto it = running.begin(); it != running.end();)
  {
    std::optional<ExitStatus> status = it->process.poll();
    std::string failure;
    bool interrupted = false;
    if (!status && timeout_s > 0 && it->process.elapsed_s() > timeout_s)
    {
      failure = fmt::format("timed out after {:.0f} s (--timeout)", timeout_s);
      status = it->process.terminate();
    }
    else if (!status && stop_signal)
    {
      interrupted = true;
      status = it->process.terminate();
    }
    if (!status)
    {
      ++it;
      continue;
    }
    CaseOutcome outcome;
    try
    {
      outcome = finish_job(*it, *status, out, failure, interrupted);
    }
    catch (const std::exception& e)
    {
      outcome = {it->job.name, it->job.kind, it->job.file, it->job.hash, CaseStatus::failed, it->process.elapsed_s(),
                 fmt::format("batch: cannot record the result: {}", e.what())};
    }
    done(*it, outcome);
    it = running.erase(it);
  }
}

/// A job that could not even start, as an outcome.
CaseOutcome start_failure(const Job& job, const std::exception& e)
{
  return {job.name, job.kind, job.file, job.hash, CaseStatus::failed, 0.0, fmt::format("batch: {}", e.what())};
}

nlohmann::json outcome_json(const CaseOutcome& o)
{
  return {{"name", o.name},       {"kind", o.kind},     {"file", o.file},      {"hash", o.hash},
          {"status", status_name(o.status)}, {"wall_s", o.wall_s}, {"message", o.message}};
}

/// Ranks other than 0: run what rank 0 hands out until it says stop.
void serve_jobs(const fs::path& out, double timeout_s)
{
  std::list<RunningJob> running;
  bool stop = false;
  auto report = [](const RunningJob& r, const CaseOutcome& outcome) {
    nlohmann::json message = outcome_json(outcome);
    message["index"] = r.job.index;
    send_text(0, tag_done, message.dump());
  };
  while (!(stop && running.empty()))
  {
    while (std::optional<Message> m = receive_text(0))
    {
      if (m->tag == tag_stop)
      {
        stop = true;
        if (m->text == "interrupt")
          stop_signal = SIGTERM;
      }
      else if (m->tag == tag_assign)
      {
        const Job job = job_from_json(nlohmann::json::parse(m->text));
        try
        {
          running.push_back(start_job(job, out));
        }
        catch (const std::exception& e)
        {
          nlohmann::json message = outcome_json(start_failure(job, e));
          message["index"] = job.index;
          send_text(0, tag_done, message.dump());
        }
      }
    }
    poll_jobs(running, out, timeout_s, report);
    if (stop_signal && running.empty())
      return;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
}

/// Rank 0's view of the batch before anything runs.
struct Plan
{
  std::vector<CaseOutcome> outcomes;          ///< one per case, in order
  std::vector<Job> jobs;                      ///< one per distinct hash to compute
  std::map<std::string, std::vector<std::size_t>> cases_of_hash;
};

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
        plan.jobs.push_back({plan.jobs.size(), c.name, c.kind, c.file.string(), c.hash, c.parameters, c.overrides,
                             c.mpi_ranks});
      sharing.push_back(i);
    }
    plan.outcomes.push_back(outcome);
  }
  return plan;
}

/// The store's entries: every case with a record on disk (or, for a case
/// that could not be resolved, its message), in the batch's order.
std::vector<StoreEntry> store_entries(const std::vector<CaseOutcome>& outcomes, const fs::path& out)
{
  std::vector<StoreEntry> entries;
  for (const CaseOutcome& o : outcomes)
  {
    if (o.status == CaseStatus::interrupted || o.status == CaseStatus::not_run)
      continue;
    std::optional<nlohmann::json> record = o.hash.empty() ? std::nullopt : read_case_record(out, o.hash);
    if (!record)
      record = nlohmann::json{{"status", "failed"}, {"message", o.message}, {"case_file", o.file}, {"kind", o.kind}};
    (*record)["case_file"] = o.file; // the file of this name; a shared result may have come from another
    entries.push_back({o.name, *record});
  }
  return entries;
}

/// Rank 0: hands out the jobs, runs its own share, collects the outcomes.
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
    if (stop_signal && !interrupted_at)
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
      progress.started(ranks > 1 ? fmt::format("{} (rank {})", job.name, r) : job.name);
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
      record(job.index, {j.at("name"), j.at("kind"), j.at("file"), j.at("hash"), parse_status(j.at("status")),
                         j.at("wall_s"), j.at("message")});
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
  if (!stop_signal)
    for (int r = 1; r < ranks; ++r)
      send_text(r, tag_stop, "done");
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
    cases.push_back(outcome_json(o));
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
  const StopSignals signals;
  const int rank = world_rank(), ranks = world_size();
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
  Plan plan;
  std::optional<OutputLock> lock;
  std::string setup_error;
  if (rank == 0)
  {
    try
    {
      if (fs::exists(out) && !fs::is_directory(out))
        throw InputError(fmt::format("batch --out '{}': exists and is not a folder", out.string()));
      // The cases are read and checked before the folder is touched: a batch
      // refused for bad input leaves nothing behind, no folder, no lock.
      plan = make_plan(options, out, find_schema);
      fs::create_directories(out / "cases");
      lock.emplace(out);
      remove_stale_work(out);
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
    serve_jobs(out, options.case_timeout_s);
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
  coordinate(plan, slots, options, out, progress);
  progress.close();

  result.outcomes = std::move(plan.outcomes);
  result.interrupted = stop_signal != 0;
  result.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  result.store = out / "results.h5";
  const std::vector<StoreEntry> entries = store_entries(result.outcomes, out);
  write_results_store(result.store, entries,
                      {{"created_utc", utc_now()},
                       {"n_cases", result.outcomes.size()},
                       {"n_ok", result.count(CaseStatus::ok) + result.count(CaseStatus::skipped)},
                       {"n_failed", result.count(CaseStatus::failed)},
                       {"n_not_run", result.count(CaseStatus::interrupted) + result.count(CaseStatus::not_run)},
                       {"batch_wall_s", result.wall_s}});
  return result;
}
} // namespace rollcheck::io
