#include "io/batch_jobs.h"
#include "core/error.h"
#include "io/batch_messages.h"
#include "io/batch_record.h"
#include "rollcheck_version.h"
#include <algorithm>
#include <chrono>
#include <fmt/format.h>
#include <fstream>
#include <optional>
#include <thread>
#include <unistd.h>

namespace rollcheck::io::batch
{
namespace
{
namespace fs = std::filesystem;

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
                           {"exit", status.describe()},    {"parameters", job.parameters},
                           {"inputs", job.inputs}};
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
} // namespace

nlohmann::json job_json(const Job& j)
{
  return {{"index", j.index},         {"name", j.name},     {"kind", j.kind},
          {"file", j.file},           {"hash", j.hash},     {"parameters", j.parameters},
          {"inputs", j.inputs},       {"overrides", j.overrides}, {"mpi_ranks", j.mpi_ranks}};
}

Job job_from_json(const nlohmann::json& j)
{
  return {j.at("index"), j.at("name"), j.at("kind"), j.at("file"), j.at("hash"), j.at("parameters"),
          j.at("inputs"), j.at("overrides"), j.at("mpi_ranks")};
}

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
    else if (!status && stop_signal())
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

CaseOutcome start_failure(const Job& job, const std::exception& e)
{
  return {job.name, job.kind, job.file, job.hash, CaseStatus::failed, 0.0, fmt::format("batch: {}", e.what())};
}

nlohmann::json outcome_json(const CaseOutcome& o)
{
  return {{"name", o.name},       {"kind", o.kind},     {"file", o.file},      {"hash", o.hash},
          {"status", status_name(o.status)}, {"wall_s", o.wall_s}, {"message", o.message}};
}

CaseOutcome outcome_from_json(const nlohmann::json& j)
{
  return {j.at("name"), j.at("kind"), j.at("file"), j.at("hash"), parse_status(j.at("status")), j.at("wall_s"),
          j.at("message")};
}

void serve_jobs(const fs::path& out, double timeout_s)
{
  std::list<RunningJob> running;
  bool stop = false;
  // An outcome goes to rank 0 with the index of its job.
  auto report = [](std::size_t index, const CaseOutcome& outcome) {
    nlohmann::json message = outcome_json(outcome);
    message["index"] = index;
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
          raise_stop(SIGTERM);
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
          report(job.index, start_failure(job, e));
        }
      }
    }
    poll_jobs(running, out, timeout_s,
              [&](const RunningJob& r, const CaseOutcome& outcome) { report(r.job.index, outcome); });
    if (stop_signal() && running.empty())
      return;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
}
} // namespace rollcheck::io::batch
