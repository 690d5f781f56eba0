// `rollcheck batch CASES... [-j N] [--out DIR] [--force]`: runs case files on
// worker processes (and MPI ranks under mpirun) into one results store,
// skipping cases already done. src/io/batch_run.h has the design.
#include "cli/cli.h"
#include "cli/scenes.h"
#include "io/batch_progress.h"
#include "io/batch_run.h"

namespace rollcheck::cli
{
void add_batch_command(CLI::App& app)
{
  CLI::App* sub = app.add_subcommand(
      "batch", "Run case files on worker processes (and MPI ranks) into one HDF5 results store; resumable");
  static io::BatchOptions options;
  static std::string json_path;
  sub->add_option("cases", options.cases, "Case files (.toml), folders of them, or quoted globs")->required();
  sub->add_option("-j,--jobs", options.jobs,
                  "Worker processes per MPI rank (default: 0 = one per CPU: the CPUs mpirun bound the rank to, else the "
                  "node's CPUs shared among its ranks)");
  sub->add_option("--out", options.out,
                  "Results folder: cases/<hash>/ per case, results.h5 for all (default: results)");
  sub->add_flag("--force", options.force, "Recompute cases already done (default: reuse their results)");
  sub->add_option("--timeout", options.case_timeout_s,
                  "A case running longer than this fails [s] (default: 0 = no limit)");
  add_json_option(sub, json_path);
  on_run(sub, [] {
    const io::BatchResult result = io::run_batch(options, [](const std::string& kind, const std::string& origin)
                                                     -> const io::Schema& { return *find_scene(kind, origin).schema; });
    if (!result.coordinator)
      return 0;
    io::print_batch_table(result, stdout);
    emit_json(json_path, result.to_json());
    return result.exit_code();
  });
}
} // namespace rollcheck::cli
