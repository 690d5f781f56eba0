// `rollcheck oracle` and the case-file scene "oracle": study::body_scores::score_body, the preprint's oracles scored with CDS ...
// FDS (docs/methods/oracles.md#rollcheck-oracle) or real rolling scored with U (`--oracle rolling`, docs/methods/real-rolling.md),
// and the paper-compat quirk table (`--quirk-table`, study::body_scores::quirk_table).
#include "cli/cli.h"
#include "cli/scenes.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "io/surface_vtu.h"
#include "study/body_scores/paper_quirks.h"
#include "study/body_scores/score_body.h"
#include <fmt/format.h>
#include <map>
#include <spdlog/spdlog.h>

namespace rollcheck::cli
{
namespace
{
using study::body_scores::Oracle;
const auto max_samples = static_cast<double>(study::body_scores::max_oracle_samples);

/// score_body's settings and the options that resolve into them (settings_of).
struct OracleScene : study::body_scores::ScoreBodySettings
{
  std::string metric_list = "all", quirks, vtu_file;
  bool paper_compat = false, per_face = false, quirk_table = false;
  int runs = static_cast<int>(oracle::RigidBodySettings{}.initial_spins.size());
};
using Schema = io::BoundSchema<OracleScene>;

void add_scene_parameters(Schema& s)
{
  s.choice("oracle", "--oracle", &OracleScene::oracle,
           "approx: the approximate oracle (Algorithm 1); rigid: the rigid-body oracle (Algorithm 2); rolling: real "
           "rolling without slipping of a named --body (not uv-sphere, hemisphere), scored with U, not CDS ... FDS",
           {{"approx", Oracle::approximate}, {"rigid", Oracle::rigid}, {"rolling", Oracle::rolling}})
      .text("metrics", "--metrics", &OracleScene::metric_list,
            "Scores, comma-separated from cds,sds,tds,wds,fds, or all (tds, wds need --oracle rigid; all: cds,sds,fds)")
      .flag("paper_compat", "--paper-compat", &OracleScene::paper_compat,
            "Reproduce the reference code, quirks included (every switch of --quirks paper); else all are corrected")
      .text("quirks", "--quirks", &OracleScene::quirks,
            "Set single paper-compat switches after --paper-compat: name=paper|corrected,... (docs/results/oracles.md#paper-compat-quirk-table)")
      .flag("per_face", "--per-face", &OracleScene::per_face, "Add the per-face arrays to the JSON")
      .path("vtu_file", "--vtu", &OracleScene::vtu_file,
            "Write the body with its per-face arrays (those of --per-face) as named cell data to this .vtu "
            "(ParaView, meshio); the preprint's oracles")
      .flag("quirk_table", "--quirk-table", &OracleScene::quirk_table,
            "Print the table of each paper-compat switch's effect, alone, on the rigid-body scores, with the band")
      .integer("convergence_every", "--convergence-every", &OracleScene::convergence_every, "",
               "Record every score after each this many samples (the reference outputs: 50; 0: never)",
               io::Bounds{0, max_samples})
      .integer("runs", "--runs", &OracleScene::runs, "",
               "Rigid-body oracle: runs, from the reference's spins (0.3,1.5,0.2), (-0.5,1,0.8), (0.7,-1.2,0.4), "
               "(0.1,0.8,-1), (-0.3,-0.6,1.5) rad/s", io::Bounds{1, double(oracle::reference_initial_spins().size())});
}

void add_oracle_parameters(Schema& s)
{
  using A = oracle::ApproximateSettings;
  using R = oracle::RigidBodySettings;
  const std::string guard = fmt::format("at most {} samples, a resource guard", study::body_scores::max_oracle_samples);
  s.include(io::BoundSchema<A>("approximate")
                .integer("steps", "--steps", &A::steps, "", "Approximate oracle: rotation steps T (" + guard + ")",
                         io::Bounds{1, max_samples})
                .real("threshold_m", "--threshold", &A::contact_threshold_m, "m",
                      "Contact threshold eps of both oracles: a face touches when its centroid is less than eps "
                      "above the ground (the preprint's); 0: nothing touches, every score is inf", io::non_negative)
                .real("roll_cycles", "--roll-cycles", &A::roll_cycles, "", "Approximate oracle: turns about y over T")
                .real("wobble_amplitude_rad", "--wobble", &A::wobble_amplitude_rad, "rad", "Approximate: x wobble A_w"),
            &OracleScene::approximate);
  s.include(io::BoundSchema<R>("rigid")
                .real("duration_s", "--duration", &R::duration_s, "s", "Rigid-body oracle: time per run", io::positive)
                .real("time_step_s", "--dt", &R::time_step_s, "s", "Rigid-body oracle: time step dt", io::positive)
                .integer("sample_every", "--sample-every", &R::sample_every, "",
                         "Rigid-body oracle: steps between samples (" + guard + ")", io::Bounds{1, max_samples})
                .real("damping_n_m_s", "--damping", &R::damping_n_m_s, "N m s",
                      "Rigid-body oracle: damping gamma, torque per angular velocity", io::non_negative)
                .real("mass_kg", "--mass", &R::mass_kg, "kg", "Rigid and rolling: mass m", io::positive)
                .real("gravity_m_s2", "--gravity", &R::gravity_m_s2, "m/s^2", "Rigid and rolling: g", io::non_negative)
                .real("max_angular_speed_rad_s", "--max-spin", &R::max_angular_speed_rad_s, "rad/s",
                      "Rigid-body oracle: cap on |omega| (the reference code's)", io::positive)
                .ratio_cap("duration_s", "dt_s", io::max_rigid_steps, "rigid-body time steps"),
            &OracleScene::rigid);
}

void add_contact_parameters(Schema& s)
{
  using H = contact::HertzParameters;
  using F = contact::FatigueParameters;
  using W = contact::WearParameters;
  io::BoundSchema<H> hertz("hertz");
  add_material(hertz, &H::youngs_modulus_pa, &H::poisson_ratio);
  hertz.real("normal_load_n", "--load", &H::normal_load_n, "N", "Reference load F of SDS, TDS and WDS", io::positive)
      .real("flat_radius_m", "--flat-radius", &H::flat_radius_m, "m",
            "Faces with a larger effective radius are flat: no Hertz pressure (the reference code's)", io::positive)
      .real("curvature_floor_per_m", "--curvature-floor", &H::curvature_floor_per_m, "1/m",
            "Principal curvatures below this count as zero (the reference code's)", io::non_negative);
  s.include(hertz, [](auto& scene) -> auto& { return scene.contact.hertz; });
  s.include(io::BoundSchema<F>("fatigue")
                .real("fatigue_load_n", "--fatigue-load", &F::load_n, "N", "Load of FDS", io::positive)
                .real("fatigue_strength_pa", "--fatigue-strength", &F::strength_coefficient_pa, "Pa",
                      "Basquin fatigue strength coefficient sigma_f'", io::positive)
                .real("basquin_exponent", "--basquin-exponent", &F::basquin_exponent, "", "Basquin exponent b",
                      io::Bounds{-io::positive.upper, 0, false, true})
                .real("endurance_limit_pa", "--endurance-limit", &F::endurance_limit_pa, "Pa",
                      "Endurance limit sigma_e, no damage below it", io::non_negative),
            [](auto& scene) -> auto& { return scene.contact.fatigue; });
  s.real("friction_coefficient", "--friction", [](auto& o) -> auto& { return o.contact.thermal.friction_coefficient; },
         "", "mu of TDS", io::non_negative);
  s.include(io::BoundSchema<W>("wear")
                .real("archard_coefficient", "--archard-k", &W::archard_coefficient, "", "Archard wear coefficient k",
                      io::non_negative)
                .real("hardness_pa", "--hardness", &W::hardness_pa, "Pa", "Hardness H of WDS", io::positive)
                .real("contact_time_s", "--contact-time", &W::contact_time_s, "s",
                      "Sliding time per sample in WDS (the reference code's: dt x sample interval)", io::non_negative),
            [](auto& scene) -> auto& { return scene.contact.wear; });
}

void add_rolling_parameters(Schema& s)
{
  using P = oracle::RollingStudyParameters;
  s.include(io::BoundSchema<P>("rolling")
                .real("rolling_energy", "--rolling-energy", &P::rolling_energy, "",
                      "Rolling oracle: initial kinetic energy / potential barrier dV - 1 (0.1: over every barrier, "
                      "no rim lifts)", io::non_negative)
                .former("barrier_energy_excess")
                .integer("loops", "--loops", &P::loops, "",
                         "Rolling oracle: loops of the contact curve scored (undamped, every loop is the same)",
                         io::rolling_loops)
                .integer("face_subdivisions", "--face-subdivisions", &P::face_subdivisions, "",
                         "Rolling oracle: every mesh face cut into this^2 parts for scoring U, which rises towards "
                         "its mesh-free value U_inf as this grows; at most 64, a resource guard", io::Bounds{1, 64})
                .integer("mass_points", "--mass-points", &P::mass_points, "",
                         "Rolling oracle: samples per circle (cylinder: sides) of the mesh giving the exact body's "
                         "mass, inertia and area (error ~ 1/this^2); at most 2^20, a resource guard",
                         io::Bounds{16, 1 << 20})
                .choice("contact_width", "--contact-width", [](auto& p) -> auto& { return p.contact_width.model; },
                        "Rolling oracle: contact strip width, hertz (Hertz patch) or geometric (unit width)",
                        {{"hertz", oracle::ContactWidthModel::hertz}, {"geometric", oracle::ContactWidthModel::rigid}}),
            &OracleScene::rolling);
  using C = contact::ContinuumLoopSettings;
  s.include(io::BoundSchema<C>("continuum")
                .choice("load_rule", "--load-rule", &C::load_rule,
                        "Rolling oracle, continuum scores: the load on each ruling, dynamic (the normal force and "
                        "centre of pressure of the same rolling motion), static (through the centre of mass) or "
                        "uniform (along the ruling)",
                        contact::load_rule_names())
                .real("end_margin", "--end-margin", &C::end_margin, "",
                      "Rolling oracle, continuum pressure scores: fraction of the ruling held at each loaded end",
                      io::Bounds{0, 0.5, false, true})
                .choice("time_law", "--time-law", &C::time_law,
                        "Rolling oracle, continuum scores: free (the rolling motion's) or uniform_rate (the same loop "
                        "at a constant rolling rate; needs --load-rule static or uniform)",
                        contact::time_law_names()),
            &OracleScene::continuum);
}

const SceneSchema<OracleScene>& oracle_schema()
{
  return kept_schema<OracleScene>("oracle",
                                  "Roll a body with the approximate or rigid-body oracle and score its contact, stress, "
                                  "heat, wear and fatigue distributions, or roll it for real (--oracle rolling) and "
                                  "score its contact with U. Defaults: the preprint's values, else the reference code's",
                                  [](Schema& s) {
    s.include(body_schema(), &OracleScene::body);
    add_scene_parameters(s);
    add_oracle_parameters(s);
    add_contact_parameters(s);
    add_rolling_parameters(s);
  });
}

study::body_scores::ScoreBodySettings settings_of(const OracleScene& scene)
{
  study::body_scores::ScoreBodySettings s = scene;
  s.rigid.contact_threshold_m = scene.approximate.contact_threshold_m; // one --threshold for both oracles
  s.rolling.mass_kg = scene.rigid.mass_kg;                             // one --mass and --gravity for all
  s.rolling.gravity_m_s2 = scene.rigid.gravity_m_s2;
  const auto& spins = oracle::reference_initial_spins();
  s.rigid.initial_spins.assign(spins.begin(), spins.begin() + scene.runs);
  s.compat = scene.paper_compat ? oracle::PaperCompat::reference() : oracle::PaperCompat::corrected();
  oracle::apply_quirk_settings(s.compat, scene.quirks, "option --quirks");
  s.metrics = contact::MetricSet::parse(scene.metric_list, "option --metrics");
  if (scene.metric_list == "all" && scene.oracle != Oracle::rigid)
    s.metrics.tds = s.metrics.wds = false;
  return s;
}

/// The preprint's scores all apply one template (oracle/distribution_score.h)
/// whose every face term is weighted by (a_f / A)^2 ~ N^-2
/// (oracle/uniformity_score.h): each falls as the face count N to this power
/// at a fixed body, so two bodies compare only at matched face counts. The
/// audit measures -2.01 (docs/results/audit.md); real rolling's U does not fall.
constexpr double template_face_count_exponent = -2.0;

/// The resolution note of the preprint's scores, for the JSON.
nlohmann::json resolution_json(const study::body_scores::BodyScores& scores)
{
  return {{"n_faces", scores.n_faces},
          {"face_count_exponent", template_face_count_exponent},
          {"depends_on_resolution", true},
          {"note", "cds, sds, tds, wds_vol, wds_depth and fds fall as n_faces^face_count_exponent at a fixed body: "
                   "compare bodies at matched face counts, or by the resolution-free U (--oracle rolling)"}};
}

/// The summary table: each score with how it depends on the mesh.
std::string summary_table(const study::body_scores::BodyScores& scores)
{
  if (scores.oracle == Oracle::rolling)
  {
    const oracle::RollingStudyResult& r = scores.rolling;
    return fmt::format("| {} (real rolling) | value | resolution |\n|---|---|---|\n"
                       "| U | {:.6g} | rises to U_inf as the {} scoring faces are refined |\n"
                       "| U_inf | {:.6g} | none (continuum) |\n| coverage | {:.4g} | |\n",
                       scores.body, r.uniformity, r.faces, r.continuum_uniformity, r.coverage);
  }
  const contact::ScoreVector& v = scores.scores;
  std::string table = fmt::format("| {} ({} oracle, {} samples) | value | resolution |\n|---|---|---|\n",
                                  scores.body, scores.oracle == Oracle::rigid ? "rigid-body" : "approximate", v.n_samples);
  const std::pair<const char*, const std::optional<double>*> rows[] = {
      {"CDS", &v.cds}, {"SDS", &v.sds}, {"TDS", &v.tds}, {"WDS_vol", &v.wds_vol}, {"WDS_depth", &v.wds_depth}, {"FDS", &v.fds}};
  for (const auto& [name, value] : rows)
    if (value->has_value())
      table += fmt::format("| {} | {:.6g} | x N^{:g}, N = {} faces: compare at matched face counts |\n", name,
                           **value, template_face_count_exponent, scores.n_faces);
  return table;
}

/// The per-face arrays of the run as a VTU's cell data, under the names of
/// the JSON's "per_face" (study::body_scores::to_json; tests/cli/oracle_vtu.sh
/// holds the two to the same names and values).
void write_face_fields(const OracleScene& scene, const study::body_scores::BodyScores& scores)
{
  std::map<std::string, Eigen::VectorXd> fields = scores.scores.per_face;
  fields["face_areas_m2"] = scores.face_areas_m2;
  fields["effective_radius_m"] = scores.curvature.effective_radius_m;
  fields["mean_curvature_per_m"] = scores.curvature.mean;
  fields["gaussian_curvature_per_m2"] = scores.curvature.gaussian;
  fields["peak_pressure_pa"] = scores.pressure.peak_pressure_pa;
  std::erase_if(fields, [](const auto& field) { return field.second.size() == 0; }); // a metric not asked for
  io::write_surface_vtu(scene.vtu_file, geometry::make_body(scene.body), fields);
}

nlohmann::json run_oracle(const io::Parameters& params)
{
  const OracleScene scene = oracle_schema().bind(params);
  if (scene.oracle == Oracle::rolling && (scene.quirk_table || scene.paper_compat || scene.per_face || !scene.vtu_file.empty()))
    throw InputError("options --quirk-table, --paper-compat, --per-face and --vtu belong to the preprint's oracles, not "
                     "to --oracle rolling");
  if (!scene.vtu_file.empty())
    check_output_file(scene.vtu_file, "option --vtu");
  if (scene.quirk_table)
  {
    const study::body_scores::QuirkTable table = study::body_scores::quirk_table(settings_of(scene));
    print_summary(study::body_scores::to_markdown(table));
    return to_json(table);
  }
  const study::body_scores::BodyScores scores = study::body_scores::score_body(settings_of(scene));
  spdlog::debug("{}", study::body_scores::summary_line(scores));
  print_summary(summary_table(scores));
  if (!scene.vtu_file.empty())
    write_face_fields(scene, scores);
  nlohmann::json j = to_json(scores, scene.per_face);
  if (scene.oracle != Oracle::rolling)
    j["resolution"] = resolution_json(scores);
  return j;
}
} // namespace

void add_oracle_command(CLI::App& app) { add_scene_command(app, oracle_schema(), run_oracle); }
} // namespace rollcheck::cli
