// rollcheck: validation of rolling-contact distribution scores and of Hertz
// contact by penalty FEM. See README.md. main() owns the process: MPI, the
// log, the command line (rollcheck's options before `--`, PETSc's after it)
// and the mapping of errors to exit codes.
#include "cli/cli.h"
#include "core/error.h"
#include "fem/petsc_session.h"
#include "rollcheck_version.h"
#include <algorithm>
#include <cstdlib>
#include <set>
#include <cctype>
#include <dolfinx/common/version.h>
#include <fmt/format.h>
#include <gmsh.h>
#include <mpi.h>
#include <petscsys.h>
#include <petscversion.h>
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

namespace
{
using namespace rollcheck;

/// A PETSc option given (after `--` or in --petsc-options) that no solver
/// read is named, on rank 0: a misspelt option must not pass silently.
void warn_unused_petsc_options()
{
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  PetscInt count = 0;
  char** names = nullptr;
  char** values = nullptr;
  if (PetscOptionsLeftGet(nullptr, &count, &names, &values) != 0)
    return;
  for (PetscInt i = 0; rank == 0 && i < count; ++i)
    spdlog::warn("PETSc option -{}{}{} was not used by any solver", names[i], values[i] ? " " : "",
                 values[i] ? values[i] : "");
  PetscOptionsLeftRestore(nullptr, &count, &names, &values);
}

/// MPI is started for the scenes that need it (FEM solves, batches spread
/// over ranks, case files of any scene) or when a launcher started this
/// process; the others (and --help, --version) start in milliseconds without
/// it. PETSc is started by whoever needs it and ended here.
struct MpiSession
{
  MpiSession(int& argc, char**& argv, bool needed)
  {
    if (!needed)
      return;
    int provided;
    MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
  }
  ~MpiSession()
  {
    int initialized = 0;
    MPI_Initialized(&initialized);
    if (!initialized)
      return;
    PetscBool petsc_running = PETSC_FALSE;
    PetscInitialized(&petsc_running);
    if (petsc_running)
    {
      warn_unused_petsc_options();
      PetscFinalize();
    }
    MPI_Finalize();
  }
};

/// Whether the subcommand named in `args` needs MPI: every one but those that
/// compute on one process with threads (search, unless it scores FEM-SDS),
/// unless a launcher (mpirun) started us.
bool needs_mpi(const std::string& subcommand, const std::vector<std::string>& args)
{
  static const std::set<std::string> without_mpi = {"", "mesh", "oracle", "search", "report", "audit", "optimize"};
  const bool launched = std::getenv("OMPI_COMM_WORLD_SIZE") || std::getenv("PMIX_RANK") || std::getenv("PMI_RANK");
  const bool fem_search = subcommand == "search" && std::ranges::find(args, "fem-sds") != args.end();
  return launched || fem_search || !without_mpi.contains(subcommand);
}

std::string version_text()
{
  return fmt::format("rollcheck {} (commit {})\nDOLFINx {}, PETSc {}.{}.{}, gmsh {}", ROLLCHECK_VERSION,
                     ROLLCHECK_GIT_COMMIT, DOLFINX_VERSION_STRING, PETSC_VERSION_MAJOR, PETSC_VERSION_MINOR,
                     PETSC_VERSION_SUBMINOR, GMSH_API_VERSION);
}

/// The subcommand the arguments name ("" if none): the first argument that is
/// not an option, since rollcheck's own options take no values.
std::string subcommand_in(const std::vector<std::string>& args)
{
  const auto name = std::ranges::find_if(args, [](const std::string& a) { return !a.starts_with('-'); });
  return name == args.end() ? "" : *name;
}

/// A single-dash word with an underscore, `-hertz_ksp_type`: PETSc's form,
/// which the parser would read as `-h` and more.
bool looks_like_petsc_option(const std::string& arg)
{
  return arg.size() > 2 && arg[0] == '-' && std::isalpha(static_cast<unsigned char>(arg[1]))
         && arg.find('_') != std::string::npos && arg.find(' ') == std::string::npos;
}

/// The subcommand's exit code; InputError -> 2, ComputationError -> 1.
int run_guarded(const std::function<int()>& run)
{
  try
  {
    return run();
  }
  catch (const InputError& e)
  {
    spdlog::error("{}", e.what());
    return 2;
  }
  catch (const ComputationError& e)
  {
    spdlog::error("computation failed: {}", e.what());
    return 1;
  }
  catch (const std::exception& e)
  {
    spdlog::error("internal error: {}", e.what());
    return 1;
  }
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
                  *petsc, subcommand_in(args), *petsc);
    return 2;
  }
  if (app.get_subcommands().empty())
    if (const int code = run_guarded([&] { cli::check_subcommand(app, subcommand_in(args)); return 0; }); code != 0)
      return code;
  return app.exit(e) == 0 ? 0 : 2;
}

/// Puts the arguments after `--` into PETSc's options database, where every
/// solver reads them (prefix hertz_), as it reads PETSC_OPTIONS.
void insert_petsc_options(std::vector<std::string> options)
{
  if (options.empty())
    return;
  if (!options.front().starts_with('-'))
    throw InputError(fmt::format("after `--` come PETSc options (-name [value] ...), got '{}'", options.front()));
  fem::ensure_petsc();
  std::vector<char*> argv;
  for (std::string& option : options)
    argv.push_back(option.data());
  if (PetscOptionsInsertArgs(nullptr, static_cast<int>(argv.size()), argv.data()) != 0)
    throw InputError(fmt::format("cannot read the PETSc options after `--`: {}", fmt::join(options, " ")));
}

} // namespace

int main(int argc, char** argv)
{
  // rollcheck's arguments end at `--`; PETSc's follow.
  const int ours = static_cast<int>(std::find(argv, argv + argc, std::string_view("--")) - argv);
  const std::vector<std::string> args(argv + 1, argv + ours);
  MpiSession mpi(argc, argv, needs_mpi(subcommand_in(args), args));
  spdlog::set_default_logger(spdlog::stderr_color_mt("rollcheck"));
  spdlog::set_pattern("[%^%l%$] %v");

  CLI::App app{"rollcheck: contact-distribution oracles and penalty-contact FEM checks of Hertz theory"};
  app.name("rollcheck");
  app.set_version_flag("--version", version_text());
  app.require_subcommand(1);
  int verbosity = 0;
  bool quiet = false;
  app.add_flag("-v,--verbose", verbosity, "More log output on stderr (-vv for trace)");
  app.add_flag("-q,--quiet", quiet, "Only errors on stderr");
  app.footer("PETSc options follow `--`: rollcheck hertz --model 3d -- -hertz_ksp_type cg");

  cli::add_mesh_command(app);
  cli::add_oracle_command(app);
  cli::add_search_command(app);
  cli::add_hertz_command(app);
  cli::add_fem_sds_command(app);
  cli::add_crease_command(app);
  cli::add_optimize_command(app);
  cli::add_run_command(app);
  cli::add_batch_command(app);
  cli::add_report_command(app);
  cli::add_audit_command(app);
  cli::add_validate_command(app);

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
    insert_petsc_options({argv + std::min(ours + 1, argc), argv + argc});
    return cli::run_parsed(app);
  });
}
