// `rollcheck report --from STORE`: the Markdown and HTML report of a results
// store, with the plots of postprocess/ (docs/guide/report.md).
#include "cli/cli.h"
#include "io/batch_report.h"
#include "io/report_json_inputs.h"
#include "io/results_store_check.h"
#include <fmt/format.h>

namespace rollcheck::cli
{
void add_report_command(CLI::App& app)
{
  static std::string store, folder, validation, audit, robustness, life;
  static std::string scripts = io::default_scripts_folder().string();
  static std::string python = "/usr/bin/python3";
  CLI::App* sub = add_command(
      app, "report", "Write the Markdown + HTML report (plots, tables) of a results store", [] {
        const std::filesystem::path target = folder.empty()
                                                 ? std::filesystem::absolute(store).parent_path() / "report"
                                                 : std::filesystem::path(folder);
        io::require_results_store(store, "option --from");
        io::require_report_json_inputs({validation, audit, robustness, life}, "report");
        const io::ReportFiles report =
            io::write_report(store, target, scripts, python, validation, audit, robustness, life);
        print_summary(fmt::format("report: {}\nmarkdown: {}\n", report.html.string(), report.markdown.string()));
        return CommandResult{{{"html", report.html.string()}, {"markdown", report.markdown.string()}}};
      });
  sub->add_option("--from", store, "Results store written by `rollcheck batch` (DIR/results.h5)")->required();
  sub->add_option("--out", folder, "Report folder, replaced whole (default: 'report' beside the store)");
  sub->add_option("--scripts", scripts, "Folder of the plotting scripts (default: postprocess/ of the installed or source tree)");
  sub->add_option("--validation", validation,
                  "Checks JSON written by `rollcheck validate` (results/validation.json), shown first (default: none)");
  sub->add_option("--audit", audit, "JSON of `rollcheck audit --json PATH`, shown as the claim table (default: none)");
  sub->add_option("--robustness", robustness,
                  "JSON of `rollcheck robustness --json PATH`: the headline's ranges over the modelling choices "
                  "(default: none)");
  sub->add_option("--life", life,
                  "JSON of `rollcheck life --json PATH`: the fatigue-life section, its figure and tables (default: none)");
  sub->add_option("--python", python, "Python with matplotlib and h5py (default: Debian's /usr/bin/python3)");
}
} // namespace rollcheck::cli
