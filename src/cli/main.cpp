// rollcheck: validation of rolling-contact distribution scores and of Hertz
// contact by penalty FEM. See README.md.
#include "cli/cli.h"
#include "core/error.h"
#include "rollcheck_version.h"
#include <map>
#include <mpi.h>
#include <petscsys.h>
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

namespace
{
std::map<const CLI::App*, std::function<int()>>& runners()
{
  static std::map<const CLI::App*, std::function<int()>> table;
  return table;
}
} // namespace

namespace rollcheck::cli
{
void on_run(CLI::App* sub, std::function<int()> runner) { runners()[sub] = std::move(runner); }
} // namespace rollcheck::cli

namespace
{
/// MPI lives for the whole run (batch spreads cases over ranks, FEM solves
/// use PETSc); PETSc is started by whoever needs it and ended here.
struct MpiSession
{
  MpiSession(int& argc, char**& argv)
  {
    int provided;
    MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
  }
  ~MpiSession()
  {
    PetscBool petsc_running = PETSC_FALSE;
    PetscInitialized(&petsc_running);
    if (petsc_running)
      PetscFinalize();
    MPI_Finalize();
  }
};
} // namespace

int main(int argc, char** argv)
{
  using namespace rollcheck;
  MpiSession mpi(argc, argv);
  spdlog::set_default_logger(spdlog::stderr_color_mt("rollcheck"));
  spdlog::set_pattern("[%^%l%$] %v");

  CLI::App app{"rollcheck: contact-distribution oracles and penalty-contact FEM checks of Hertz theory"};
  app.set_version_flag("--version", std::string("rollcheck ") + ROLLCHECK_VERSION);
  app.require_subcommand(1);
  int verbosity = 0;
  bool quiet = false;
  app.add_flag("-v,--verbose", verbosity, "More log output on stderr (-vv for trace)");
  app.add_flag("-q,--quiet", quiet, "Only errors on stderr");

  cli::add_mesh_command(app);
  cli::add_oracle_command(app);
  cli::add_search_command(app);
  cli::add_hertz_command(app);
  cli::add_fem_sds_command(app);
  cli::add_crease_command(app);
  cli::add_run_command(app);
  cli::add_batch_command(app);
  cli::add_report_command(app);
  cli::add_audit_command(app);
  cli::add_validate_command(app);

  try
  {
    app.parse(argc, argv);
  }
  catch (const CLI::ParseError& e)
  {
    // --help and --version are "errors" with exit code 0.
    const int code = app.exit(e);
    return code == 0 ? 0 : 2;
  }
  spdlog::set_level(quiet ? spdlog::level::err
                          : verbosity >= 2 ? spdlog::level::trace
                          : verbosity == 1 ? spdlog::level::debug
                                           : spdlog::level::info);
  try
  {
    for (const CLI::App* sub : app.get_subcommands())
      if (auto it = runners().find(sub); it != runners().end())
        return it->second();
    spdlog::error("no runner for subcommand");
    return 2;
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
