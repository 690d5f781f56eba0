// rollcheck: validation of rolling-contact distribution scores and of Hertz
// contact by penalty FEM. See README.md. main() owns the process: the session
// (cli.h ProcessSession: MPI and PETSc in rollcheck-fem; in rollcheck, the
// hand-over of FEM commands to rollcheck-fem), the log, the command line
// (rollcheck's options before `--`, PETSc's after it) and the mapping of
// errors to exit codes. Both executables are built from this file.
#include "cli/cli.h"
#include "core/error.h"
#include "core/mpi_launch.h"
#include "rollcheck_commit.h"
#include "rollcheck_version.h"
#include <algorithm>
#include <cstdlib>
#include <set>
#include <tuple>
#include <cctype>
#include <fmt/format.h>
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

namespace
{
using namespace rollcheck;

std::string version_text()
{
  return fmt::format("rollcheck {} (commit {})\nDOLFINx {}, PETSc {}, gmsh {}", ROLLCHECK_VERSION, ROLLCHECK_GIT_COMMIT,
                     ROLLCHECK_DOLFINX_VERSION, ROLLCHECK_PETSC_VERSION, ROLLCHECK_GMSH_VERSION);
}

/// A single-dash word with an underscore, `-hertz_ksp_type`: PETSc's form,
/// which the parser would read as `-h` and more.
bool looks_like_petsc_option(const std::string& arg)
{
  return arg.size() > 2 && arg[0] == '-' && std::isalpha(static_cast<unsigned char>(arg[1]))
         && arg.find('_') != std::string::npos && arg.find(' ') == std::string::npos;
}

/// The subcommand's exit code; InputError -> 2, ComputationError -> 1. Under
/// MPI every rank ends with the first failing rank's code and message
/// (cli.h shared_outcome): a write that failed on one rank is named on all.
int run_guarded(const std::function<int()>& run)
{
  int code = 0;
  std::string error;
  try
  {
    code = run();
  }
  catch (const InputError& e)
  {
    code = 2;
    error = e.what();
  }
  catch (const ComputationError& e)
  {
    code = 1;
    error = fmt::format("computation failed: {}", e.what());
  }
  catch (const std::exception& e)
  {
    code = 1;
    error = fmt::format("internal error: {}", e.what());
  }
  std::tie(code, error) = cli::shared_outcome(code, error);
  if (!error.empty())
    spdlog::error("{}", error);
  return code;
}
/// The exit code of a failed parse, its message on stderr: a PETSc option
/// before `--` and an unknown subcommand are named; --help and --version are
/// "errors" with exit code 0.
int parse_failure(const CLI::App& app, const CLI::ParseError& e, const std::vector<std::string>& args)
{
  if (const auto petsc = std::ranges::find_if(args, looks_like_petsc_option); petsc != args.end())
  {
    spdlog::error("'{}' looks like a PETSc option: PETSc options go after `--`, as in `rollcheck {} [options] -- {} "
                  "...`",
                  *petsc, cli::subcommand_in(args), *petsc);
    return 2;
  }
  if (app.get_subcommands().empty())
    if (const int code = run_guarded([&] { cli::check_subcommand(app, cli::subcommand_in(args)); return 0; }); code != 0)
      return code;
  if (e.get_exit_code() != 0)
    if (const int code = run_guarded([&] { cli::check_options(app, args); return 0; }); code != 0)
      return code;
  return app.exit(e) == 0 ? 0 : 2;
}

} // namespace

namespace rollcheck::cli
{
std::string subcommand_in(const std::vector<std::string>& args)
{
  const auto name = std::ranges::find_if(args, [](const std::string& a) { return !a.starts_with('-'); });
  return name == args.end() ? "" : *name;
}

bool fast_command(const std::vector<std::string>& args)
{
  static const std::set<std::string> fast = {"mesh", "oracle", "search", "report", "audit", "optimize", "robustness"};
  // The score as an argument of its own or in an option's `--score=` form.
  const bool fem_score = std::ranges::any_of(args, [](const std::string& a) {
    const std::size_t equals = a.find('=');
    const std::string value = a.starts_with("--") && equals != std::string::npos ? a.substr(equals + 1) : a;
    return value == "fem-sds" || value == "fem-sds-template";
  });
  return fast.contains(subcommand_in(args)) && !fem_score && !launched_by_mpi();
}
} // namespace rollcheck::cli

int main(int argc, char** argv)
{
  // rollcheck's arguments end at `--`; PETSc's follow.
  const int ours = static_cast<int>(std::find(argv, argv + argc, std::string_view("--")) - argv);
  const std::vector<std::string> args(argv + 1, argv + ours);
  const cli::ProcessSession session(argc, argv, args);
  spdlog::set_default_logger(spdlog::stderr_color_mt("rollcheck"));
  spdlog::set_pattern("[%^%l%$] %v");

  CLI::App app{"rollcheck: contact-distribution oracles and penalty-contact FEM checks of Hertz theory"};
  app.name("rollcheck");
  app.set_version_flag("--version", version_text());
  app.require_subcommand(1);
  int verbosity = 0;
  bool quiet = false;
  app.add_flag("-v,--verbose", verbosity, "More log output on stderr (-vv for trace); anywhere on the line");
  app.add_flag("-q,--quiet", quiet, "Only errors on stderr (results still go to stdout); anywhere on the line");
  // Options a subcommand does not know pass to the executable: -q and -v after it.
  app.fallthrough();

  cli::add_mesh_command(app);
  cli::add_oracle_command(app);
  cli::add_search_command(app);
  cli::add_optimize_command(app);
  cli::add_report_command(app);
  cli::add_audit_command(app);
  cli::add_robustness_command(app);
  const std::size_t fast_subcommands = app.get_subcommands([](CLI::App*) { return true; }).size();
  cli::add_fem_commands(app);
  // PETSc reads options only in the FEM subcommands: theirs is the footer.
  const std::string petsc_footer = "PETSc options follow `--`: rollcheck hertz --model 3d -- -hertz_ksp_type cg";
  const std::vector<CLI::App*> subcommands = app.get_subcommands([](CLI::App*) { return true; });
  for (std::size_t k = fast_subcommands; k < subcommands.size(); ++k)
    subcommands[k]->footer(petsc_footer);
  app.footer(petsc_footer);

  try
  {
    app.parse(ours, argv);
  }
  catch (const CLI::ParseError& e)
  {
    return parse_failure(app, e, args);
  }
  spdlog::set_level(quiet ? spdlog::level::err
                          : verbosity >= 2 ? spdlog::level::trace
                          : verbosity == 1 ? spdlog::level::debug
                                           : spdlog::level::info);
  return run_guarded([&] {
    cli::insert_petsc_options({argv + std::min(ours + 1, argc), argv + argc});
    return cli::run_parsed(app);
  });
}
