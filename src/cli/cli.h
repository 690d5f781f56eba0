#pragma once
// Layer: cli. Owns the `rollcheck` executable: one file per subcommand, each
// exposing add_<name>_command(). Subcommands parse options, call the layers
// below and write results; they hold no physics of their own.
#include "core/process_rank.h"
#include "io/batch_run.h"
#include "io/parameters.h"
#include <cstdio>
#include <CLI/CLI.hpp>
#include <filesystem>
#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

namespace rollcheck::geometry
{
struct SurfaceMesh;
struct BodySpec;
} // namespace rollcheck::geometry

namespace rollcheck::cli
{
/// The subcommand the arguments name ("" if none): the first argument that is
/// not an option, since rollcheck's own options take no values.
std::string subcommand_in(const std::vector<std::string>& args);

/// Whether the command line is one of the fast subcommands (mesh, oracle,
/// search, optimize, report, audit) without FEM-SDS scores, outside mpirun:
/// what needs neither MPI nor the FEM libraries.
bool fast_command(const std::vector<std::string>& args);

/// What the executable runs around the command line. Two executables share
/// every other file of this layer: rollcheck-fem (fem_session.cpp), with the
/// FEM libraries, starts MPI where a subcommand needs it and ends PETSc and
/// MPI; rollcheck (light_session.cpp) loads no FEM library, runs the fast
/// subcommands itself and replaces its process with rollcheck-fem, beside it,
/// for every other command line.
class ProcessSession
{
public:
  ProcessSession(int& argc, char**& argv, const std::vector<std::string>& args);
  ~ProcessSession();
  ProcessSession(const ProcessSession&) = delete;
  ProcessSession& operator=(const ProcessSession&) = delete;
};

/// The subcommands of the executable's session beyond the fast ones (none in rollcheck).
void add_fem_commands(CLI::App& app);

/// MPI for a command that knows it needs it only once its input is read
/// (`run`: a case file's scene; not `run --template` or a rejected file),
/// started here unless the session already has it (rollcheck-fem).
void start_mpi();

/// MPI for a subcommand whose session put it off until the command line was
/// checked (rollcheck-fem, not started by a launcher): a subcommand's own
/// options once parsed and bound, so that a refused one costs no MPI start.
/// Does nothing where MPI runs already or the command needs none.
void start_deferred_mpi();

/// PETSc's options, the arguments after `--` (rollcheck-fem).
void insert_petsc_options(std::vector<std::string> options);

// What the fast subcommands reach only in rollcheck-fem. Each has a
// definition for either executable: rollcheck's refuses (it hands such
// command lines to rollcheck-fem before they get here).

/// The command's outcome on every rank: this rank's exit code and error line,
/// or, when another rank failed, the lowest failing rank's (fem/first_failure.h),
/// so that a write that failed on one rank ends every rank with its exit code
/// and the file named. Collective in rollcheck-fem under MPI (every rank calls
/// it at the same point: where main() maps errors to exit codes, after a
/// write of rank 0 between collective steps); the identity in rollcheck and
/// without MPI.
std::pair<int, std::string> shared_outcome(int exit_code, const std::string& error);

/// `mesh --out FILE.msh`: the gmsh tetrahedral mesh of `surface`, written to
/// `path` ({"nodes", "tetrahedra"} returned).
nlohmann::json write_volume_mesh(const geometry::SurfaceMesh& surface, double mesh_size_m,
                                 const std::filesystem::path& path);

/// `optimize --score fem-sds` (`continuum`) or `fem-sds-template`:
/// study::fem_sds_scorer on MPI_COMM_WORLD with the default FEM-SDS
/// settings, each body's loop status appended to `statuses`.
std::function<double(const geometry::BodySpec&)> fem_sds_family_scorer(
    bool continuum, std::shared_ptr<std::vector<std::string>> statuses);

/// Registers what runs when `sub` was the parsed subcommand. The runner returns
/// the exit code (0 success); it may throw InputError (exit 2) or
/// ComputationError (exit 1), which main() reports.
void on_run(CLI::App* sub, std::function<int()> runner);

/// InputError naming `name` if `app` has no subcommand of that name (none
/// given is left to the parser), with the closest name when it is a typo away.
void check_subcommand(const CLI::App& app, const std::string& name);

/// Calls the runner of the subcommand `app` parsed; its exit code.
int run_parsed(const CLI::App& app);

/// Adds the shared `--json PATH` option ("-" for stdout) to a subcommand.
CLI::Option* add_json_option(CLI::App* sub, std::string& path);

/// Writes `summary` to `path` when it is non-empty ("-" is stdout), atomically.
void emit_json(const std::string& path, const nlohmann::json& summary);

/// Prints a subcommand's result summary, a short table, on rank 0: to stdout,
/// which holds results only (logs go to stderr); when `--json -` has stdout,
/// the summary goes to the log instead, so that stdout stays JSON alone.
void print_summary(const std::string& text);

/// Whether this run's --json writes to stdout (add_command sets it).
void set_json_on_stdout(bool on_stdout);

/// Where a subcommand prints its result table: stdout, or stderr when
/// `--json -` has stdout (so that stdout is one JSON document).
std::FILE* summary_stream();

/// InputError naming the first option in `args` (before any `--`) that neither
/// the subcommand they name nor the executable has, with the closest known
/// option when it is a typo away; nothing when every option is known.
void check_options(const CLI::App& app, const std::vector<std::string>& args);

/// How a command ends: the summary its --json option writes (null: nothing
/// to write, as on a rank that holds no outcome) and the exit code.
struct CommandResult
{
  nlohmann::json summary;
  int exit_code = 0;
};

/// A subcommand with the shared --json option whose `run` is called after
/// parsing, its summary written to --json. Returns the subcommand, for the
/// options of its own. MPI, where the session put it off, starts before
/// `run` unless `checks_input_before_mpi`: then `run` starts it
/// (start_deferred_mpi) once its input is checked.
CLI::App* add_command(CLI::App& app, const std::string& name, const std::string& description,
                      std::function<CommandResult()> run, bool checks_input_before_mpi = false);

/// A scene's JSON summary from its resolved parameters.
using SceneRun = std::function<nlohmann::json(const io::Parameters&)>;

/// A subcommand that runs a scene: one option per parameter of `schema`, the
/// --json option, and the scene registered for case files (`rollcheck run`,
/// batch). The subcommand runs `command` if one is given (hertz's --study),
/// else `run`; case files always run `run`. Returns the subcommand, for the
/// options of its own.
CLI::App* add_scene_command(CLI::App& app, const std::string& name, const std::string& description,
                            const io::Schema& schema, SceneRun run, SceneRun command = {});

/// How an output parameter of a scene is written: a file (its folder must
/// exist) or a folder output (--out: created; new, empty or rollcheck's,
/// core/output_manifest.h).
enum class OutputKind
{
  file,
  folder
};
struct SceneOutput
{
  std::string key; ///< the parameter holding the path ("" in it: no output)
  OutputKind kind;
};

/// Declares the output parameters of the scene of `schema`: they are checked
/// (core/atomic_file.h) before the scene computes anything, whether it runs
/// from its options or from a case file.
void declare_outputs(const io::Schema& schema, std::vector<SceneOutput> outputs);

/// InputError naming the option and the path for a declared output of
/// `params` that cannot be written; called before the scene runs.
void check_scene_outputs(const io::Schema& schema, const io::Parameters& params);

/// Runs a batch of case files against the registered scenes (the batch and
/// validate subcommands); the coordinator prints its table.
io::BatchResult run_scene_batch(const io::BatchSettings& options);

void add_mesh_command(CLI::App& app);
void add_oracle_command(CLI::App& app);
void add_search_command(CLI::App& app);
void add_hertz_command(CLI::App& app);
void add_fem_sds_command(CLI::App& app);
void add_crease_command(CLI::App& app);
void add_rim_command(CLI::App& app);
void add_flat_rim_command(CLI::App& app);
void add_rounded_end_command(CLI::App& app);
void add_optimize_command(CLI::App& app);
void add_run_command(CLI::App& app);
void add_batch_command(CLI::App& app);
void add_report_command(CLI::App& app);
void add_audit_command(CLI::App& app);
void add_validate_command(CLI::App& app);
void add_whole_body_command(CLI::App& app);
void add_robustness_command(CLI::App& app);
void add_life_command(CLI::App& app);
} // namespace rollcheck::cli
