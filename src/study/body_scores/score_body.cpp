#include "study/body_scores/score_body.h"
#include "core/error.h"
#include <chrono>
#include <ctime>
#include <cmath>
#include <fmt/format.h>
#include <limits>
#include <utility>

namespace rollcheck::study::body_scores
{
namespace
{
/// The checks of the oracle about to run, before any mesh is built.
void validate(const ScoreBodySettings& s)
{
  if (s.oracle == Oracle::rolling && !s.body.mesh_file.empty())
    throw InputError(fmt::format("mesh file '{}': the rolling oracle rolls an exact named body, not a mesh; give a "
                                 "body oloid, paper-oloid, roller, cylinder or sphere instead",
                                 s.body.mesh_file));
  if (s.oracle == Oracle::rolling && s.continuum.time_law == contact::TimeLaw::uniform_rate
      && s.continuum.load_rule == contact::LoadRule::dynamic)
    throw InputError("--time-law uniform_rate needs --load-rule static or uniform: the dynamic load is the free motion's, and no "
                     "free motion rolls at a uniform rate");
  if (s.oracle == Oracle::rolling)
    return; // oracle::real_rolling checks its parameters and the body
  contact::validate(s.contact);
  if (s.oracle == Oracle::approximate)
  {
    oracle::validate(s.approximate);
    if (s.approximate.steps > max_oracle_samples)
      throw InputError(fmt::format("approximate oracle: at most {} steps (a resource guard), got {}",
                                   max_oracle_samples, s.approximate.steps));
    return;
  }
  oracle::validate(s.rigid);
  const long samples
      = static_cast<long>(s.rigid.initial_spins.size()) * (oracle::steps_per_run(s.rigid) / s.rigid.sample_every + 1);
  if (samples > max_oracle_samples)
    throw InputError(fmt::format("rigid-body oracle: {} runs of {} steps sampled every {} give {} samples, more "
                                 "than {} (a resource guard)",
                                 s.rigid.initial_spins.size(), oracle::steps_per_run(s.rigid), s.rigid.sample_every,
                                 samples, max_oracle_samples));
}

/// A trajectory's scores with the curvatures and pressures they were counted with.
struct Scored
{
  contact::FaceCurvature curvature;
  contact::FacePressure pressure;
  contact::ScoreVector scores;
};

Scored score_rolled(const geometry::SurfaceMesh& mesh, const oracle::RollingBody& body,
                    const oracle::Trajectory& trajectory, const ScoreBodySettings& s)
{
  Scored out;
  out.curvature = contact::face_curvature(mesh, s.contact.hertz, s.compat);
  out.pressure = contact::face_pressure(out.curvature.effective_radius_m, s.contact.hertz, s.compat);
  out.scores = contact::score_trajectory({body, out.curvature, out.pressure}, trajectory, s.metrics, s.contact,
                                         s.compat, s.convergence_every);
  return out;
}

nlohmann::json array_of(const Eigen::VectorXd& v)
{
  nlohmann::json a = nlohmann::json::array();
  for (Eigen::Index i = 0; i < v.size(); ++i)
    a.push_back(json_number(v[i]));
  return a;
}

const char* oracle_name(Oracle o) { return o == Oracle::rigid ? "rigid" : o == Oracle::approximate ? "approx" : "rolling"; }

/// The statistics of each score asked for, under the keys the audit and the plots read.
void add_statistics(nlohmann::json& j, const contact::ScoreVector& v, const contact::MetricSet& m)
{
  if (m.cds)
    j["contact"] = {{"contact_cv", json_number(v.contact.cv)},
                    {"max_contact_ratio", json_number(v.contact.max_mean_ratio)},
                    {"faces_with_contact", v.contact.faces_with},
                    {"faces_without_contact", v.contact.faces_without}};
  j["mean_peak_pressure_pa"] = m.sds ? json_number(v.peak_pressure_pa.mean) : nlohmann::json(nullptr);
  j["stress_cv"] = m.sds ? json_number(v.peak_pressure_pa.cv) : nlohmann::json(nullptr);
  if (m.sds)
    j["hertz"] = {{"min_peak_pressure_pa", json_number(v.peak_pressure_pa.min)},
                  {"max_peak_pressure_pa", json_number(v.peak_pressure_pa.max)},
                  {"touching_samples", v.peak_pressure_pa.count},
                  {"effective_modulus_pa", v.effective_modulus_pa}};
  if (m.fds)
    j["fatigue"] = {{"damage_ratio", json_number(v.damage_ratio)},
                    {"first_failure_cycles", json_number(v.first_failure_cycles)},
                    {"mean_stress_amplitude_pa", json_number(v.fatigue_stress_pa.mean)},
                    {"max_stress_amplitude_pa", json_number(v.fatigue_stress_pa.max)},
                    {"fraction_above_endurance", v.fraction_above_endurance}};
  if (m.tds)
    j["thermal"] = {{"heat_ratio", json_number(v.heat_ratio)}};
  if (m.needs_sliding())
    j["sliding"] = {{"mean_speed_m_s", json_number(v.sliding_speed_m_s.mean)},
                    {"max_speed_m_s", json_number(v.sliding_speed_m_s.max)},
                    {"speed_cv", json_number(v.sliding_speed_m_s.cv)}};
  if (m.wds)
    j["wear"] = {{"wear_depth_ratio", json_number(v.wear_depth_ratio)}};
}

nlohmann::json curvature_json(const contact::FaceCurvature& c)
{
  double r_min = std::numeric_limits<double>::infinity(), r_max = 0;
  for (Eigen::Index f = 0; f < c.effective_radius_m.size(); ++f)
    if (std::isfinite(c.effective_radius_m[f]))
    {
      r_min = std::min(r_min, c.effective_radius_m[f]);
      r_max = std::max(r_max, c.effective_radius_m[f]);
    }
  const double h_mean = c.mean.mean();
  return {{"face_mean_curvature_mean_per_m", h_mean},
          {"face_mean_curvature_std_per_m", std::sqrt((c.mean.array() - h_mean).square().mean())},
          {"face_gaussian_curvature_mean_per_m2", c.gaussian.mean()},
          {"effective_radius_min_m", json_number(r_min)},
          {"effective_radius_max_finite_m", r_max},
          {"flat_faces", c.flat_faces}};
}

/// The keys of every oracle's record: the oracle, the body, the preprint's
/// six scores (null where not computed, as under real rolling), the faces
/// and the time.
nlohmann::json record_json(const BodyScores& r)
{
  const contact::ScoreVector& v = r.scores;
  nlohmann::json j = {{"oracle", oracle_name(r.oracle)},
                      {"body", r.body},
                      {"cds", json_number(v.cds)},
                      {"sds", json_number(v.sds)},
                      {"tds", json_number(v.tds)},
                      {"wds_vol", json_number(v.wds_vol)},
                      {"wds_depth", json_number(v.wds_depth)},
                      {"fds", json_number(v.fds)},
                      {"n_faces", r.n_faces},
                      {"wall_s", r.wall_s},
                      {"cpu_s", r.cpu_s}};
  return j;
}

/// The preprint's oracles' keys beyond record_json.
nlohmann::json oracle_json(const BodyScores& r, bool per_face)
{
  const contact::ScoreVector& v = r.scores;
  nlohmann::json j = {{"n_samples", v.n_samples},
                      {"paper_compat", oracle::describe(r.compat) == oracle::describe(oracle::PaperCompat::reference())}};
  nlohmann::json quirks = nlohmann::json::object();
  for (const oracle::Quirk& q : oracle::quirks())
    quirks[std::string(q.name)] = r.compat.*q.flag ? "paper" : "corrected";
  j["quirks"] = quirks;
  add_statistics(j, v, r.metrics);
  j["curvature"] = curvature_json(r.curvature);
  nlohmann::json convergence = nlohmann::json::object();
  for (const auto& [key, points] : v.convergence)
  {
    nlohmann::json list = nlohmann::json::array();
    for (const auto& [n, score] : points)
      list.push_back({n, json_number(score)});
    convergence[key] = list;
  }
  j["convergence"] = convergence;
  if (per_face)
  {
    nlohmann::json pf = {{"face_areas_m2", array_of(r.face_areas_m2)},
                         {"effective_radius_m", array_of(r.curvature.effective_radius_m)},
                         {"mean_curvature_per_m", array_of(r.curvature.mean)},
                         {"gaussian_curvature_per_m2", array_of(r.curvature.gaussian)},
                         {"peak_pressure_pa", array_of(r.pressure.peak_pressure_pa)}};
    for (const auto& [key, values] : v.per_face)
      pf[key] = array_of(values);
    j["per_face"] = pf;
  }
  return j;
}

/// Real rolling's keys beyond record_json.
nlohmann::json rolling_json(const BodyScores& s)
{
  const oracle::RollingStudyResult& r = s.rolling;
  const oracle::RollingStudyParameters& p = s.rolling_parameters;
  auto maybe = [](double v) { return std::isnan(v) ? nlohmann::json(nullptr) : json_number(v); };
  const contact::ContinuumLoopSettings& c = s.continuum_settings;
  auto continuum = [&](auto value) { return s.continuum ? json_number(value(*s.continuum)) : nlohmann::json(nullptr); };
  using Scores = contact::ContinuumLoopScores;
  nlohmann::json j = {
      {"load_rule", name_of(contact::load_rule_names(), c.load_rule, "load rule")},
      {"end_margin", c.end_margin},
      {"time_law", name_of(contact::time_law_names(), c.time_law, "time law")},
      {"accumulated_pressure_continuum", continuum([](const Scores& x) { return x.accumulated_pressure.whole; })},
      {"peak_pressure_continuum", continuum([](const Scores& x) { return x.peak_pressure.whole; })},
      {"peak_to_mean_pressure_continuum", continuum([](const Scores& x) { return x.peak_pressure.peak_to_mean; })},
      {"basquin_damage_continuum", continuum([](const Scores& x) { return x.damage.whole; })}};
  j.update(nlohmann::json{{"contact", r.contact},
          {"contact_width", p.contact_width.model == oracle::ContactWidthModel::rigid ? "geometric" : "hertz"},
          {"uniformity_score", json_number(r.uniformity)},
          // U_inf under the named choices (contact/continuum_loop_scores.h); the oracle's own (dynamic load) for point contact.
          {"uniformity_score_continuum",
           s.continuum ? json_number(s.continuum->contact_time.whole) : maybe(r.continuum_uniformity)},
          {"coverage", json_number(r.coverage)},
          {"max_over_mean", json_number(r.max_over_mean)},
          {"contact_held", r.contact_held},
          {"loops_completed", json_number(r.loops_completed)},
          {"initial_rate_rad_s", json_number(r.initial_rate_rad_s)},
          {"loop_period_s", json_number(r.loop_period_s)},
          {"scored_time_s", json_number(r.scored_time_s)},
          {"max_energy_error", json_number(r.max_energy_error)},
          {"centre_of_pressure_min", json_number(r.centre_of_pressure_min)},
          {"centre_of_pressure_max", json_number(r.centre_of_pressure_max)},
          {"friction_ratio_max", json_number(r.friction_ratio_max)},
          {"rolling_energy", p.rolling_energy},
          {"loops", p.loops},
          {"face_subdivisions", p.face_subdivisions},
          {"mass_points", p.mass_points},
          {"not_computed",
           "the rolling oracle scores its contact measure with the uniformity score U and the continuum scores of "
           "contact/continuum_loop_scores.h; the template scores cds, sds, tds, wds_vol, wds_depth and fds are not "
           "computed and are null"}});
  return j;
}
} // namespace

contact::ScoreVector score_trajectory(const geometry::SurfaceMesh& mesh, const oracle::RollingBody& body,
                                      const oracle::Trajectory& trajectory, const ScoreBodySettings& s)
{
  return score_rolled(mesh, body, trajectory, s).scores;
}

oracle::RevalidationMetrics revalidation_scores(const ScoreBodySettings& settings)
{
  return [settings](const geometry::SurfaceMesh& mesh, const oracle::RollingBody& body,
                    const oracle::Trajectory& trajectory) {
    const contact::ScoreVector v = score_trajectory(mesh, body, trajectory, settings);
    oracle::NamedScores out;
    if (v.sds)
    {
      out.emplace_back("sds", *v.sds);
      out.emplace_back("mean_peak_pressure_pa", v.peak_pressure_pa.mean);
      out.emplace_back("stress_cv", v.peak_pressure_pa.cv);
    }
    if (v.tds)
      out.emplace_back("tds", *v.tds);
    if (v.wds_vol)
      out.emplace_back("wds_vol", *v.wds_vol), out.emplace_back("wds_depth", *v.wds_depth);
    if (v.fds)
      out.emplace_back("fds", *v.fds);
    return out;
  };
}

contact::ContinuumLoopSettings rolling_continuum_settings(const ScoreBodySettings& s)
{
  contact::ContinuumLoopSettings c = s.continuum;
  c.width = s.rolling.contact_width.model;
  return c;
}

BodyScores score_body(const ScoreBodySettings& s)
{
  validate(s);
  const auto start = std::chrono::steady_clock::now();
  const std::clock_t cpu_start = std::clock();
  BodyScores r;
  r.body = geometry::body_label(s.body);
  r.oracle = s.oracle;
  if (s.oracle == Oracle::rolling)
  {
    oracle::RealRolling run;
    try
    {
      run = oracle::real_rolling(s.body, s.rolling);
    }
    catch (const InputError& e)
    {
      throw InputError(fmt::format("rolling oracle on {}: {}", r.body, e.what()));
    }
    r.rolling = oracle::score_real_rolling(run, geometry::make_body(s.body), s.rolling);
    r.rolling_parameters = s.rolling;
    r.n_faces = r.rolling.faces;
    r.continuum_settings = rolling_continuum_settings(s);
    if (s.with_continuum && run.trajectory.mode == oracle::ContactMode::line && std::isfinite(run.first_loop_end_s))
      r.continuum = contact::continuum_loop_scores(
          run.trajectory, 0, run.first_loop_end_s, run.surface_area_m2,
          {run.mass.centre_of_mass_m, run.mass.mass_kg, s.rolling.gravity_m_s2}, r.continuum_settings);
  }
  else
  {
    const geometry::SurfaceMesh mesh = geometry::make_body(s.body);
    const oracle::RollingBody body = oracle::make_rolling_body(mesh, s.compat);
    const oracle::Trajectory trajectory = s.oracle == Oracle::rigid
                                              ? oracle::rigid_body_oracle(body, s.rigid, s.compat)
                                              : oracle::approximate_oracle(body, s.approximate, s.compat);
    Scored scored = score_rolled(mesh, body, trajectory, s);
    r.scores = std::move(scored.scores);
    r.curvature = std::move(scored.curvature);
    r.pressure = std::move(scored.pressure);
    r.face_areas_m2 = body.face_areas;
    r.compat = s.compat;
    r.metrics = s.metrics;
    r.n_faces = static_cast<long>(mesh.faces.rows());
  }
  r.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  r.cpu_s = static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC;
  return r;
}

nlohmann::json to_json(const BodyScores& scores, bool per_face)
{
  nlohmann::json j = record_json(scores);
  j.update(scores.oracle == Oracle::rolling ? rolling_json(scores) : oracle_json(scores, per_face));
  return j;
}

std::string summary_line(const BodyScores& s)
{
  if (s.oracle == Oracle::rolling)
  {
    const oracle::RollingStudyResult& r = s.rolling;
    return fmt::format("{} (rolling oracle, {} width, {} faces, {:.3f} s): U {:.6g}, U_inf {}, coverage {:.4g}, "
                       "contact held {}, loops {:.3g}",
                       s.body, s.rolling_parameters.contact_width.model == oracle::ContactWidthModel::rigid ? "rigid"
                                                                                                           : "hertz",
                       r.faces, s.wall_s, r.uniformity,
                       std::isnan(r.continuum_uniformity) ? std::string("-")
                                                          : fmt::format("{:.6g}", r.continuum_uniformity),
                       r.coverage, r.contact_held ? "yes" : "no", r.loops_completed);
  }
  auto text = [](const std::optional<double>& v) { return v ? fmt::format("{:.6g}", *v) : std::string("-"); };
  const contact::ScoreVector& v = s.scores;
  return fmt::format("{} ({} oracle, {} faces, {} samples, {:.3f} s): CDS {}, SDS {}, TDS {}, WDS_vol {}, "
                     "WDS_depth {}, FDS {}",
                     s.body, s.oracle == Oracle::rigid ? "rigid-body" : "approximate", s.n_faces, v.n_samples,
                     s.wall_s, text(v.cds), text(v.sds), text(v.tds), text(v.wds_vol), text(v.wds_depth),
                     text(v.fds));
}
} // namespace rollcheck::study::body_scores
