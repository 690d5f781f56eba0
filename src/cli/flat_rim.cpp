// `rollcheck flat-rim`: a rounded rim end whose rim is nearly flat, in 3D by
// half-space theory on the ball-rounded surface (study/rims/flat_rim_contact.h),
// level by level: the finished oloid at a vertex orientation (c = 1/4), where
// the ruling's largest line load meets the sheet's apex, against what
// `rim --body` takes there (line Hertz at R = r_e); or, with
// --interior-angle, a straight rim across a flattened sheet, `rim`'s one end,
// to check the reduction against the FEM. Also the scene "flat-rim".
#include "cli/cli.h"
#include "cli/scenes.h"
#include "study/rims/flat_rim_contact.h"
#include "core/progress_beat.h"
#include <numbers>
#include <nlohmann/json.hpp>
#include <spdlog/spdlog.h>

namespace rollcheck::cli
{
namespace
{
const SceneSchema<study::rims::FlatRimSettings>& flat_rim_schema()
{
  using S = study::rims::FlatRimSettings;
  return kept_schema<S>("flat-rim",
                        "A rounded rim end whose rim is nearly flat, in 3D by half-space theory on the ball-rounded "
                        "surface, rigid or steel counter-face, several grid levels: the finished oloid at a vertex "
                        "orientation (the ruling's largest line load at the sheet's apex), or a straight rim of 150-180 "
                        "deg across a flattened sheet (rim's one end)",
                        [](auto& s) {
    s.include(line_contact_body_schema(), [](S& settings) -> geometry::BodySpec& { return settings.body; });
    s.real("normal_load_n", "--load", &S::normal_load_n, "N",
              "Force F pressing the body onto the counter-face through its centre of mass (rim --body's)",
              io::positive)
        .real("end_angle_deg", "--end-angle", &S::end_angle_rad, "deg",
              "The body's loop orientation whose loaded end has this interior angle (150-180 deg; 180: the loop's "
              "flattest end, the oloid's vertex, c = 1/4; below it on the loop's side --side from there)",
              io::Bounds{150, 180}, std::numbers::pi / 180)
        .choice("loop_side", "--side", &S::loop_side,
                "With --end-angle below the flattest: the orientation walking the loop forwards or backwards from "
                "its flattest end (the oloid's two are mirror images; rim --body's flat-rim table solves both)",
                {{"forward", 0}, {"backward", 1}})
        .real("interior_angle_deg", "--interior-angle", &S::interior_angle_rad, "deg",
              "0: the body's loop end (--end-angle). Else a straight rim of this interior angle (150-180 deg: the rim's other face "
              "leans by 180 deg - a) across a sheet of radius R, flattened with its profile in the gap: `rim`'s one end",
              io::Bounds{0, 180, false, false}, std::numbers::pi / 180)
        .real("sheet_radius_m", "--sheet-radius", &S::sheet_radius_m, "m",
              "With --interior-angle: R, the sheet's radius across the ruling", io::positive)
        .real("load_n_per_m", "--load-per-length", &S::load_n_per_m, "N/m",
              "With --interior-angle: q, the line load along the ruling", io::positive)
        .real("edge_radius_m", "--edge-radius", &S::edge_radius_m, "m",
              "r_e of the finish: the hull rounded by a ball of r_e rolled inside it (rim --body's)", io::positive)
        .choice("counter_face", "--counter-face", &S::steel_counter_face,
                "What the body presses on: rigid (the frictionless rigid plane) or steel (a half-space of the "
                "body's own material, frictionless)",
                {{"rigid", false}, {"steel", true}});
    add_material(s, &S::youngs_modulus_pa, &S::poisson_ratio);
    s.real("cells_per_half_width", "--cells", &S::cells_per_half_width, "",
           "Cells across b (line Hertz's half-width at the end's q with R = max(R_end, r_e); the oloid's apex: r_e) at the first level; each level doubles it",
           io::Bounds{2, 64})
        .integer("levels", "--levels", &S::levels, "", "Grid levels (convergence needs 2)", io::Bounds{1, 4})
        .integer("extra_levels", "--extra-levels", &S::extra_levels, "",
                 "Levels beyond --levels, added one at a time while the peak changes by --tolerance or more "
                 "between the last two (rim --body's flat-rim table adds one)",
                 io::Bounds{0, 2})
        .real("before_over_half_width", "--before", &S::before_over_half_width, "",
              "The window beyond the end (past the ruling's end), in b", io::Bounds{1, 200})
        .real("after_over_half_width", "--after", &S::after_over_half_width, "",
              "The window along the ruling from the end, in b; the ruling's line load is prescribed beyond it",
              io::Bounds{5, 1000})
        .real("across_over_half_width", "--across", &S::across_over_half_width, "",
              "The window's half-width across the ruling, in b", io::Bounds{1.5, 100})
        .flag("whole_ruling", "--whole-ruling", &S::whole_ruling,
              "A body's end: solve its whole loaded ruling in one grid (F at the centre of mass's foot by the tilt "
              "alone) instead of the window and the rule beyond it; --after is not used, no longer window is "
              "solved (rim --body's flat-rim table takes it for a side whose shortened window does not converge)")
        .real("tolerance", "--tolerance", &S::tolerance, "",
              "Largest change of the peak between the last two levels, and when the first level's window doubles, that counts as converged",
              io::Bounds{0, 1, true, false});
  });
}

nlohmann::json run_flat_rim(const io::Parameters& p)
{
  const study::rims::FlatRimSettings setup = flat_rim_schema().bind(p);
  ProgressBeat beat("flat-rim", process_rank() == 0);
  const study::rims::FlatRimContact r
      = study::rims::flat_rim_contact(setup, [&](const std::string& what) { beat.step(what); });
  print_summary(study::rims::report(setup, r));
  nlohmann::json j = to_json(r);
  j["counter_face"] = setup.steel_counter_face ? "steel" : "rigid";
  j["edge_radius_m"] = setup.edge_radius_m;
  j["normal_load_n"] = setup.normal_load_n;
  j["body"] = setup.body.body;
  j["radius_m"] = setup.body.radius_m;
  j["interior_angle_deg"] = setup.interior_angle_rad * 180 / std::numbers::pi;
  j["peak_over_line_hertz"] = r.levels.back().peak_pressure_pa / r.line_hertz_peak_pa;
  return j;
}
} // namespace

void add_flat_rim_command(CLI::App& app) { add_scene_command(app, flat_rim_schema(), run_flat_rim); }
} // namespace rollcheck::cli
