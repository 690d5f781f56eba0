// `rollcheck validate`: the main job. Runs the default batch (cases/default/,
// two workers) into results/ and writes the report; prints where it is.
#include "cli/cli.h"
#include "cli/scenes.h"
#include "io/batch_progress.h"
#include "io/batch_report.h"
#include "io/batch_run.h"
#include "rollcheck_version.h"
#include <fmt/format.h>
#include <spdlog/spdlog.h>

namespace rollcheck::cli
{
void add_validate_command(CLI::App& app)
{
  CLI::App* sub = app.add_subcommand(
      "validate", "The main job: run the default cases (cases/default) as a batch and write the report");
  static io::BatchOptions options = [] {
    io::BatchOptions o;
    o.cases = {std::string(ROLLCHECK_SOURCE_DIR) + "/cases/default"};
    o.out = std::string(ROLLCHECK_SOURCE_DIR) + "/results";
    o.jobs = 2;
    // Each default case is sized to finish in well under this; one that hangs
    // must not keep the main job from its report.
    o.case_timeout_s = 600;
    return o;
  }();
  static std::string json_path;
  sub->add_option("--cases", options.cases[0], "Folder of case files (default: the source tree's cases/default)");
  sub->add_option("--out", options.out, "Results folder (default: the source tree's results/)");
  sub->add_option("-j,--jobs", options.jobs, "Worker processes per MPI rank (default: 2)");
  sub->add_flag("--force", options.force, "Recompute cases already done (default: reuse their results)");
  sub->add_option("--timeout", options.case_timeout_s, "A case running longer than this fails [s] (default: 600)");
  add_json_option(sub, json_path);
  on_run(sub, [] {
    const io::BatchResult batch = io::run_batch(options, [](const std::string& kind, const std::string& origin)
                                                    -> const io::Schema& { return *find_scene(kind, origin).schema; });
    if (!batch.coordinator)
      return 0;
    io::print_batch_table(batch, stdout);
    nlohmann::json summary = batch.to_json();
    summary["rollcheck_version"] = ROLLCHECK_VERSION;
    if (!batch.interrupted)
    {
      const io::ReportFiles report = io::write_report(batch.store, options.out / "report",
                                                      io::default_scripts_folder(), "/usr/bin/python3");
      summary["report"] = {{"html", report.html.string()}, {"markdown", report.markdown.string()}};
      fmt::print("report: {}\nmarkdown: {}\n", report.html.string(), report.markdown.string());
    }
    emit_json(json_path, summary);
    return batch.exit_code();
  });
}
} // namespace rollcheck::cli
