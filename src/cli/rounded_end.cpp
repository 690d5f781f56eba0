// `rollcheck rounded-end` (and the case files' scene "rounded-end"): `rim`'s
// rounded end by half-space theory on a graded grid, level by level
// (study/rims/half_space_end.h): the end/interior ratio of a fillet r_e >> b
// in seconds, where the FEM end model takes minutes to hours.
#include "cli/cli.h"
#include "cli/scenes.h"
#include "core/process_rank.h"
#include "core/progress_beat.h"
#include "study/rims/half_space_end.h"
#include <fmt/format.h>
#include <nlohmann/json.hpp>

namespace rollcheck::cli
{
namespace
{
const SceneSchema<study::rims::HalfSpaceEndSettings>& rounded_end_schema()
{
  using S = study::rims::HalfSpaceEndSettings;
  return kept_schema<S>(
      "rounded-end",
      "A rounded rim end (rim's one end, fillet r_e well above line Hertz's b) by half-space theory on a graded grid, "
      "several levels: its end/interior pressure ratio in seconds; no interior angle (0.6-3.4 % above the FEM's "
      "from 120 deg at r_e >= 20 b)",
      [](auto& s) {
    s.real("sheet_radius_m", "--sheet-radius", &S::sheet_radius_m, "m",
           "R, the contacting sheet's radius across the ruling",
           io::positive)
        .real("load_n_per_m", "--load-per-length", &S::load_n_per_m, "N/m", "q, the line load at the end", io::positive)
        .real("edge_radius_m", "--edge-radius", &S::edge_radius_m, "m", "r_e of the edge's fillet (at least 2 b)",
              io::Bounds{0, 1, true, false})
        .choice("counter_face", "--counter-face", &S::steel_counter_face,
                "What the body presses on: rigid (the frictionless rigid plane) or steel (a half-space of the "
                "body's own material, frictionless)",
                {{"rigid", false}, {"steel", true}});
    add_material(s, &S::youngs_modulus_pa, &S::poisson_ratio);
    s.real("depth_over_half_width", "--depth", &S::depth_over_half_width, "",
           "H / b: the line contact held over this length from its far mirror plane to the end, as the FEM block's "
           "depth (rim --depth); 0: --block-depth r_e",
           io::Bounds{10, 5000, false, false, true})
        .real("depth_over_edge_radius", "--block-depth", &S::depth_over_edge_radius, "",
              "With --depth 0: held over this many edge radii, as rim --body's blocks", io::Bounds{1, 100})
        .integer("levels", "--levels", &S::levels, "",
                 "Grid levels, each halving the finest cells (convergence needs 2)",
                 io::Bounds{1, 4})
        .real("finest_over_layer", "--finest",
              [](S& c) -> double& { return c.grid.finest_over_layer; }, "",
              "The first level's cells about the fillet's start, in units of its boundary layer s = 2 r_e b / (pi R)",
              io::Bounds{0.01, 1})
        .real("across_over_half_width", "--across",
              [](S& c) -> double& { return c.grid.across_over_half_width; }, "",
              "Cells across the contact, in b", io::Bounds{0.01, 0.5})
        .real("tolerance", "--tolerance", &S::tolerance, "",
              "Largest relative change of the end/interior ratio between the last two levels that counts as converged",
              io::Bounds{0, 1, true, false});
  });
}

nlohmann::json run_rounded_end(const io::Parameters& p)
{
  const study::rims::HalfSpaceEndSettings settings = rounded_end_schema().bind(p);
  ProgressBeat beat("rounded-end", process_rank() == 0);
  const auto on_level = [&beat](int level, double finest_m) {
    beat.step(fmt::format("level {} (finest cell {:.3g} m)", level + 1, finest_m));
  };
  const study::rims::HalfSpaceEndStudy study = study::rims::half_space_end(settings, on_level);
  print_summary(study::rims::report(study));
  return study::rims::to_json(study);
}
} // namespace

void add_rounded_end_command(CLI::App& app) { add_scene_command(app, rounded_end_schema(), run_rounded_end); }
} // namespace rollcheck::cli
