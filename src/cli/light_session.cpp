// The process around the command line in rollcheck, the executable without
// the FEM libraries (cli.h ProcessSession): it loads in milliseconds and runs
// the subcommands that need no FEM; for every other command line (a FEM
// subcommand, a case file, a batch, FEM-SDS scores, a gmsh volume mesh,
// PETSc options, --help, a launch under mpirun) it replaces its process with
// rollcheck-fem, beside it in the same folder, with the same arguments.
#include "cli/cli.h"
#include "cli/search_family.h"
#include "core/child_process.h"
#include "core/error.h"
#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <spdlog/spdlog.h>
#include <unistd.h>

namespace rollcheck::cli
{
namespace
{
/// Whether this executable runs the command line itself: a fast subcommand
/// (cli.h fast_command) that writes no gmsh volume mesh and passes no PETSc
/// options, or --version; --help and no subcommand go to rollcheck-fem, which
/// lists every subcommand.
bool runs_here(int argc, char** argv, const std::vector<std::string>& args)
{
  if (subcommand_in(args).empty())
    return std::ranges::find(args, "--version") != args.end();
  const bool petsc_options = std::find(argv, argv + argc, std::string_view("--")) != argv + argc;
  const bool volume_mesh = std::ranges::any_of(args, [](const std::string& a) { return a.ends_with(".msh"); });
  return fast_command(args) && !petsc_options && !volume_mesh;
}
} // namespace

ProcessSession::ProcessSession(int& argc, char**& argv, const std::vector<std::string>& args)
{
  if (runs_here(argc, argv, args))
    return;
  const std::string fem = (process::own_executable().parent_path() / "rollcheck-fem").string();
  ::execv(fem.c_str(), argv);
  // Only reached when the exec failed.
  std::fprintf(stderr, "[error] rollcheck: cannot start %s, which runs this command: %s\n", fem.c_str(),
               std::strerror(errno));
  std::exit(1);
}

ProcessSession::~ProcessSession() = default;

void add_fem_commands(CLI::App&) {}

void start_deferred_mpi() {}

void insert_petsc_options(std::vector<std::string> options)
{
  if (!options.empty())
    throw InputError("PETSc options are read by rollcheck-fem");
}

std::pair<int, std::string> shared_outcome(int exit_code, const std::string& error) { return {exit_code, error}; }

// ProcessSession hands the command lines that reach these to rollcheck-fem.
nlohmann::json write_volume_mesh(const geometry::SurfaceMesh&, double, const std::filesystem::path&)
{
  throw ComputationError("gmsh volume meshes are written by rollcheck-fem");
}

std::function<double(const geometry::BodySpec&)> fem_sds_family_scorer(bool,
                                                                       std::shared_ptr<std::vector<std::string>>)
{
  throw ComputationError("optimize --score fem-sds runs in rollcheck-fem");
}

nlohmann::json run_family_scores(oracle::SearchGrid, int, double, const std::string&, const std::string&)
{
  throw ComputationError("search --score fem-sds runs in rollcheck-fem");
}
} // namespace rollcheck::cli
