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
#include "io/report_json_inputs.h"
#include "io/batch_validation.h"
#include "core/error.h"
#include "rollcheck_version.h"
#include <fstream>
#include <fmt/format.h>

namespace rollcheck::cli
{
namespace
{
constexpr const char* validation_name = "validation.json";

/// A validation.json of a rollcheck before manifests: its three keys.
bool written_by_validate(const std::filesystem::path& path)
{
  std::ifstream in(path);
  const nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
  return j.is_object() && j.size() == 3 && j.contains("checks") && j.contains("passed") && j.contains("failed");
}

/// What validate writes besides the batch's own, checked before any case
/// runs: validation.json (replaced only if rollcheck wrote it), report/ (a
/// folder output) and the audit and robustness JSON the report reads.
void check_validate_outputs(const std::filesystem::path& out, const std::string& audit_json,
                            const std::string& robustness_json, const std::string& life_json)
{
  io::require_report_json_inputs({{}, audit_json, robustness_json, life_json}, "validate");
  check_output_location(out, "validate --out");
  if (!written_by_validate(out / validation_name))
    check_output_entries(out, {validation_name}, "validate --out");
  if (std::filesystem::is_directory(out))
    check_output_folder(out / "report", "validate --out");
}
} // namespace

void add_validate_command(CLI::App& app)
{
  static std::string audit_json, robustness_json, life_json;
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
        check_validate_outputs(options.out, audit_json, robustness_json, life_json);
        const io::BatchResult batch = run_scene_batch(options);
        if (!batch.coordinator)
          return CommandResult{};
        nlohmann::json summary = batch.to_json();
        summary["rollcheck_version"] = ROLLCHECK_VERSION;
        const std::vector<io::CaseVerdict> verdicts = io::check_batch(batch, options.out);
        const nlohmann::json validation = io::to_json(verdicts);
        summary["validation"] = validation;
        const std::filesystem::path validation_file = options.out / validation_name;
        claim_outputs(options.out, {validation_name});
        write_file_atomically(validation_file, validation.dump(2) + "\n");
        print_summary(fmt::format("\n{}\n{} checks passed, {} failed\n", io::verdict_table(verdicts),
                                  validation["passed"].get<int>(), validation["failed"].get<int>()));
        if (!batch.interrupted)
        {
          const io::ReportFiles report = io::write_report(batch.store, options.out / "report",
                                                          io::default_scripts_folder(), "/usr/bin/python3",
                                                          validation_file, audit_json, robustness_json, life_json);
          summary["report"] = {{"html", report.html.string()}, {"markdown", report.markdown.string()}};
          print_summary(fmt::format("report: {}\nmarkdown: {}\n", report.html.string(), report.markdown.string()));
        }
        const int failed_checks = validation["failed"].get<int>();
        return CommandResult{summary, batch.exit_code() != 0 ? batch.exit_code() : failed_checks > 0 ? 1 : 0};
      });
  sub->add_option("--cases", options.cases[0], "Folder of case files (default: cases/default of the installed or source tree)");
  sub->add_option("--out", options.out, "Results folder, results.h5, validation.json and report/ (default: results/ in the working folder)");
  sub->add_option("-j,--jobs", options.jobs, "Worker processes per MPI rank (default: 2)")
      ->check(CLI::Range(0, 1024));
  sub->add_option("--robustness", robustness_json,
                  "JSON of `rollcheck robustness --json PATH`, the headline's ranges in the report (default: none)")
      ->check(CLI::ExistingFile);
  sub->add_option("--life", life_json,
                  "JSON of `rollcheck life --json PATH`, the fatigue-life section of the report (default: none)")
      ->check(CLI::ExistingFile);
  sub->add_option("--audit", audit_json,
                  "JSON of `rollcheck audit --json PATH`, shown in the report after the verdicts (default: none)")
      ->check(CLI::ExistingFile);
  sub->add_flag("--force", options.force, "Recompute cases already done (default: reuse their results)");
  sub->add_option("--timeout", options.case_timeout_s, "A case running longer than this fails [s] (default: 600)")
      ->check(finite_number() & CLI::Range(0.0, 1e7));
}
} // namespace rollcheck::cli
