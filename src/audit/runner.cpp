#include "audit/runner.h"
#include "core/child_process.h"
#include "core/error.h"
#include "core/progress_beat.h"
#include "core/slice_table_folder.h"
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdlib>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <fstream>
#include <functional>
#include <map>
#include <mutex>
#include <numeric>
#include <spdlog/spdlog.h>
#include <sys/resource.h>
#include <thread>

namespace rollcheck::audit
{
std::string command_id(std::size_t i) { return fmt::format("c{}", i + 1); }

namespace
{
/// The CPU time (user + system) of this process's children that have ended
/// and been reaped, and of their own reaped children.
double reaped_children_cpu_s()
{
  rusage usage{};
  getrusage(RUSAGE_CHILDREN, &usage);
  auto seconds = [](const timeval& t) { return static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_usec); };
  return seconds(usage.ru_utime) + seconds(usage.ru_stime);
}

/// Runs `argv` to its end, stdout and stderr captured, and measures it. The
/// kernel adds a child's CPU time to reaped_children_cpu_s() when it is
/// reaped; every reap of the audit happens under one lock, between two
/// readings, so the difference is this child's alone whatever the other
/// workers' children do.
std::pair<process::ExitStatus, std::string> run_measured(const std::vector<std::string>& argv, CommandCost& cost)
{
  static std::mutex reaping;
  process::ChildProcess child(argv, {});
  for (;;)
  {
    {
      std::lock_guard lock(reaping);
      const double before = reaped_children_cpu_s();
      if (const std::optional<process::ExitStatus> status = child.poll())
      {
        cost = {child.elapsed_s(), reaped_children_cpu_s() - before};
        return {*status, child.captured_stderr()};
      }
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
}

/// Runs one command with its JSON written to `json_path` (not to stdout:
/// `search` prints its table there too); the error text when it failed.
std::string run_one(const CommandArgs& args, const std::filesystem::path& rollcheck,
                    const std::filesystem::path& json_path, nlohmann::json& output, CommandCost& cost)
{
  std::vector<std::string> argv = {rollcheck.string(), "-q"};
  argv.insert(argv.end(), args.begin(), args.end());
  argv.insert(argv.end(), {"--json", json_path.string()});
  const auto [status, err] = run_measured(argv, cost);
  if (!status.success())
    return fmt::format("{}: {}", status.describe(), err);
  std::ifstream in(json_path);
  output = nlohmann::json::parse(in, nullptr, false);
  return output.is_discarded() ? fmt::format("unreadable JSON output in {}", json_path.string()) : "";
}

/// The `count` costliest commands by CPU time, on the log: where the audit's time goes.
void log_costliest(const std::vector<CommandArgs>& commands, const std::vector<CommandCost>& costs, std::size_t count)
{
  std::vector<std::size_t> order(commands.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return costs[a].cpu_s > costs[b].cpu_s; });
  double cpu_s = 0;
  for (const CommandCost& c : costs)
    cpu_s += c.cpu_s;
  spdlog::info("audit: the commands' CPU time {:.1f} s; the costliest:", cpu_s);
  for (std::size_t k = 0; k < std::min(count, order.size()); ++k)
    spdlog::info("  {:7.1f} s CPU {:7.1f} s wall  {} {}", costs[order[k]].cpu_s, costs[order[k]].wall_s,
                 command_id(order[k]), command_line(commands[order[k]]));
}

/// Subcommands that run for tens of seconds (FEM loops, searches over rolling
/// loops, the grid of modelling choices, the life study), longest first. The runner starts
/// them before the short ones, so that the short commands fill the other
/// workers around them instead of one long command running alone at the end
/// (longest-processing-time-first scheduling).
const std::vector<std::string> long_subcommands = {"optimize", "rim", "robustness", "life", "fem-sds", "search", "hertz"};

/// The indices of `commands` in the order they start: the long subcommands
/// first, in the order of long_subcommands, each group in citation order.
std::vector<std::size_t> start_order(const std::vector<CommandArgs>& commands)
{
  auto rank = [&](std::size_t i) {
    const auto it = commands[i].empty() ? long_subcommands.end()
                                        : std::find(long_subcommands.begin(), long_subcommands.end(), commands[i][0]);
    return it - long_subcommands.begin();
  };
  std::vector<std::size_t> order(commands.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return rank(a) < rank(b); });
  return order;
}

/// A fresh folder for the commands' JSON files, removed with it.
struct ScratchFolder
{
  std::filesystem::path path;
  ScratchFolder()
  {
    std::string pattern = (std::filesystem::temp_directory_path() / "rollcheck-audit-XXXXXX").string();
    if (!mkdtemp(pattern.data()))
      throw ComputationError("cannot create a scratch folder in " + std::filesystem::temp_directory_path().string());
    path = pattern;
  }
  ~ScratchFolder()
  {
    std::error_code ignored;
    std::filesystem::remove_all(path, ignored);
  }
  ScratchFolder(const ScratchFolder&) = delete;
  ScratchFolder& operator=(const ScratchFolder&) = delete;
};

/// While it lives, the commands keep the FEM slice table's nodes in `folder`
/// (core/slice_table_folder.h), unless the caller named a folder already (a
/// job sharing them beyond the audit): each node is solved once per audit,
/// not once per command.
class SharedSliceTable
{
public:
  explicit SharedSliceTable(const std::filesystem::path& folder) : set_(!slice_table_folder())
  {
    if (set_)
      setenv(slice_table_folder_variable, folder.c_str(), 1);
  }
  ~SharedSliceTable()
  {
    if (set_)
      unsetenv(slice_table_folder_variable);
  }
  SharedSliceTable(const SharedSliceTable&) = delete;
  SharedSliceTable& operator=(const SharedSliceTable&) = delete;

private:
  const bool set_;
};
/// The claim's `true` verdict from its source: a cell, its own rule (run by
/// `run_rule`, which fills the command ids) or its untestable reason.
Judgement decide_truth(const AuditClaim& claim, const TruthSource& source,
                       const std::function<CellResult(std::vector<std::string>&)>& run_rule)
{
  if (!source.mode.empty())
    return truth_from_cell(claim, source.mode, source.note);
  if (!source.rule)
    return {truth::cannot_be_tested,
            source.untestable.empty() ? "no recomputation under the best physics" : source.untestable, {}};
  Judgement j;
  const CellResult result = run_rule(j.commands);
  j.verdict = !result.undecided.empty() ? result.undecided : result.holds ? truth::holds : truth::does_not_hold;
  j.reason = source.note.empty() ? result.value : result.value + ". " + source.note;
  return j;
}
} // namespace

std::vector<Claim> select_claims(std::vector<Claim> all, const std::vector<std::string>& ids)
{
  if (ids.empty())
    return all;
  std::vector<std::string> known;
  for (const Claim& claim : all)
    known.push_back(claim.id);
  for (const std::string& id : ids)
    if (std::find(known.begin(), known.end(), id) == known.end())
      throw InputError(fmt::format("option --claims: no claim '{}'; the claims are {}", id, fmt::join(known, ", ")));
  std::erase_if(all, [&](const Claim& claim) { return std::find(ids.begin(), ids.end(), claim.id) == ids.end(); });
  return all;
}

std::vector<CommandArgs> distinct_commands(const std::vector<Claim>& claims)
{
  std::vector<CommandArgs> commands;
  auto add = [&](const std::vector<CommandArgs>& cited) {
    for (const CommandArgs& args : cited)
      if (std::find(commands.begin(), commands.end(), args) == commands.end())
        commands.push_back(args);
  };
  for (const Claim& claim : claims)
  {
    for (const ClaimCell& cell : claim.cells)
      add(cell.commands);
    add(claim.truth.commands);
  }
  return commands;
}

std::vector<CommandOutput> run_commands(const std::vector<CommandArgs>& commands,
                                        const std::filesystem::path& rollcheck, unsigned threads)
{
  const ScratchFolder scratch;
  const SharedSliceTable slice_table(scratch.path / "slice_table");
  std::vector<nlohmann::json> outputs(commands.size());
  std::vector<std::string> errors(commands.size());
  std::vector<CommandCost> costs(commands.size());
  const std::vector<std::size_t> order = start_order(commands);
  std::atomic<std::size_t> next{0};
  std::mutex log_mutex;
  std::size_t done = 0;
  // The costliest commands take half a minute each: the beat names the running ones meanwhile.
  ProgressBeat beat("audit", true, std::chrono::seconds(5));
  std::map<std::size_t, std::chrono::steady_clock::time_point> running; // by command index
  const auto start = std::chrono::steady_clock::now();
  auto set_beat = [&] { // under log_mutex
    std::vector<std::string> names;
    for (const auto& [i, since] : running)
      names.push_back(fmt::format("{} (from {:.0f} s)", command_id(i),
                                  std::chrono::duration<double>(since - start).count()));
    beat.step(fmt::format("[{}/{}] running {}", done, commands.size(), fmt::join(names, ", ")), false);
  };
  auto worker = [&] {
    for (std::size_t k = next++; k < commands.size(); k = next++)
    {
      const std::size_t i = order[k];
      {
        std::lock_guard lock(log_mutex);
        running[i] = std::chrono::steady_clock::now();
        set_beat();
      }
      try
      {
        errors[i] = run_one(commands[i], rollcheck, scratch.path / (command_id(i) + ".json"), outputs[i], costs[i]);
      }
      catch (const std::exception& e) // a child that cannot start: reported with the others, not thrown from a thread
      {
        errors[i] = e.what();
      }
      std::lock_guard lock(log_mutex);
      running.erase(i);
      spdlog::info("audit [{}/{}] {} {} ({:.1f} s, {:.1f} s CPU)", ++done, commands.size(), command_id(i),
                   command_line(commands[i]), costs[i].wall_s, costs[i].cpu_s);
      set_beat();
    }
  };
  std::vector<std::thread> pool;
  for (unsigned t = 0; t < std::max(1u, threads); ++t)
    pool.emplace_back(worker);
  for (std::thread& t : pool)
    t.join();
  log_costliest(commands, costs, 10);
  std::vector<CommandOutput> read;
  for (std::size_t i = 0; i < commands.size(); ++i)
  {
    if (!errors[i].empty())
      throw ComputationError(
          fmt::format("audit command {} `{}` failed: {}", command_id(i), command_line(commands[i]), errors[i]));
    read.emplace_back(command_line(commands[i]), std::move(outputs[i]), costs[i]);
  }
  return read;
}

AuditTable decide_claims(const std::vector<Claim>& claims, std::vector<CommandOutput>& outputs)
{
  const std::vector<CommandArgs> commands = distinct_commands(claims);
  if (outputs.size() != commands.size())
    throw ComputationError(fmt::format("audit: {} outputs for {} commands", outputs.size(), commands.size()));
  auto index = [&](const CommandArgs& args) {
    return static_cast<std::size_t>(std::find(commands.begin(), commands.end(), args) - commands.begin());
  };
  // A rule on its commands' outputs, with the ids it cites; errors name the claim and what was decided.
  auto apply = [&](const Claim& claim, const std::string& what, const Rule& rule,
                   const std::vector<CommandArgs>& cited, std::vector<std::string>& ids) {
    std::vector<CommandOutput*> inputs;
    for (const CommandArgs& args : cited)
    {
      inputs.push_back(&outputs[index(args)]);
      ids.push_back(command_id(index(args)));
    }
    try
    {
      return rule(inputs);
    }
    catch (const ComputationError& e)
    {
      throw ComputationError(fmt::format("audit claim '{}' ({}): {}", claim.id, what, e.what()));
    }
  };
  AuditTable table;
  for (const Claim& claim : claims)
  {
    AuditClaim decided{claim.id, claim.claim, claim.paper_value, claim.rule, {}, Verdict::not_built, claim.note, {}, {}};
    for (const ClaimCell& cell : claim.cells)
    {
      AuditCell& out = decided.cells[cell.mode];
      out = {true, static_cast<bool>(cell.rule), "", {}, false, cell.untestable};
      if (!cell.rule)
        continue;
      const CellResult result = apply(claim, cell.mode, cell.rule, cell.commands, out.commands);
      out.value = result.value, out.holds = result.holds, out.undecided = result.undecided;
    }
    decided.verdict = judge(decided);
    decided.reproduced = judge_reproduced(decided, claim.reproduced_note);
    decided.truth = decide_truth(decided, claim.truth, [&](std::vector<std::string>& ids) {
      return apply(claim, "true", claim.truth.rule, claim.truth.commands, ids);
    });
    table.claims.push_back(std::move(decided));
  }
  for (std::size_t i = 0; i < commands.size(); ++i)
    table.commands.push_back({command_id(i), outputs[i].command(), outputs[i].reads(), outputs[i].cost().wall_s,
                              outputs[i].cost().cpu_s});
  return table;
}

AuditTable run_audit(const AuditSettings& settings, const std::filesystem::path& rollcheck,
                     std::vector<CommandOutput>* kept)
{
  const auto start = std::chrono::steady_clock::now();
  const std::vector<Claim> claims = select_claims(audit_claims(settings.reference_meshes, settings.quick), settings.claims);
  const std::vector<CommandArgs> commands = distinct_commands(claims);
  const unsigned threads = settings.threads ? settings.threads : std::max(1u, std::thread::hardware_concurrency());
  spdlog::info("audit: {} commands on {} threads", commands.size(), threads);
  std::vector<CommandOutput> outputs = run_commands(commands, rollcheck, threads);
  AuditTable table = decide_claims(claims, outputs);
  table.modes = audit_modes();
  table.verdict_rules = audit_verdict_rules();
  table.quick = settings.quick;
  table.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (kept)
    *kept = std::move(outputs);
  return table;
}
} // namespace rollcheck::audit
