// `rollcheck batch CASES... [-j N] [--out DIR] [--force]`: runs case files on
// worker processes (and MPI ranks under mpirun) into one results store,
// skipping cases already done. src/io/batch_run.h has the design.
#include "cli/cli.h"
#include "cli/option_checks.h"
#include "cli/scenes.h"
#include "io/batch_progress.h"

namespace rollcheck::cli
{
io::BatchResult run_scene_batch(const io::BatchSettings& options)
{
  const io::BatchResult result = io::run_batch(options, [](const std::string& kind, const std::string& origin)
                                                   -> const io::Schema& { return *find_scene(kind, origin).schema; });
  if (result.coordinator)
    io::print_batch_table(result, summary_stream());
  return result;
}

void add_batch_command(CLI::App& app)
{
  static io::BatchSettings options;
  CLI::App* sub = add_command(
      app, "batch", "Run case files on worker processes (and MPI ranks) into one HDF5 results store; resumable", [] {
        const io::BatchResult result = run_scene_batch(options);
        return result.coordinator ? CommandResult{result.to_json(), result.exit_code()} : CommandResult{};
      });
  sub->add_option("cases", options.cases, "Case files (.toml), folders of them, or quoted globs")->required();
  sub->add_option("-j,--jobs", options.jobs,
                  "Worker processes per MPI rank (default: 0 = one per CPU: the CPUs mpirun bound the rank to, else the "
                  "node's CPUs shared among its ranks)")
      ->check(CLI::Range(0, 1024));
  sub->add_option("--out", options.out,
                  "Results folder: cases/<hash>/ per case, results.h5 for all (default: results)")
      ->check(non_empty());
  sub->add_flag("--force", options.force, "Recompute cases already done (default: reuse their results)");
  sub->add_option("--timeout", options.case_timeout_s,
                  "A case running longer than this fails [s] (default: 0 = no limit)")
      ->check(finite_number() & CLI::Range(0.0, 1e7));
}
} // namespace rollcheck::cli
