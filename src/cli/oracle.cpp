// `rollcheck oracle`: the preprint's approximate or rigid-body oracle on a
// body, scored with CDS, SDS, TDS, WDS and FDS (README "rollcheck oracle"),
// or real rolling without slipping of a named body, scored with the
// uniformity score U (`--oracle rolling`, README "Corrected physics").
// Also the scene "oracle" of case files, and the paper-compat quirk table
// (`--quirk-table`).
#include "cli/body_from_parameters.h"
#include "cli/cli.h"
#include "cli/scenes.h"
#include "contact/face_curvature.h"
#include "contact/face_pressure.h"
#include "contact/trajectory_scores.h"
#include "geometry/body.h"
#include "core/error.h"
#include "io/search_store.h"
#include "oracle/approximate_oracle.h"
#include "oracle/rigid_body_oracle.h"
#include "oracle/rolling_body.h"
#include "oracle/rolling_study.h"
#include <chrono>
#include <fmt/format.h>
#include <spdlog/spdlog.h>

namespace rollcheck::cli
{
namespace
{
const io::Schema& oracle_schema()
{
  static const io::Schema schema = [] {
    const oracle::ApproximateOptions a;
    const oracle::RigidBodyOptions r;
    const contact::ContactParameters c;
    const oracle::RollingStudyParameters rolling;
    io::Schema s{"oracle", body_parameters()};
    const std::vector<io::Parameter> own = {
        {"oracle", "--oracle", std::string("rigid"), "",
         "approx: the approximate oracle (Algorithm 1); rigid: the rigid-body oracle (Algorithm 2); rolling: real "
         "rolling without slipping under gravity of a named --body (oloid, paper-oloid, two-circle roller, "
         "cylinder, sphere), scored with the uniformity score U instead of CDS ... FDS",
         {"approx", "rigid", "rolling"}},
        {"barrier_energy_excess", "--energy-excess", rolling.barrier_energy_excess, "",
         "Rolling oracle: initial kinetic energy at the stable ruling / potential barrier dV - 1 (0.1: just over "
         "every barrier without lifting a rim, README \"The preprint's bodies under real rolling\")"},
        {"loops", "--loops", std::int64_t{rolling.loops}, "",
         "Rolling oracle: complete loops of the contact curve scored (undamped, every loop is the same)"},
        {"face_subdivisions", "--face-subdivisions", std::int64_t{8}, "",
         "Rolling oracle: every mesh face cut into this^2 parts for scoring U; U on the mesh rises towards its "
         "mesh-free value U_inf as this grows (8: the README's real-rolling table)"},
        {"mass_points", "--mass-points", std::int64_t{rolling.mass_points}, "",
         "Rolling oracle: samples per circle (cylinder: sides) of the fine mesh giving the exact body's mass, "
         "inertia and area; U_inf's error from it falls as 1/mass_points^2"},
        {"contact_width", "--contact-width", std::string("hertz"), "",
         "Rolling oracle: width of the contact strip, hertz (the elastic Hertz patch, physical) or rigid (unit "
         "width, the geometric sweep)",
         {"hertz", "rigid"}},
        {"steps", "--steps", std::int64_t{a.steps}, "",
         "Approximate oracle: rotation steps T (the rigid-body oracle takes --duration / --dt)"},
        {"threshold_m", "--threshold", a.contact_threshold_m, "m",
         "Contact threshold eps: a face touches when its centroid is less than eps above the ground (the "
         "preprint's); 0 means nothing ever touches and every score is infinite"},
        {"metrics", "--metrics", std::string("all"), "",
         "Scores to compute, comma-separated from cds,sds,tds,wds,fds, or all (tds and wds need --oracle rigid; "
         "all means cds,sds,fds for approx)"},
        {"paper_compat", "--paper-compat", false, "",
         "Reproduce the reference code, quirks included (every switch of --quirks set to paper); without it "
         "every quirk is corrected"},
        {"quirks", "--quirks", std::string(), "",
         "Set single paper-compat switches after --paper-compat: name=paper|corrected,... (README quirk table)"},
        {"per_face", "--per-face", false, "", "Add the per-face arrays to the JSON"},
        {"quirk_table", "--quirk-table", false, "",
         "Print the Markdown table of each paper-compat switch's effect on this body's rigid-body scores, each "
         "switch corrected alone from the paper-compatible mode, with the 1e-12 spin-nudge band"},
        {"convergence_every", "--convergence-every", std::int64_t{50}, "",
         "Record every score after each this many samples (the reference outputs: 50)"},
        {"roll_cycles", "--roll-cycles", a.roll_cycles, "", "Approximate oracle: turns about y over T (the preprint's)"},
        {"wobble_amplitude_rad", "--wobble", a.wobble_amplitude_rad, "rad",
         "Approximate oracle: amplitude A_w of the x wobble (the preprint's)"},
        {"duration_s", "--duration", r.duration_s, "s", "Rigid-body oracle: simulated time T per run (the preprint's)"},
        {"time_step_s", "--dt", r.time_step_s, "s", "Rigid-body oracle: time step dt (the preprint's)"},
        {"sample_every", "--sample-every", std::int64_t{r.sample_every}, "",
         "Rigid-body oracle: steps between contact samples (the preprint's)"},
        {"runs", "--runs", std::int64_t{3}, "",
         "Rigid-body oracle: runs, 1 to 5, with the reference's initial spins (0.3,1.5,0.2), (-0.5,1,0.8), "
         "(0.7,-1.2,0.4), (0.1,0.8,-1), (-0.3,-0.6,1.5) rad/s (the preprint: 3)"},
        {"damping_n_m_s", "--damping", r.damping_n_m_s, "N m s",
         "Rigid-body oracle: damping gamma, torque per angular velocity (the preprint's)"},
        {"mass_kg", "--mass", r.mass_kg, "kg", "Rigid-body and rolling oracles: mass m (the preprint's; U does not depend on it)"},
        {"gravity_m_s2", "--gravity", r.gravity_m_s2, "m/s^2", "Rigid-body and rolling oracles: g (the preprint's)"},
        {"max_angular_speed_rad_s", "--max-spin", r.max_angular_speed_rad_s, "rad/s",
         "Rigid-body oracle: cap on |omega| (the reference code's)"},
        {"youngs_modulus_pa", "--youngs-modulus", c.hertz.youngs_modulus_pa, "Pa", "E of the body, mild steel (the preprint's)"},
        {"poisson_ratio", "--poisson", c.hertz.poisson_ratio, "", "nu of the body (the preprint's)"},
        {"normal_load_n", "--load", c.hertz.normal_load_n, "N", "Reference load F of SDS, TDS and WDS (the preprint's)"},
        {"flat_radius_m", "--flat-radius", c.hertz.flat_radius_m, "m",
         "Faces with a larger effective radius are flat: no Hertz pressure (the reference code's)"},
        {"curvature_floor_per_m", "--curvature-floor", c.hertz.curvature_floor_per_m, "1/m",
         "Principal curvatures below this count as zero (the reference code's)"},
        {"fatigue_load_n", "--fatigue-load", c.fatigue.load_n, "N", "Load of FDS (the preprint's)"},
        {"fatigue_strength_pa", "--fatigue-strength", c.fatigue.strength_coefficient_pa, "Pa",
         "Basquin fatigue strength coefficient sigma_f' (the preprint's)"},
        {"basquin_exponent", "--basquin-exponent", c.fatigue.basquin_exponent, "", "Basquin exponent b (the preprint's)"},
        {"endurance_limit_pa", "--endurance-limit", c.fatigue.endurance_limit_pa, "Pa",
         "Endurance limit sigma_e, no damage below it (the preprint's)"},
        {"friction_coefficient", "--friction", c.thermal.friction_coefficient, "", "mu of TDS (the preprint's)"},
        {"archard_coefficient", "--archard-k", c.wear.archard_coefficient, "", "Archard wear coefficient k (the preprint's)"},
        {"hardness_pa", "--hardness", c.wear.hardness_pa, "Pa", "Hardness H of WDS (the preprint's)"},
        {"contact_time_s", "--contact-time", c.wear.contact_time_s, "s",
         "Sliding time per sample in WDS (the reference code's; equals dt x sample interval)"},
    };
    s.parameters.insert(s.parameters.end(), own.begin(), own.end());
    return s;
  }();
  return schema;
}

struct Setup
{
  bool rigid = true;
  oracle::ApproximateOptions approximate;
  oracle::RigidBodyOptions rigid_options;
  contact::ContactParameters contact;
  oracle::PaperCompat compat;
  contact::MetricSet metrics;
  long convergence_every = 50;
};

Setup setup_from(const io::Parameters& p)
{
  Setup s;
  s.rigid = p.text("oracle") == "rigid";
  s.approximate.steps = p.integer("steps");
  s.approximate.contact_threshold_m = p.real("threshold_m");
  s.approximate.roll_cycles = p.real("roll_cycles");
  s.approximate.wobble_amplitude_rad = p.real("wobble_amplitude_rad");
  oracle::validate(s.approximate); // also for rigid runs: --steps 0 is an error either way
  auto& r = s.rigid_options;
  r.duration_s = p.real("duration_s");
  r.time_step_s = p.real("time_step_s");
  r.sample_every = p.integer("sample_every");
  r.contact_threshold_m = p.real("threshold_m");
  r.damping_n_m_s = p.real("damping_n_m_s");
  r.mass_kg = p.real("mass_kg");
  r.gravity_m_s2 = p.real("gravity_m_s2");
  r.max_angular_speed_rad_s = p.real("max_angular_speed_rad_s");
  const std::int64_t runs = p.integer("runs");
  const auto& spins = oracle::reference_initial_spins();
  if (runs < 1 || runs > static_cast<std::int64_t>(spins.size()))
    throw InputError(fmt::format("option --runs: must be 1 to {} (the reference's initial spins), got {}",
                                 spins.size(), runs));
  r.initial_spins.assign(spins.begin(), spins.begin() + runs);
  oracle::validate(r);
  auto& c = s.contact;
  c.hertz = {p.real("youngs_modulus_pa"), p.real("poisson_ratio"), p.real("normal_load_n"), p.real("flat_radius_m"),
             p.real("curvature_floor_per_m")};
  c.fatigue = {p.real("fatigue_load_n"), p.real("fatigue_strength_pa"), p.real("basquin_exponent"),
               p.real("endurance_limit_pa")};
  c.thermal = {p.real("friction_coefficient")};
  c.wear = {p.real("archard_coefficient"), p.real("hardness_pa"), p.real("contact_time_s")};
  contact::validate(c);
  s.compat = p.flag("paper_compat") ? oracle::PaperCompat::reference() : oracle::PaperCompat::corrected();
  oracle::apply_quirk_settings(s.compat, p.text("quirks"), "option --quirks");
  s.metrics = contact::MetricSet::parse(p.text("metrics"), "option --metrics");
  if (p.text("metrics") == "all" && !s.rigid)
    s.metrics.tds = s.metrics.wds = false;
  s.convergence_every = p.integer("convergence_every");
  if (s.convergence_every < 0)
    throw InputError(fmt::format("option --convergence-every: must be >= 0, got {}", s.convergence_every));
  return s;
}

struct Evaluation
{
  contact::ScoreVector scores;
  contact::FaceCurvature curvature;
  contact::FacePressure pressure;
  Eigen::VectorXd face_areas;
  double wall_s = 0;
};

Evaluation evaluate(const geometry::SurfaceMesh& mesh, const Setup& s)
{
  const auto start = std::chrono::steady_clock::now();
  Evaluation e;
  const oracle::RollingBody body = oracle::make_rolling_body(mesh, s.compat);
  const oracle::Trajectory trajectory = s.rigid ? oracle::rigid_body_oracle(body, s.rigid_options, s.compat)
                                                : oracle::approximate_oracle(body, s.approximate, s.compat);
  e.curvature = contact::face_curvature(mesh, s.contact.hertz, s.compat);
  e.pressure = contact::face_pressure(e.curvature.effective_radius_m, s.contact.hertz, s.compat);
  e.scores = contact::score_trajectory({body, e.curvature, e.pressure}, trajectory, s.metrics, s.contact, s.compat,
                                       s.convergence_every);
  e.face_areas = body.face_areas;
  e.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return e;
}

nlohmann::json optional_score(const std::optional<double>& v)
{
  return v ? io::json_number(*v) : nlohmann::json(nullptr);
}

nlohmann::json array_of(const Eigen::VectorXd& v)
{
  nlohmann::json a = nlohmann::json::array();
  for (Eigen::Index i = 0; i < v.size(); ++i)
    a.push_back(io::json_number(v[i]));
  return a;
}

nlohmann::json summary_of(const Evaluation& e, const Setup& s, std::size_t n_faces, bool per_face)
{
  const contact::ScoreVector& v = e.scores;
  const contact::MetricSet& m = s.metrics;
  nlohmann::json j = {{"oracle", s.rigid ? "rigid" : "approx"},
                      {"cds", optional_score(v.cds)},
                      {"sds", optional_score(v.sds)},
                      {"tds", optional_score(v.tds)},
                      {"wds_vol", optional_score(v.wds_vol)},
                      {"wds_depth", optional_score(v.wds_depth)},
                      {"fds", optional_score(v.fds)},
                      {"n_faces", n_faces},
                      {"n_samples", v.n_samples},
                      {"wall_s", e.wall_s},
                      {"paper_compat", oracle::describe(s.compat) == oracle::describe(oracle::PaperCompat::reference())}};
  nlohmann::json quirks = nlohmann::json::object();
  for (const oracle::Quirk& q : oracle::quirks())
    quirks[std::string(q.name)] = s.compat.*q.flag ? "paper" : "corrected";
  j["quirks"] = quirks;
  if (m.cds)
    j["contact"] = {{"contact_cv", io::json_number(v.contact.cv)},
                    {"max_contact_ratio", io::json_number(v.contact.max_mean_ratio)},
                    {"faces_with_contact", v.contact.faces_with},
                    {"faces_without_contact", v.contact.faces_without}};
  j["mean_peak_pressure_pa"] = m.sds ? io::json_number(v.peak_pressure_pa.mean) : nlohmann::json(nullptr);
  j["stress_cv"] = m.sds ? io::json_number(v.peak_pressure_pa.cv) : nlohmann::json(nullptr);
  if (m.sds)
    j["hertz"] = {{"min_peak_pressure_pa", io::json_number(v.peak_pressure_pa.min)},
                  {"max_peak_pressure_pa", io::json_number(v.peak_pressure_pa.max)},
                  {"touching_samples", v.peak_pressure_pa.count},
                  {"effective_modulus_pa", v.effective_modulus_pa}};
  if (m.fds)
    j["fatigue"] = {{"damage_ratio", io::json_number(v.damage_ratio)},
                    {"first_failure_cycles", io::json_number(v.first_failure_cycles)},
                    {"mean_stress_amplitude_pa", io::json_number(v.fatigue_stress_pa.mean)},
                    {"max_stress_amplitude_pa", io::json_number(v.fatigue_stress_pa.max)},
                    {"fraction_above_endurance", v.fraction_above_endurance}};
  if (m.tds)
    j["thermal"] = {{"heat_ratio", io::json_number(v.heat_ratio)}};
  if (m.needs_sliding())
    j["sliding"] = {{"mean_speed_m_s", io::json_number(v.sliding_speed_m_s.mean)},
                    {"max_speed_m_s", io::json_number(v.sliding_speed_m_s.max)},
                    {"speed_cv", io::json_number(v.sliding_speed_m_s.cv)}};
  if (m.wds)
    j["wear"] = {{"wear_depth_ratio", io::json_number(v.wear_depth_ratio)}};
  const contact::FaceCurvature& c = e.curvature;
  double r_min = std::numeric_limits<double>::infinity(), r_max = 0;
  for (Eigen::Index f = 0; f < c.effective_radius_m.size(); ++f)
    if (std::isfinite(c.effective_radius_m[f]))
    {
      r_min = std::min(r_min, c.effective_radius_m[f]);
      r_max = std::max(r_max, c.effective_radius_m[f]);
    }
  const double h_mean = c.mean.mean();
  j["curvature"] = {{"face_mean_curvature_mean_per_m", h_mean},
                    {"face_mean_curvature_std_per_m", std::sqrt((c.mean.array() - h_mean).square().mean())},
                    {"face_gaussian_curvature_mean_per_m2", c.gaussian.mean()},
                    {"effective_radius_min_m", io::json_number(r_min)},
                    {"effective_radius_max_finite_m", r_max},
                    {"flat_faces", c.flat_faces}};
  nlohmann::json convergence = nlohmann::json::object();
  for (const auto& [key, points] : v.convergence)
  {
    nlohmann::json list = nlohmann::json::array();
    for (const auto& [n, score] : points)
      list.push_back({n, io::json_number(score)});
    convergence[key] = list;
  }
  j["convergence"] = convergence;
  if (per_face)
  {
    nlohmann::json pf = {{"face_areas_m2", array_of(e.face_areas)},
                         {"effective_radius_m", array_of(c.effective_radius_m)},
                         {"mean_curvature_per_m", array_of(c.mean)},
                         {"gaussian_curvature_per_m2", array_of(c.gaussian)},
                         {"peak_pressure_pa", array_of(e.pressure.peak_pressure_pa)}};
    for (const auto& [key, values] : v.per_face)
      pf[key] = array_of(values);
    j["per_face"] = pf;
  }
  return j;
}

// --- the quirk table ---

struct QuirkRow
{
  std::string name, layer, reference_does, physically_right;
  contact::ScoreVector scores;
};

std::string percent_change(const std::optional<double>& value, const std::optional<double>& base)
{
  if (!value || !base)
    return "-";
  if (std::isinf(*value) || std::isinf(*base))
    return std::isinf(*value) && std::isinf(*base) ? "inf = inf" : fmt::format("{:.3g} vs {:.3g}", *value, *base);
  return fmt::format("{:+.2f} %", 100 * (*value / *base - 1));
}

nlohmann::json quirk_table(const geometry::SurfaceMesh& mesh, const Setup& paper_setup, const std::string& label)
{
  Setup base = paper_setup;
  base.compat = oracle::PaperCompat::reference();
  base.rigid = true;
  base.metrics = {};
  const contact::ScoreVector reference = evaluate(mesh, base).scores;

  // The chaotic-trajectory band: every run's spin nudged by +-1e-12 rad/s
  // along x, y, z; half-width = largest relative change of each score.
  using Score = std::optional<double> contact::ScoreVector::*;
  const std::vector<std::pair<std::string, Score>> scores = {
      {"CDS", &contact::ScoreVector::cds},         {"SDS", &contact::ScoreVector::sds},
      {"TDS", &contact::ScoreVector::tds},         {"WDS_vol", &contact::ScoreVector::wds_vol},
      {"WDS_depth", &contact::ScoreVector::wds_depth}, {"FDS", &contact::ScoreVector::fds}};
  std::vector<double> band(scores.size(), 0.0);
  double pressure_band = 0;
  for (int axis = 0; axis < 3; ++axis)
    for (const double sign : {1.0, -1.0})
    {
      Setup nudged = base;
      for (Eigen::Vector3d& w : nudged.rigid_options.initial_spins)
        w[axis] += sign * 1e-12;
      const contact::ScoreVector v = evaluate(mesh, nudged).scores;
      for (std::size_t k = 0; k < scores.size(); ++k)
      {
        const auto& a = v.*scores[k].second;
        const auto& b = reference.*scores[k].second;
        if (a && b && std::isfinite(*a) && std::isfinite(*b))
          band[k] = std::max(band[k], std::abs(*a / *b - 1));
      }
      pressure_band = std::max(pressure_band, std::abs(v.peak_pressure_pa.mean / reference.peak_pressure_pa.mean - 1));
    }

  std::vector<QuirkRow> rows;
  for (const oracle::Quirk& q : oracle::quirks())
  {
    Setup alone = base;
    alone.compat.*q.flag = false;
    rows.push_back({std::string(q.name), std::string(q.layer), std::string(q.reference_does),
                    std::string(q.physically_right), evaluate(mesh, alone).scores});
  }

  std::string header = "| quirk | layer | reference does | physically right |";
  std::string rule = "|---|---|---|---|";
  for (const auto& [name, member] : scores)
  {
    header += fmt::format(" {} |", name);
    rule += "---|";
  }
  header += " mean p0 |";
  rule += "---|";
  fmt::print("Paper-compat quirks on {} (rigid-body oracle, {} samples): change of each score when the quirk "
             "alone is corrected\n\n{}\n{}\n",
             label, reference.n_samples, header, rule);
  std::string base_line = "| (paper-compatible values) | | | |";
  std::string band_line = "| (band: 1e-12 rad/s spin nudges) | | | |";
  for (std::size_t k = 0; k < scores.size(); ++k)
  {
    const auto& v = reference.*scores[k].second;
    base_line += v ? fmt::format(" {:.4g} |", *v) : " - |";
    band_line += fmt::format(" +-{:.2f} % |", 100 * band[k]);
  }
  base_line += fmt::format(" {:.4g} MPa |", reference.peak_pressure_pa.mean / 1e6);
  band_line += fmt::format(" +-{:.2f} % |", 100 * pressure_band);
  fmt::print("{}\n{}\n", base_line, band_line);

  nlohmann::json table = nlohmann::json::array();
  auto json_scores = [&](const contact::ScoreVector& v) {
    nlohmann::json j = nlohmann::json::object();
    for (const auto& [name, member] : scores)
      j[name] = optional_score(v.*member);
    j["mean_peak_pressure_pa"] = io::json_number(v.peak_pressure_pa.mean);
    return j;
  };
  for (const QuirkRow& row : rows)
  {
    auto cell = [](std::string text) { // a '|' would end the Markdown cell
      for (std::size_t at = text.find('|'); at != std::string::npos; at = text.find('|', at + 2))
        text.replace(at, 1, "\\|");
      return text;
    };
    std::string line = fmt::format("| {} | {} | {} | {} |", row.name, row.layer, cell(row.reference_does),
                                   cell(row.physically_right));
    for (const auto& [name, member] : scores)
      line += fmt::format(" {} |", percent_change(row.scores.*member, reference.*member));
    line += fmt::format(" {} |",
                        percent_change(row.scores.peak_pressure_pa.mean, reference.peak_pressure_pa.mean));
    fmt::print("{}\n", line);
    table.push_back({{"quirk", row.name},
                     {"layer", row.layer},
                     {"reference_does", row.reference_does},
                     {"physically_right", row.physically_right},
                     {"scores", json_scores(row.scores)}});
  }
  fmt::print("\n");
  nlohmann::json band_json = nlohmann::json::object();
  for (std::size_t k = 0; k < scores.size(); ++k)
    band_json[scores[k].first] = band[k];
  band_json["mean_peak_pressure_pa"] = pressure_band;
  return {{"body", label}, {"paper_compatible", json_scores(reference)}, {"nudge_band_relative", band_json},
          {"quirks", table}};
}

/// The body of body_parameters() as a BodySpec: the rolling model needs the
/// exact body, not a mesh of it.
geometry::BodySpec body_spec_from(const io::Parameters& params)
{
  if (const std::string& file = params.text("mesh_file"); !file.empty())
    throw InputError(fmt::format("option --mesh '{}': --oracle rolling rolls an exact named body, not a mesh; "
                                 "give --body oloid|paper-oloid|roller|cylinder|sphere instead",
                                 file));
  return body_spec_from_parameters(params);
}

nlohmann::json run_rolling(const io::Parameters& params)
{
  if (params.flag("quirk_table") || params.flag("paper_compat") || params.flag("per_face"))
    throw InputError("options --quirk-table, --paper-compat and --per-face belong to the preprint's oracles, not to "
                     "--oracle rolling");
  const geometry::BodySpec spec = body_spec_from(params);
  oracle::RollingStudyParameters p;
  p.mass_kg = params.real("mass_kg");
  p.gravity_m_s2 = params.real("gravity_m_s2");
  p.barrier_energy_excess = params.real("barrier_energy_excess");
  const std::int64_t loops = params.integer("loops"), parts = params.integer("face_subdivisions");
  if (loops < 1 || loops > 1000)
    throw InputError(fmt::format("option --loops: must be 1 to 1000, got {}", loops));
  if (parts < 1 || parts > 64)
    throw InputError(fmt::format("option --face-subdivisions: must be 1 to 64, got {}", parts));
  p.loops = static_cast<int>(loops);
  p.face_subdivisions = static_cast<int>(parts);
  const std::int64_t mass_points = params.integer("mass_points");
  if (mass_points < 16 || mass_points > 1 << 20)
    throw InputError(fmt::format("option --mass-points: must be 16 to {}, got {}", 1 << 20, mass_points));
  p.mass_points = static_cast<int>(mass_points);
  p.contact_width.model =
      params.text("contact_width") == "rigid" ? oracle::ContactWidthModel::rigid : oracle::ContactWidthModel::hertz;
  const std::string label = spec.body == "roller"
                                ? fmt::format("roller({}, {}, {}, {}, {})", params.text("family"),
                                              spec.genome.theta_deg, spec.genome.offset, spec.genome.ratio,
                                              spec.genome.n_circles)
                                : spec.body;
  const auto start = std::chrono::steady_clock::now();
  oracle::RollingStudyResult r;
  try
  {
    r = oracle::rolling_study(spec, p);
  }
  catch (const InputError& e)
  {
    throw InputError(fmt::format("option --oracle rolling with --body {}: {}", label, e.what()));
  }
  const double wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  auto maybe = [](double v) { return std::isnan(v) ? nlohmann::json(nullptr) : io::json_number(v); };
  nlohmann::json j = {
      {"oracle", "rolling"},
      {"body", label},
      {"contact", r.contact},
      {"contact_width", params.text("contact_width")},
      {"uniformity_score", io::json_number(r.uniformity)},
      {"uniformity_score_continuum", maybe(r.continuum_uniformity)},
      {"coverage", io::json_number(r.coverage)},
      {"max_over_mean", io::json_number(r.max_over_mean)},
      {"contact_held", r.contact_held},
      {"loops_completed", io::json_number(r.loops_completed)},
      {"initial_rate_rad_s", io::json_number(r.initial_rate_rad_s)},
      {"loop_period_s", io::json_number(r.loop_period_s)},
      {"scored_time_s", io::json_number(r.scored_time_s)},
      {"max_energy_error", io::json_number(r.max_energy_error)},
      {"centre_of_pressure_min", io::json_number(r.centre_of_pressure_min)},
      {"centre_of_pressure_max", io::json_number(r.centre_of_pressure_max)},
      {"friction_ratio_max", io::json_number(r.friction_ratio_max)},
      {"barrier_energy_excess", p.barrier_energy_excess},
      {"loops", p.loops},
      {"face_subdivisions", p.face_subdivisions},
      {"mass_points", p.mass_points},
      {"n_faces", r.faces},
      {"wall_s", wall_s},
      {"cds", nullptr},
      {"sds", nullptr},
      {"tds", nullptr},
      {"wds_vol", nullptr},
      {"wds_depth", nullptr},
      {"fds", nullptr},
      {"not_computed",
       "the rolling oracle scores its contact measure with the uniformity score U only (README \"The normalised "
       "uniformity score\"); cds, sds, tds, wds_vol, wds_depth and fds are not computed and are null"}};
  spdlog::info("{} (rolling oracle, {} width, {} faces, {:.3f} s): U {:.6g}, U_inf {}, coverage {:.4g}, contact "
               "held {}, loops {:.3g}",
               label, params.text("contact_width"), r.faces, wall_s, r.uniformity,
               std::isnan(r.continuum_uniformity) ? std::string("-") : fmt::format("{:.6g}", r.continuum_uniformity),
               r.coverage, r.contact_held ? "yes" : "no", r.loops_completed);
  return j;
}

nlohmann::json run_oracle(const io::Parameters& params)
{
  if (params.text("oracle") == "rolling")
    return run_rolling(params);
  std::string label;
  const geometry::SurfaceMesh mesh = body_from_parameters(params, &label);
  const Setup setup = setup_from(params);
  if (params.flag("quirk_table"))
  {
    nlohmann::json j = quirk_table(mesh, setup, label);
    j["body"] = label;
    return j;
  }
  const Evaluation e = evaluate(mesh, setup);
  nlohmann::json j = summary_of(e, setup, static_cast<std::size_t>(mesh.faces.rows()), params.flag("per_face"));
  j["body"] = label;
  auto text = [](const std::optional<double>& v) { return v ? fmt::format("{:.6g}", *v) : std::string("-"); };
  spdlog::info("{} ({} oracle, {} faces, {} samples, {:.3f} s): CDS {}, SDS {}, TDS {}, WDS_vol {}, WDS_depth {}, "
               "FDS {}",
               label, setup.rigid ? "rigid-body" : "approximate", mesh.faces.rows(), e.scores.n_samples, e.wall_s,
               text(e.scores.cds), text(e.scores.sds), text(e.scores.tds), text(e.scores.wds_vol),
               text(e.scores.wds_depth), text(e.scores.fds));
  return j;
}
} // namespace

void add_oracle_command(CLI::App& app)
{
  CLI::App* sub = app.add_subcommand(
      "oracle", "Roll a body with the approximate or rigid-body oracle and score its contact, stress, heat, wear "
                "and fatigue distributions, or roll it for real (--oracle rolling) and score its contact with U");
  static std::string json_path;
  add_json_option(sub, json_path);
  static io::SchemaOptions* options = new io::SchemaOptions(sub, oracle_schema());
  register_scene({&oracle_schema(), run_oracle});
  on_run(sub, [] {
    emit_json(json_path, run_oracle(options->apply()));
    return 0;
  });
}
} // namespace rollcheck::cli
