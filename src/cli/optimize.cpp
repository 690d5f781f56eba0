// `rollcheck optimize`: where a two-circle roller family's optimum lies, and
// what its (90, 1, 1) member is (gradient, Hessian, verdict), by a continuous
// search with NLopt (docs/methods/optimize.md). Also the scene "optimize" of case
// files. The method and its log line are study/optimize/optimize_family.h;
// here its parameters, the log, the start's and the optimum's meshes, the
// JSON, the plots and the finished runs kept in the output folder for a
// rerun (cli/optimize_runs.h).
#include "cli/cli.h"
#include "cli/optimize_runs.h"
#include "cli/scenes.h"
#include "core/atomic_file.h"
#include "geometry/write_mesh.h"
#include "io/batch_report.h"
#include "study/optimize/optimize_family.h"
#include <memory>
#include <spdlog/spdlog.h>

namespace rollcheck::cli
{
namespace
{
using study::optimize::FamilyAxis;
using study::optimize::FamilySearchSettings;
using Schema = io::BoundSchema<FamilySearchSettings>;

/// theta_min_deg (--theta-min), theta_max_deg, theta_start_deg for name "theta", unit "deg".
void add_axis(Schema& s, FamilyAxis FamilySearchSettings::*axis, const std::string& name, const std::string& unit,
              const std::string& what, io::Bounds range)
{
  const std::string suffix = unit.empty() ? "" : "_" + unit;
  s.real(name + "_min" + suffix, "--" + name + "-min",
         [axis](FamilySearchSettings& f) -> double& { return (f.*axis).min; }, unit, "Search box: least " + what, range)
      .real(name + "_max" + suffix, "--" + name + "-max",
            [axis](FamilySearchSettings& f) -> double& { return (f.*axis).max; }, unit, "Search box: largest " + what,
            range)
      .real(name + "_start" + suffix, "--" + name + "-start",
            [axis](FamilySearchSettings& f) -> double& { return (f.*axis).start; }, unit,
            "Start of the search, and the point whose derivatives are judged: " + what, range);
}

void add_method_parameters(Schema& s)
{
  using S = FamilySearchSettings;
  s.choice("score", "--score", &S::score,
           "Score minimised: cds, sds (oracle approx or rigid), uniformity (U of real rolling), fem-sds (FEM-SDS "
           "over one loop of real rolling, its continuum value on the exact surface, resolution-free; a body that "
           "cannot roll a whole loop scores +inf) or fem-sds-template (the same loop by the preprint's per-face "
           "template, which falls about as faces^-2), the last three with oracle rolling",
           study::optimize::family_score_names())
      .choice("oracle", "--oracle", &S::oracle,
              "approx: the approximate oracle (deterministic); rigid: the rigid-body oracle (chaotic: each score the "
              "mean of --replicates runs at genomes moved by --resolution); rolling: real rolling (for --score "
              "uniformity, fem-sds and fem-sds-template)",
              {{"approx", study::body_scores::Oracle::approximate},
               {"rigid", study::body_scores::Oracle::rigid},
               {"rolling", study::body_scores::Oracle::rolling}})
      .flag("paper_compat", "--paper-compat", &S::paper_compat,
            "Reproduce the reference code, quirks included; else every quirk corrected")
      .choice("family", "--family", &S::family,
              "Roller family: paper (the preprint's) or centre-line (its (90,1,1) is the true oloid)",
              {{"paper", geometry::RollerFamily::paper}, {"centre-line", geometry::RollerFamily::centre_line}})
      .integer("points", "--points", &S::points, "",
               "Samples per generating circle: of every body, or with --matched-resolution of the start only",
               body_points_range)
      .flag("matched_resolution", "--matched-resolution", &S::match_face_count,
            "Match the face count, not the points per circle: mesh each genome with the points per circle whose "
            "hull's face count is nearest the start's at --points (ties: --points itself, else the fewer points), "
            "since CDS falls about as faces^-2; off: every body with --points per circle")
      .choice("method", "--method", &S::method, "NLopt method (docs/methods/optimize.md)", study::optimize::method_names())
      .integer("max_evaluations", "--max-evaluations", &S::max_evaluations, "",
               "Distinct genomes the search scores, the start included", io::Bounds{1, 100000})
      .integer("replicates", "--replicates", &S::replicates, "",
               "Noise replicates at the start, each the genome moved by --resolution (rigid: also the runs averaged "
               "per score)", io::Bounds{2, 1000})
      .real("resolution", "--resolution", &S::resolution, "",
            "Fraction of each box width the search resolves (xtol), and the noise replicates' move",
            io::Bounds{0, 0.5, true, true})
      .real("pilot_step", "--pilot-step", &S::pilot_step, "",
            "Pilot steps of the derivatives' step choice, fraction of each box width", io::Bounds{0, 0.25, true})
      .choice("derivatives", "--derivatives", &S::derivatives,
              "Where the gradient and Hessian are measured: both (the start and the optimum), start, or none (the "
              "search and the sweeps alone)", study::optimize::derivatives_at_names())
      .integer("sweep_points", "--sweep-points", &S::sweep_points, "",
               "Points per axis of the sweeps through the start", io::Bounds{2, 1000})
      .integer("threads", "--threads", &S::threads, "", "Evaluations in parallel (0: one per core)",
               io::thread_count);
}

void add_oracle_parameters(Schema& s)
{
  s.integer("steps", "--steps", [](FamilySearchSettings& f) -> auto& { return f.scoring.approximate.steps; }, "",
            "Approximate oracle: rotation steps T", io::Bounds{1, double(study::body_scores::max_oracle_samples)})
      .real("duration_s", "--duration", [](FamilySearchSettings& f) -> auto& { return f.scoring.rigid.duration_s; },
            "s", "Rigid-body oracle: time per run", io::rigid_duration_s)
      .integer("loops", "--loops", [](FamilySearchSettings& f) -> auto& { return f.scoring.rolling.loops; }, "",
               "Rolling oracle: loops of the contact curve scored", io::rolling_loops)
      .unbound({"out", "--out", std::string(), "",
                "Folder for optimize.json, the meshes start.obj and optimum.obj, sweeps.png and optimum.png (a "
                "rendered view of both bodies), written whole or not at all, and evaluations.json, the finished "
                "runs, kept during the search so that the same command rerun after an interruption reuses them; "
                "empty: none"})
      .unbound({"python", "--python", std::string("/usr/bin/python3"), "",
                "Python with matplotlib for the plot (Debian's)"});
}

const SceneSchema<FamilySearchSettings>& optimize_schema()
{
  return kept_schema<FamilySearchSettings>("optimize",
                                           "Search a two-circle roller family for the genome (theta, d, rho) minimising "
                                           "a score with NLopt, judged against the noise, with the gradient and Hessian "
                                           "at the start and at the optimum",
                                           [](Schema& s) {
    add_method_parameters(s);
    add_axis(s, &FamilySearchSettings::theta_deg, "theta", "deg", "angle between the circle planes",
             io::Bounds{0, 180, true, true});
    add_axis(s, &FamilySearchSettings::offset, "offset", "", "centre distance d in units of r1", io::Bounds{0, 1000});
    add_axis(s, &FamilySearchSettings::ratio, "ratio", "", "radius ratio rho = r2 / r1", io::Bounds{1e-3, 1000});
    add_oracle_parameters(s);
  });
}

nlohmann::json run_optimize(const io::Parameters& params)
{
  FamilySearchSettings settings = optimize_schema().bind(params);
  const std::string& out = params.text("out");
  std::shared_ptr<io::EvaluationCache> runs;
  if (!out.empty())
    runs = keep_runs(out, params, settings);
  // The FEM-SDS loops' convergence, one status per body scored (a score is
  // reported with its convergence).
  auto fem_sds_statuses = std::make_shared<std::vector<std::string>>();
  if (study::optimize::is_fem_sds(settings.score))
    settings.fem_sds_score
        = fem_sds_family_scorer(settings.score == study::optimize::FamilyScore::fem_sds, fem_sds_statuses);
  const study::optimize::FamilySearchResult result = study::optimize::optimize_family(settings);
  nlohmann::json j = to_json(result);
  if (study::optimize::is_fem_sds(settings.score))
  {
    const study::optimize::LoopStatusCounts loops = study::optimize::count_loop_statuses(*fem_sds_statuses);
    j["fem_sds_loops"] = loops;
    if (loops.not_converged() > 0)
      spdlog::warn("optimize: {} of the {} FEM-SDS loops scored did not converge to the tolerance (JSON "
                   "fem_sds_loops)",
                   loops.not_converged(), loops.scored);
  }
  print_summary(study::optimize::summary_line(result));
  if (!out.empty())
    io::draw_folder(out, params.text("python"), io::default_scripts_folder() / "plot_optimize.py", {}, "plot.log",
                    [&](const std::filesystem::path& folder) {
                      write_file_atomically(folder / "optimize.json", j.dump(1) + "\n");
                      runs->save(folder / evaluations_file);
                      // Both bodies as they were scored, for the plot's side-by-side view.
                      const geometry::BodySpec start =
                          study::optimize::family_body(settings, result.search.start, result.start_mesh.points);
                      const geometry::BodySpec optimum =
                          study::optimize::family_body(settings, result.search.best_x, result.best_mesh.points);
                      geometry::write_mesh(geometry::make_body(start), folder / "start.obj");
                      geometry::write_mesh(geometry::make_body(optimum), folder / "optimum.obj");
                    });
  return j;
}
} // namespace

void add_optimize_command(CLI::App& app)
{
  add_scene_command(app, optimize_schema(), run_optimize);
  declare_outputs(optimize_schema().schema(), {{"out", OutputKind::folder}});
}
} // namespace rollcheck::cli
