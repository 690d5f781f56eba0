// Subcommands and what runs when one was parsed: the one way a subcommand
// gets its --json option, its scene's options and its registration for case
// files, so that no subcommand repeats the wiring; and the check that a
// subcommand exists.
#include "cli/cli.h"
#include "cli/scenes.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include <algorithm>
#include <fmt/format.h>
#include <iterator>
#include <map>
#include <memory>
#include <spdlog/spdlog.h>

namespace rollcheck::cli
{
namespace
{
std::map<const CLI::App*, std::function<int()>>& runners()
{
  static std::map<const CLI::App*, std::function<int()>> table;
  return table;
}

/// Edits (insertions, deletions, substitutions) that turn `a` into `b`.
std::size_t edit_distance(const std::string& a, const std::string& b)
{
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j)
    row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i)
  {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j)
    {
      const std::size_t above = row[j];
      row[j] = std::min({above + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

/// The name in `known` closest to `name`, as " (did you mean 'X'?)" when it
/// is at most two edits away and those edits change less than half of the
/// name (its dashes aside: `--nu` is not a typo of `--out`); else "".
std::string suggestion(const std::vector<std::string>& known, const std::string& name)
{
  const auto closest = std::ranges::min_element(known, {}, [&](const std::string& k) { return edit_distance(k, name); });
  if (closest == known.end())
    return "";
  const std::size_t edits = edit_distance(*closest, name);
  const std::size_t letters = name.size() - std::min(name.find_first_not_of('-'), name.size());
  return edits <= 2 && 2 * edits < letters ? fmt::format(" (did you mean '{}'?)", *closest) : "";
}

/// The long option names ("--radius") of `app`.
std::vector<std::string> long_options(const CLI::App& app)
{
  std::vector<std::string> names;
  for (const CLI::Option* option : app.get_options())
    for (const std::string& name : option->get_lnames())
      names.push_back("--" + name);
  return names;
}
} // namespace

void on_run(CLI::App* sub, std::function<int()> runner) { runners()[sub] = std::move(runner); }

int run_parsed(const CLI::App& app)
{
  for (const CLI::App* sub : app.get_subcommands())
    if (auto it = runners().find(sub); it != runners().end())
      return it->second();
  spdlog::error("no runner for subcommand");
  return 2;
}

void check_subcommand(const CLI::App& app, const std::string& name)
{
  std::vector<std::string> known;
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; }))
    known.push_back(sub->get_name());
  if (name.empty() || std::ranges::find(known, name) != known.end())
    return;
  throw InputError(
      fmt::format("unknown subcommand '{}'{}; known: {}", name, suggestion(known, name), fmt::join(known, ", ")));
}

void check_options(const CLI::App& app, const std::vector<std::string>& args)
{
  const std::string name = subcommand_in(args);
  std::vector<std::string> known = long_options(app);
  std::string command = "rollcheck";
  for (const CLI::App* sub : app.get_subcommands([&](const CLI::App* s) { return s->get_name() == name; }))
  {
    std::ranges::copy(long_options(*sub), std::back_inserter(known));
    command += " " + name;
  }
  for (const std::string& arg : args)
  {
    if (arg == "--")
      return;
    if (!arg.starts_with("--"))
      continue;
    const std::string option = arg.substr(0, arg.find('='));
    if (std::ranges::find(known, option) == known.end())
      throw InputError(fmt::format("{}: unknown option '{}'{}; `{} --help` lists the options", command, option,
                                   suggestion(known, option), command));
  }
}

CLI::App* add_command(CLI::App& app, const std::string& name, const std::string& description,
                      std::function<CommandResult()> run, bool checks_input_before_mpi)
{
  CLI::App* sub = app.add_subcommand(name, description);
  // The option writes into the string for the whole run; the runner shares it.
  auto json_path = std::make_shared<std::string>();
  add_json_option(sub, *json_path);
  on_run(sub, [json_path, run = std::move(run), checks_input_before_mpi] {
    set_json_on_stdout(*json_path == "-");
    // Refused before any computation, not after it.
    if (!json_path->empty() && *json_path != "-")
      check_output_file(*json_path, "option --json");
    if (!checks_input_before_mpi)
      start_deferred_mpi();
    const CommandResult result = run();
    if (!result.summary.is_null())
      emit_json(*json_path, result.summary);
    return result.exit_code;
  });
  return sub;
}

CLI::App* add_scene_command(CLI::App& app, const std::string& name, const std::string& description,
                            const io::Schema& schema, SceneRun run, SceneRun command)
{
  register_scene({&schema, run});
  // The scene's options need the subcommand, which add_command creates; they
  // exist before any runner is called.
  auto options = std::make_shared<std::unique_ptr<io::SchemaOptions>>();
  CLI::App* sub = add_command(
      app, name, description,
      [options, &schema, run = command ? command : run] {
        const io::Parameters params = (*options)->apply();
        check_scene_outputs(schema, params);
        start_deferred_mpi();
        return CommandResult{run(params)};
      },
      true);
  *options = std::make_unique<io::SchemaOptions>(sub, schema);
  return sub;
}
} // namespace rollcheck::cli
