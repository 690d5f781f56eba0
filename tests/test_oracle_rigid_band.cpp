// Rigid-body scores against the reference outputs. The rigid-body runs are
// chaotic (tests/data/reference/README.md): a 1e-12 rad/s change of the initial
// spin moves the final orientations by ~1e-3 and the scores by up to ~10 %.
// The reference's scores are therefore compared within the band of that
// sensitivity, measured here on our own oracle: every run's initial spin is
// nudged by +-1e-12 rad/s along x, y and z in turn (6 nudged evaluations
// besides the nominal one), and the band half-width of a score is the largest
// |nudged - nominal|. A reference score passes when it lies within that
// half-width of our nominal score, or, where no nudge changes any contact
// (the cylinder's CDS: half-width 0), agrees with it to rounding (1e-12
// relative). Mean peak pressure and stress CV, which average over all
// samples, must agree to 0.5 %.
#include "contact/face_curvature.h"
#include "contact/face_pressure.h"
#include "contact/trajectory_scores.h"
#include "geometry/read_mesh.h"
#include "oracle/rigid_body_oracle.h"
#include <fstream>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace
{
using namespace rollcheck;
const std::string reference_dir = std::string(ROLLCHECK_REFERENCE_DATA_DIR);

struct Scores
{
  double cds, sds, tds, wds_vol, wds_depth, fds, mean_peak_pressure_pa, stress_cv;
};

Scores rigid_scores(const geometry::SurfaceMesh& mesh, const oracle::RigidBodyOptions& options)
{
  const auto compat = oracle::PaperCompat::reference();
  const contact::ContactParameters parameters;
  const oracle::RollingBody body = oracle::make_rolling_body(mesh, compat);
  const contact::FaceCurvature curvature = contact::face_curvature(mesh, parameters.hertz, compat);
  const contact::FacePressure pressure = contact::face_pressure(curvature.effective_radius_m, parameters.hertz, compat);
  const oracle::Trajectory trajectory = oracle::rigid_body_oracle(body, options, compat);
  const contact::ScoreVector s = contact::score_trajectory({body, curvature, pressure}, trajectory, {}, parameters,
                                                           compat, 50);
  return {*s.cds, *s.sds, *s.tds, *s.wds_vol, *s.wds_depth, *s.fds, s.peak_pressure_pa.mean, s.peak_pressure_pa.cv};
}

class RigidBand : public ::testing::TestWithParam<std::string>
{
};

TEST_P(RigidBand, ScoresLieWithinTheNudgeBand)
{
  const std::string name = GetParam();
  const auto mesh = geometry::read_mesh(std::string(ROLLCHECK_REFERENCE_MESH_DIR) + "/" + name + "_reference.obj");
  const auto ref = nlohmann::json::parse(std::ifstream(reference_dir + "/reference_outputs.json"))["geometries"][name];
  const oracle::RigidBodyOptions nominal_options;
  const Scores nominal = rigid_scores(mesh, nominal_options);
  std::vector<Scores> nudged;
  for (int axis = 0; axis < 3; ++axis)
    for (const double sign : {+1.0, -1.0})
    {
      oracle::RigidBodyOptions o = nominal_options;
      for (Eigen::Vector3d& spin : o.initial_spins)
        spin[axis] += sign * 1e-12;
      nudged.push_back(rigid_scores(mesh, o));
    }
  const std::vector<std::pair<std::string, std::pair<double Scores::*, double>>> checks = {
      {"cds", {&Scores::cds, ref["rigid"]["cds"].get<double>()}},
      {"sds", {&Scores::sds, ref["hertz"]["sds"].get<double>()}},
      {"tds", {&Scores::tds, ref["thermal"]["tds"].get<double>()}},
      {"wds_vol", {&Scores::wds_vol, ref["wear"]["wds_vol"].get<double>()}},
      {"wds_depth", {&Scores::wds_depth, ref["wear"]["wds_depth"].get<double>()}},
  };
  for (const auto& [key, check] : checks)
  {
    const auto [member, expected] = check;
    double half_width = 0;
    for (const Scores& s : nudged)
      half_width = std::max(half_width, std::abs(s.*member - nominal.*member));
    std::cout << name << " " << key << ": ours " << nominal.*member << ", reference " << expected
              << ", |diff| " << std::abs(nominal.*member - expected) << ", nudge band +-" << half_width << " ("
              << 100 * half_width / expected << " %)\n";
    EXPECT_LE(std::abs(nominal.*member - expected), std::max(half_width, 1e-12 * std::abs(expected))) << key;
  }
  // FDS is +inf for the cylinder (no stress above the endurance limit).
  if (ref["fatigue"]["fds"].is_number())
  {
    double half_width = 0;
    for (const Scores& s : nudged)
      half_width = std::max(half_width, std::abs(s.fds - nominal.fds));
    const double expected = ref["fatigue"]["fds"].get<double>();
    std::cout << name << " fds: ours " << nominal.fds << ", reference " << expected << ", nudge band +-"
              << half_width << "\n";
    EXPECT_LE(std::abs(nominal.fds - expected), std::max(half_width, 1e-12 * std::abs(expected)));
  }
  else
    EXPECT_TRUE(std::isinf(nominal.fds));
  const double mean_peak = ref["hertz"]["mean_peak_MPa"].get<double>() * 1e6;
  const double stress_cv = ref["hertz"]["stress_cv"].get<double>();
  EXPECT_LT(std::abs(nominal.mean_peak_pressure_pa / mean_peak - 1), 0.005) << nominal.mean_peak_pressure_pa;
  EXPECT_LT(std::abs(nominal.stress_cv / stress_cv - 1), 0.005) << nominal.stress_cv;
}

INSTANTIATE_TEST_SUITE_P(Meshes, RigidBand, ::testing::Values("oloid", "cylinder"));
} // namespace
