// `rollcheck robustness`: every headline comparison of bodies over the grid
// of modelling choices, with resolution-free scores and a verdict each
// (study/robustness/robustness.h). Logs the verdict table; --json writes
// the grid, the comparisons and every body's scores per cell.
#include "cli/cli.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "study/robustness/robustness.h"
#include <fmt/format.h>
#include <fstream>
#include <spdlog/spdlog.h>

namespace rollcheck::cli
{
void add_robustness_command(CLI::App& app)
{
  static study::robustness::RobustnessSettings settings;
  static std::string markdown_path;
  CLI::App* sub = add_command(
      app, "robustness",
      "Every headline comparison of bodies (oloid, cylinder, the preprint's body, the family's optima) over the "
      "modelling choices (rolling energy, contact width, load rule, end margin) with resolution-free scores: "
      "a verdict each, robust or the choice it depends on",
      [] {
        if (!markdown_path.empty())
          check_output_file(markdown_path, "option --markdown");
        const study::robustness::RobustnessResult result = study::robustness::run_robustness(settings);
        const std::string table = study::robustness::markdown_report(result);
        if (!markdown_path.empty())
          write_atomically(markdown_path, [&](const std::filesystem::path& tmp) {
            std::ofstream out(tmp);
            out << table;
            if (!out)
              throw ComputationError(fmt::format("option --markdown: cannot write '{}'", markdown_path));
          });
        print_summary(table);
        return CommandResult{study::robustness::to_json(result), 0};
      });
  sub->add_option("--samples-per-loop", settings.samples_per_loop,
                  "Samples of each rolling loop (default: 8000)")
      ->check(CLI::Range(200L, 200000L));
  sub->add_option("--pieces", settings.pieces, "Gauss pieces along each ruling (default: 64)")
      ->check(CLI::Range(4, 1024));
  sub->add_option("--family-samples-per-loop", settings.family_samples_per_loop,
                  "Samples of each rolling loop of the quick grid's genomes (default: 4000)")
      ->check(CLI::Range(200L, 200000L));
  sub->add_option("--markdown", markdown_path, "Also write the verdict table as Markdown to PATH (default: none)");
}
} // namespace rollcheck::cli
