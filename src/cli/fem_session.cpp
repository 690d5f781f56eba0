// The process around the command line in rollcheck-fem, the executable with
// the FEM libraries (cli.h ProcessSession): MPI for the subcommands that need
// it, PETSc's options and its end, and the FEM subcommands.
#include "cli/cli.h"
#include "core/error.h"
#include "core/mpi_launch.h"
#include "fem/first_failure.h"
#include "fem/petsc_session.h"
#include "geometry/tetrahedralize.h"
#include "study/loop_scores/fem_sds_family.h"
#include <algorithm>
#include <cstdlib>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <mpi.h>
#include <petscsys.h>
#include <spdlog/spdlog.h>

namespace rollcheck::cli
{
namespace
{
/// The ranks' own communicator for shared_outcome(): a failed rank's last
/// collective call must not match a call the others make inside a solver.
MPI_Comm outcome_comm = MPI_COMM_NULL;

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

/// Whether the command line needs MPI before its input is read: every
/// subcommand but the fast ones and `run` (start_mpi, once its case file is
/// read), and anything a launcher (mpirun) started.
bool needs_mpi(const std::vector<std::string>& args)
{
  const std::string subcommand = subcommand_in(args);
  return launched_by_mpi() || (!subcommand.empty() && subcommand != "run" && !fast_command(args));
}

void init_mpi(int* argc, char*** argv)
{
  prefer_isolated_mpi_singleton();
  int provided;
  MPI_Init_thread(argc, argv, MPI_THREAD_FUNNELED, &provided);
  MPI_Comm_dup(MPI_COMM_WORLD, &outcome_comm);
}

/// The command line needs MPI, which the session has put off
/// (start_deferred_mpi).
bool mpi_deferred = false;
} // namespace

/// MPI is started for the scenes that need it (FEM solves, batches spread
/// over ranks; a case file's scene once it is read, start_mpi) or when a
/// launcher started this process; the others start without it. Only under
/// a launcher does it start here: otherwise once the subcommand's options
/// are checked (start_deferred_mpi), as a refused option, about half of a
/// refusal's 0.4 s, needs none. PETSc is started by whoever needs it and
/// ended here.
ProcessSession::ProcessSession(int& argc, char**& argv, const std::vector<std::string>& args)
{
  if (launched_by_mpi())
    init_mpi(&argc, &argv);
  else
    mpi_deferred = needs_mpi(args);
}

void start_deferred_mpi()
{
  if (mpi_deferred)
    start_mpi();
  mpi_deferred = false;
}

void start_mpi()
{
  int initialized = 0;
  MPI_Initialized(&initialized);
  if (!initialized)
    init_mpi(nullptr, nullptr);
}

ProcessSession::~ProcessSession()
{
  int initialized = 0;
  MPI_Initialized(&initialized);
  if (!initialized)
    return;
  if (outcome_comm != MPI_COMM_NULL)
    MPI_Comm_free(&outcome_comm);
  PetscBool petsc_running = PETSC_FALSE;
  PetscInitialized(&petsc_running);
  if (petsc_running)
  {
    warn_unused_petsc_options();
    PetscFinalize();
  }
  // PETSc ends MPI itself when it started it (PETSc options on a command line
  // that needs no MPI, `mesh -- -foo`): MPI may be ended only once.
  int finalized = 0;
  MPI_Finalized(&finalized);
  if (!finalized)
    MPI_Finalize();
}

void add_fem_commands(CLI::App& app)
{
  add_hertz_command(app);
  add_fem_sds_command(app);
  add_crease_command(app);
  add_rim_command(app);
  add_flat_rim_command(app);
  add_rounded_end_command(app);
  add_run_command(app);
  add_batch_command(app);
  add_validate_command(app);
  add_whole_body_command(app);
  add_life_command(app);
}

void insert_petsc_options(std::vector<std::string> options)
{
  if (options.empty())
    return;
  if (!options.front().starts_with('-'))
    throw InputError(fmt::format("after `--` come PETSc options (-name [value] ...), got '{}'", options.front()));
  start_deferred_mpi(); // before PETSc, which would start MPI itself otherwise
  fem::ensure_petsc();
  std::vector<char*> argv;
  for (std::string& option : options)
    argv.push_back(option.data());
  if (PetscOptionsInsertArgs(nullptr, static_cast<int>(argv.size()), argv.data()) != 0)
    throw InputError(fmt::format("cannot read the PETSc options after `--`: {}", fmt::join(options, " ")));
}

std::pair<int, std::string> shared_outcome(int exit_code, const std::string& error)
{
  if (outcome_comm == MPI_COMM_NULL)
    return {exit_code, error};
  const std::optional<fem::RankFailure> first = fem::first_failure(outcome_comm, exit_code, error);
  if (!first || first->rank == process_rank())
    return {exit_code, error};
  return {first->exit_code, first->message.empty() ? "" : fmt::format("{} (on rank {})", first->message, first->rank)};
}

nlohmann::json write_volume_mesh(const geometry::SurfaceMesh& surface, double mesh_size_m,
                                 const std::filesystem::path& path)
{
  const geometry::VolumeMeshInfo info = geometry::write_tetrahedral_mesh(surface, mesh_size_m, path);
  return {{"nodes", info.nodes}, {"tetrahedra", info.tetrahedra}};
}

std::function<double(const geometry::BodySpec&)> fem_sds_family_scorer(
    bool continuum, std::shared_ptr<std::vector<std::string>> statuses)
{
  using study::loop_scores::FemSdsValue;
  return study::loop_scores::fem_sds_scorer(MPI_COMM_WORLD, study::loop_scores::FemSdsSettings{},
                                            continuum ? FemSdsValue::continuum : FemSdsValue::face_template,
                                            std::move(statuses));
}
} // namespace rollcheck::cli
