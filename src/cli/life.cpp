// `rollcheck life`: does the oloid live longer? Rolling-contact fatigue life
// from the subsurface stress over the loop (study/life/life_study.h): the FEM
// slice's subsurface stress against the closed form, the load-life exponent,
// and the L10 life ratios of the bodies against the cylinder at the same
// load and steel over the modelling choices, each with a verdict. Prints the
// table; --json writes everything, --markdown the table.
#include "cli/text_output.h"
#include "io/work_budget.h"
#include "study/life/life_study.h"

namespace rollcheck::cli
{
void add_life_command(CLI::App& app)
{
  static study::life::LifeSettings settings;
  static std::string markdown_path;
  CLI::App* sub = add_command(
      app, "life",
      "Rolling-contact fatigue life over the loop (Lundberg-Palmgren, Ioannides-Harris; Dang Van check) from the "
      "subsurface stress, FEM-checked against the closed form: L10 life ratios of the bodies against the cylinder "
      "at 100 N, 5000 N and the cylinder's 1.5 GPa load over the modelling choices, a verdict each",
      [] {
        return run_with_markdown(markdown_path, [] {
          const study::life::LifeResult result = study::life::run_life(settings);
          return std::pair{study::life::to_json(result), study::life::markdown_report(result)};
        });
      });
  sub->add_option("--samples-per-loop", settings.samples_per_loop, "Samples of each rolling loop (default: 4000)")
      ->check(CLI::Range(static_cast<long>(io::loop_samples.lower), static_cast<long>(io::loop_samples.upper)));
  sub->add_option("--pieces", settings.pieces, "Gauss pieces along each ruling (default: 32)")->check(CLI::Range(1, 1024));
  sub->add_option("--refines", settings.subsurface.refines,
                  "Contact-zone refinements of the FEM slice's subsurface check, coarse to fine (default: 2 4 6)")
      ->check(CLI::Range(0, 10));
  sub->add_option("--degree", settings.subsurface.degree,
                  "Lagrange degree of the FEM slice's displacement (default: 2; P1's shear stays biased under refinement: docs/methods/life.md)")
      ->check(CLI::Range(1, 2));
  sub->add_option("--edge-radii", settings.rims.edge_radius_over_radius,
                  "Rounded rims: edge radii over the body's radius r1, ascending (default: 0.0025 0.005 0.01 0.02 "
                  "0.04 0.08 0.16)")
      ->check(CLI::Range(1e-6, 10.0));
  sub->add_option("--end-ratios", settings.end_ratios_path,
                  "Rounded rim ends' peak over line Hertz against R / r_e, JSON (default: "
                  "cases/life/rounded_end_ratios.json of the data folder)")
      ->check(CLI::ExistingFile);
  sub->add_option("--markdown", markdown_path, "Also write the comparison table as Markdown to PATH (default: none)");
}
} // namespace rollcheck::cli
