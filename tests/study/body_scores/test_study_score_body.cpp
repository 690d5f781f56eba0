// study::body_scores::score_body, the one entry point of `rollcheck oracle`, the search's
// revalidation, the tests and the benchmark: from a mesh file of the
// published code (meshes/reference) to the named JSON keys (to_json), against
// that code's outputs (tests/data/reference/reference_outputs.json). The
// oracles alone are compared with them in test_oracle_reference.cpp, the
// chaotic rigid-body scores within their nudge band in
// test_oracle_rigid_band.cpp. And the quirk table (study/body_scores/paper_quirks.h):
// each row against what its switch must and must not change.
#include "study/body_scores/paper_quirks.h"
#include "study/body_scores/score_body.h"
#include "core/error.h"
#include "geometry/read_mesh.h"
#include "oracle/rigid_body_oracle.h"
#include "oracle/rolling_body.h"
#include <algorithm>
#include <cmath>
#include <fstream>
#include <gtest/gtest.h>
#include <map>
#include <nlohmann/json.hpp>

namespace
{
using namespace rollcheck;

const nlohmann::json& reference(const std::string& name)
{
  static const nlohmann::json j = nlohmann::json::parse(
      std::ifstream(std::string(ROLLCHECK_REFERENCE_DATA_DIR) + "/reference_outputs.json"));
  return j["geometries"][name];
}

std::string reference_mesh(const std::string& name)
{
  return std::string(ROLLCHECK_REFERENCE_MESH_DIR) + "/"
         + (name == "sphere" ? "sphere_icosphere3.obj" : name + "_reference.obj");
}

/// The paper-compatible mode on the mesh the reference scored, every other setting its default.
study::body_scores::ScoreBodySettings paper_settings(const std::string& name, study::body_scores::Oracle oracle)
{
  study::body_scores::ScoreBodySettings s;
  s.body.mesh_file = reference_mesh(name);
  s.oracle = oracle;
  s.compat = oracle::PaperCompat::reference();
  if (oracle == study::body_scores::Oracle::approximate)
    s.metrics.tds = s.metrics.wds = false; // they need angular velocities
  return s;
}

/// A score of the JSON: a number, or "inf".
double number(const nlohmann::json& v)
{
  return v.is_string() ? (v.get<std::string>() == "inf" ? INFINITY : NAN) : v.get<double>();
}

double relative(double ours, double theirs) { return std::abs(ours - theirs) / std::abs(theirs); }

class ScoreBodyReference : public ::testing::TestWithParam<std::string>
{
};

TEST_P(ScoreBodyReference, ApproximateOracleJsonAsTheReference)
{
  const std::string name = GetParam();
  const nlohmann::json& ref = reference(name);
  const nlohmann::json j = to_json(study::body_scores::score_body(paper_settings(name, study::body_scores::Oracle::approximate)), false);
  EXPECT_EQ(j["oracle"], "approx");
  EXPECT_EQ(j["body"], reference_mesh(name));
  EXPECT_EQ(j["n_faces"].get<long>(), ref["mesh"]["n_faces"].get<long>());
  EXPECT_EQ(j["n_samples"].get<long>(), 600); // the reference's n_steps
  EXPECT_LT(relative(number(j["cds"]), ref["approx"]["cds"].get<double>()), 1e-9);
  EXPECT_LT(relative(number(j["contact"]["contact_cv"]), ref["approx"]["contact_cv"].get<double>()), 1e-9);
  EXPECT_LT(relative(number(j["contact"]["max_contact_ratio"]), ref["approx"]["max_contact_ratio"].get<double>()),
            1e-9);
  EXPECT_EQ(j["contact"]["faces_with_contact"].get<long>(), ref["approx"]["faces_with_contact"].get<long>());
  EXPECT_EQ(j["convergence"]["cds"].size(), ref["approx"]["convergence"].size());
  EXPECT_TRUE(j["tds"].is_null() && j["wds_vol"].is_null() && j["wds_depth"].is_null()) << "not asked for";
  EXPECT_TRUE(j["paper_compat"].get<bool>());
}

INSTANTIATE_TEST_SUITE_P(Meshes, ScoreBodyReference, ::testing::Values("oloid", "cylinder", "sphere"));

class ScoreBodyRigidReference : public ::testing::TestWithParam<std::string>
{
};

// One rigid-body trajectory scored every way. CDS, SDS and FDS count contacts
// and pressures of the sampled orientations, which agree with the reference's
// to rounding; TDS and WDS also weigh the angular velocities, which differ by
// ~1e-8 relative and are compared within the nudge band (test_oracle_rigid_band.cpp).
TEST_P(ScoreBodyRigidReference, RigidBodyOracleJsonAsTheReference)
{
  const std::string name = GetParam();
  const nlohmann::json& ref = reference(name);
  const nlohmann::json j = to_json(study::body_scores::score_body(paper_settings(name, study::body_scores::Oracle::rigid)), true);
  constexpr double rounding = 1e-12;
  EXPECT_EQ(j["oracle"], "rigid");
  EXPECT_EQ(j["n_samples"].get<long>(), ref["rigid"]["n_samples"].get<long>());
  EXPECT_LT(relative(number(j["cds"]), ref["rigid"]["cds"].get<double>()), rounding);
  EXPECT_LT(relative(number(j["sds"]), ref["hertz"]["sds"].get<double>()), rounding);
  if (ref["fatigue"]["fds"].is_number())
    EXPECT_LT(relative(number(j["fds"]), ref["fatigue"]["fds"].get<double>()), rounding);
  else // the cylinder: no stress above the endurance limit
    EXPECT_TRUE(std::isinf(number(j["fds"])));
  EXPECT_LT(relative(number(j["mean_peak_pressure_pa"]), 1e6 * ref["hertz"]["mean_peak_MPa"].get<double>()), rounding);
  EXPECT_LT(relative(number(j["stress_cv"]), ref["hertz"]["stress_cv"].get<double>()), rounding);
  EXPECT_LT(relative(number(j["fatigue"]["mean_stress_amplitude_pa"]), 1e6 * ref["fatigue"]["mean_stress_MPa"].get<double>()),
            rounding);
  EXPECT_EQ(j["fatigue"]["fraction_above_endurance"].get<double>(), ref["fatigue"]["pct_above_endurance"].get<double>());
  const nlohmann::json& c = j["curvature"];
  const nlohmann::json& h = ref["hertz"];
  EXPECT_LT(relative(c["face_mean_curvature_mean_per_m"].get<double>(), h["H_face_mean"].get<double>()), rounding);
  EXPECT_LT(relative(c["face_mean_curvature_std_per_m"].get<double>(), h["H_face_std"].get<double>()), rounding);
  EXPECT_LT(relative(c["face_gaussian_curvature_mean_per_m2"].get<double>(), h["K_face_mean"].get<double>()), rounding);
  EXPECT_LT(relative(number(c["effective_radius_min_m"]), h["R_eff_min"].get<double>()), rounding);
  EXPECT_LT(relative(c["effective_radius_max_finite_m"].get<double>(), h["R_eff_max_finite"].get<double>()), rounding);
  EXPECT_EQ(c["flat_faces"].get<long>(), h["n_flat_faces"].get<long>());
  const auto areas = j["per_face"]["face_areas_m2"].get<std::vector<double>>();
  ASSERT_EQ(areas.size(), ref["mesh"]["n_faces"].get<std::size_t>());
  double area = 0;
  for (const double a : areas)
    area += a;
  EXPECT_LT(relative(area, ref["mesh"]["area"].get<double>()), rounding);
}

INSTANTIATE_TEST_SUITE_P(Meshes, ScoreBodyRigidReference, ::testing::Values("oloid", "cylinder"));

// The search scores a revalidated body as `rollcheck oracle` does.
TEST(ScoreBody, SearchRevalidationScoresAsTheOracle)
{
  const study::body_scores::ScoreBodySettings settings = paper_settings("oloid", study::body_scores::Oracle::rigid);
  const study::body_scores::BodyScores direct = study::body_scores::score_body(settings);
  const geometry::SurfaceMesh mesh = geometry::read_mesh(settings.body.mesh_file);
  const oracle::RollingBody body = oracle::make_rolling_body(mesh, settings.compat);
  const oracle::NamedScores named
      = study::body_scores::revalidation_scores(settings)(mesh, body, oracle::rigid_body_oracle(body, settings.rigid, settings.compat));
  const std::map<std::string, double> scores(named.begin(), named.end());
  EXPECT_EQ(scores.at("sds"), *direct.scores.sds);
  EXPECT_EQ(scores.at("tds"), *direct.scores.tds);
  EXPECT_EQ(scores.at("wds_depth"), *direct.scores.wds_depth);
  EXPECT_EQ(scores.at("fds"), *direct.scores.fds);
  EXPECT_EQ(scores.at("mean_peak_pressure_pa"), direct.scores.peak_pressure_pa.mean);
}

// Rolling without slipping: the cylinder touches only its side, uniformly in
// time, so U_inf = A / A_side - 1 = r / h = 1/2 (r = 1, h = 2); the exact
// body's area comes from a polygon of mass_points sides, error ~ 1/n^2.
TEST(ScoreBody, RollingCylinderScoresRadiusOverHeight)
{
  study::body_scores::ScoreBodySettings s;
  s.body.body = "cylinder";
  s.oracle = study::body_scores::Oracle::rolling;
  s.rolling.mass_points = 16384;
  s.rolling.face_subdivisions = 2;
  const study::body_scores::BodyScores r = study::body_scores::score_body(s);
  const nlohmann::json j = to_json(r, false);
  EXPECT_NEAR(j["uniformity_score_continuum"].get<double>(), s.body.radius_m / s.body.height_m, 1e-6);
  EXPECT_EQ(j["n_faces"].get<long>(), 4 * geometry::make_body(s.body).faces.rows());
  EXPECT_TRUE(j["contact_held"].get<bool>());
  EXPECT_TRUE(j["cds"].is_null() && j["fds"].is_null());
}

TEST(ScoreBody, RejectsWhatItCannotRunBeforeRunningIt)
{
  study::body_scores::ScoreBodySettings rolling_mesh = paper_settings("oloid", study::body_scores::Oracle::rolling);
  EXPECT_THROW(study::body_scores::score_body(rolling_mesh), InputError);
  study::body_scores::ScoreBodySettings long_approximate = paper_settings("oloid", study::body_scores::Oracle::approximate);
  long_approximate.approximate.steps = study::body_scores::max_oracle_samples + 1;
  EXPECT_THROW(study::body_scores::score_body(long_approximate), InputError);
  study::body_scores::ScoreBodySettings long_rigid = paper_settings("oloid", study::body_scores::Oracle::rigid);
  long_rigid.rigid.duration_s = 1e6; // 5e8 steps per run
  EXPECT_THROW(study::body_scores::score_body(long_rigid), InputError);
}

const study::body_scores::QuirkTable& cylinder_table()
{
  static const study::body_scores::QuirkTable table = study::body_scores::quirk_table(paper_settings("cylinder", study::body_scores::Oracle::rigid));
  return table;
}

const study::body_scores::QuirkRow& row(const std::string& name)
{
  for (const study::body_scores::QuirkRow& r : cylinder_table().rows)
    if (r.quirk.name == name)
      return r;
  throw std::logic_error("no quirk " + name);
}

TEST(QuirkTable, EachSwitchChangesOnlyWhatItOwns)
{
  const study::body_scores::QuirkTable& t = cylinder_table();
  const contact::ScoreVector& paper = t.band.nominal;
  ASSERT_EQ(t.rows.size(), oracle::quirks().size());
  for (std::size_t k = 0; k < t.rows.size(); ++k)
    EXPECT_EQ(t.rows[k].quirk.name, oracle::quirks()[k].name);
  // Contact-layer switches rescore the same trajectory: its contacts are unchanged.
  for (const study::body_scores::QuirkRow& r : t.rows)
    if (r.quirk.layer == "contact")
      EXPECT_EQ(*r.scores.cds, *paper.cds) << r.quirk.name;
  EXPECT_NE(*row("ground_at_lowest_centroid").scores.cds, *paper.cds);
  // E* = E / (1 - nu^2) is twice the identical-bodies modulus, and the Hertz
  // peak p0 grows as E*^(2/3); the normalised SDS does not change.
  const contact::ScoreVector& modulus = row("identical_bodies_modulus").scores;
  EXPECT_NEAR(modulus.peak_pressure_pa.mean / paper.peak_pressure_pa.mean, std::cbrt(4.0), 1e-12);
  EXPECT_NEAR(*modulus.sds / *paper.sds, 1.0, 1e-12);
  // The stress amplitude enters FDS only.
  const contact::ScoreVector& amplitude = row("peak_pressure_as_stress_amplitude").scores;
  for (const study::body_scores::ScoreColumn& c : study::body_scores::score_columns())
    if (c.key != "FDS")
      EXPECT_EQ(c.value(amplitude), c.value(paper)) << c.key;
}

TEST(QuirkTable, BandJsonAndMarkdown)
{
  const study::body_scores::QuirkTable& t = cylinder_table();
  ASSERT_EQ(t.band.nudged.size(), 6u);
  const study::body_scores::ScoreColumn& cds = study::body_scores::score_columns().front();
  // No 1e-12 rad/s nudge changes which faces of the cylinder touch.
  EXPECT_EQ(study::body_scores::half_width(t.band, cds), 0.0);
  const nlohmann::json j = to_json(t);
  EXPECT_EQ(j["body"], reference_mesh("cylinder"));
  EXPECT_EQ(j["quirks"].size(), oracle::quirks().size());
  EXPECT_EQ(j["paper_compatible"]["CDS"].get<double>(), *t.band.nominal.cds);
  EXPECT_EQ(j["nudge_band_relative"].size(), study::body_scores::score_columns().size());
  const std::string markdown = study::body_scores::to_markdown(t);
  // title, blank, header, rule, paper-compatible values, band, a row per switch, blank
  EXPECT_EQ(std::count(markdown.begin(), markdown.end(), '\n'), static_cast<long>(7 + oracle::quirks().size()));
  EXPECT_NE(markdown.find("| identical_bodies_modulus | contact |"), std::string::npos);
}
} // namespace
