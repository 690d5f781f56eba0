// `rollcheck robustness`: every headline comparison of bodies over the grid
// of modelling choices, with resolution-free scores and a verdict each
// (study/robustness/robustness.h). Prints the verdict table; --json writes
// the grid, the comparisons and every body's scores per cell.
#include "cli/text_output.h"
#include "io/work_budget.h"
#include "study/robustness/robustness.h"

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
        return run_with_markdown(markdown_path, [] {
          const study::robustness::RobustnessResult result = study::robustness::run_robustness(settings);
          return std::pair{study::robustness::to_json(result), study::robustness::markdown_report(result)};
        });
      });
  sub->add_option("--samples-per-loop", settings.samples_per_loop,
                  "Samples of each rolling loop (default: 8000)")
      ->check(CLI::Range(static_cast<long>(io::loop_samples.lower), static_cast<long>(io::loop_samples.upper)));
  sub->add_option("--pieces", settings.pieces, "Gauss pieces along each ruling (default: 64)")
      ->check(CLI::Range(4, 1024));
  sub->add_option("--family-samples-per-loop", settings.family_samples_per_loop,
                  "Samples of each rolling loop of the quick grid's genomes (default: 4000)")
      ->check(CLI::Range(static_cast<long>(io::loop_samples.lower), static_cast<long>(io::loop_samples.upper)));
  sub->add_option("--markdown", markdown_path, "Also write the verdict table as Markdown to PATH (default: none)");
}
} // namespace rollcheck::cli
