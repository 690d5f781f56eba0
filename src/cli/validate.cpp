// `rollcheck validate`: the main job. Runs the default batch (cases/default/,
// two workers) into results/, checks every case against the tolerances and
// references its case file states ([[check]]), prints the verdict table,
// writes validation.json and the report (verdicts first), and exits 1 when a
// check fails.
#include "cli/cli.h"
#include "cli/option_checks.h"
#include "core/atomic_file.h"
#include "core/data_folder.h"
#include "io/batch_report.h"
#include "io/batch_validation.h"
#include <fstream>
#include "rollcheck_version.h"
#include <fmt/format.h>

namespace rollcheck::cli
{
void add_validate_command(CLI::App& app)
{
  static std::string audit_json;
  static io::BatchSettings options = [] {
    io::BatchSettings o;
    o.cases = {(data_folder() / "cases" / "default").string()};
    o.out = "results";
    o.jobs = 2;
    // Each default case is sized to finish in well under this; one that hangs
    // must not keep the main job from its report.
    o.case_timeout_s = 600;
    return o;
  }();
  CLI::App* sub = add_command(
      app, "validate", "The main job: run the default cases (cases/default) as a batch and write the report", [] {
        const io::BatchResult batch = run_scene_batch(options);
        if (!batch.coordinator)
          return CommandResult{};
        nlohmann::json summary = batch.to_json();
        summary["rollcheck_version"] = ROLLCHECK_VERSION;
        const std::vector<io::CaseVerdict> verdicts = io::check_batch(batch, options.out);
        const nlohmann::json validation = io::to_json(verdicts);
        summary["validation"] = validation;
        const std::filesystem::path validation_file = options.out / "validation.json";
        write_atomically(validation_file, [&](const std::filesystem::path& tmp) { std::ofstream(tmp) << validation.dump(2); });
        fmt::print("\n{}\n{} checks passed, {} failed\n", io::verdict_table(verdicts), validation["passed"].get<int>(),
                   validation["failed"].get<int>());
        if (!batch.interrupted)
        {
          const io::ReportFiles report = io::write_report(batch.store, options.out / "report",
                                                          io::default_scripts_folder(), "/usr/bin/python3",
                                                          validation_file, audit_json);
          summary["report"] = {{"html", report.html.string()}, {"markdown", report.markdown.string()}};
          fmt::print("report: {}\nmarkdown: {}\n", report.html.string(), report.markdown.string());
        }
        const int failed_checks = validation["failed"].get<int>();
        return CommandResult{summary, batch.exit_code() != 0 ? batch.exit_code() : failed_checks > 0 ? 1 : 0};
      });
  sub->add_option("--cases", options.cases[0], "Folder of case files (default: cases/default of the installed or source tree)");
  sub->add_option("--out", options.out, "Results folder, results.h5, validation.json and report/ (default: results/ in the working folder)");
  sub->add_option("-j,--jobs", options.jobs, "Worker processes per MPI rank (default: 2)")
      ->check(CLI::Range(0, 1024));
  sub->add_option("--audit", audit_json,
                  "JSON of `rollcheck audit --json PATH`, shown in the report after the verdicts (default: none)")
      ->check(CLI::ExistingFile);
  sub->add_flag("--force", options.force, "Recompute cases already done (default: reuse their results)");
  sub->add_option("--timeout", options.case_timeout_s, "A case running longer than this fails [s] (default: 600)")
      ->check(finite_number() & CLI::Range(0.0, 1e7));
}
} // namespace rollcheck::cli
