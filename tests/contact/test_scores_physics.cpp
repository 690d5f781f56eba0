// The per-event laws of the contact layer on closed-form cases, and the
// scores of hand-made trajectories.
#include "contact/face_curvature.h"
#include "contact/face_pressure.h"
#include "contact/fatigue.h"
#include "contact/sliding_speed.h"
#include "contact/trajectory_scores.h"
#include "contact/wear.h"
#include "core/error.h"
#include "geometry/primitives.h"
#include "oracle/rolling_body.h"
#include <gtest/gtest.h>

namespace
{
using namespace rollcheck;

TEST(Basquin, CyclesToFailureAndMinerDamage)
{
  const contact::FatigueParameters p; // sigma_f' = 700 MPa, b = -0.085, sigma_e = 250 MPa
  // At sigma_f' itself N_f = 1; at 350 MPa N_f = 0.5^(-1/0.085).
  EXPECT_DOUBLE_EQ(contact::cycles_to_failure(700e6, p), 1.0);
  EXPECT_NEAR(contact::cycles_to_failure(350e6, p) / std::pow(2.0, 1 / 0.085), 1.0, 1e-13);
  EXPECT_NEAR(contact::miner_damage_per_cycle(350e6, p) * std::pow(2.0, 1 / 0.085), 1.0, 1e-13);
  // Below the endurance limit: infinite life, no damage; at it: finite.
  EXPECT_TRUE(std::isinf(contact::cycles_to_failure(249.9e6, p)));
  EXPECT_EQ(contact::miner_damage_per_cycle(249.9e6, p), 0.0);
  EXPECT_GT(contact::miner_damage_per_cycle(250e6, p), 0.0);
  EXPECT_EQ(contact::miner_damage_per_cycle(0.0, p), 0.0);
}

TEST(Archard, DepthIsKPressureDistanceOverHardness)
{
  const contact::WearParameters w; // k = 1e-4, H = 2 GPa, dt = 0.05 s
  EXPECT_NEAR(contact::archard_depth(1e8, 0.2, w), 1e-4 * 1e8 * 0.2 * 0.05 / 2e9, 1e-22);
}

TEST(SlidingSpeed, HorizontalPartOfOmegaCrossR)
{
  // omega = (0, 0, 2) about a point 0.5 m away: v = 1 m/s, horizontal.
  EXPECT_DOUBLE_EQ(contact::horizontal_speed({0, 0, 2}, {0.5, 0, 0}), 1.0);
  // omega = (0, 3, 0), r = (0, 0, 1): omega x r = (3, 0, 0).
  EXPECT_DOUBLE_EQ(contact::horizontal_speed({0, 3, 0}, {0, 0, 1}), 3.0);
  // omega parallel to r: no velocity.
  EXPECT_DOUBLE_EQ(contact::horizontal_speed({1, 1, 1}, {2, 2, 2}), 0.0);
}

TEST(MetricSet, ParsesListsAndRejectsUnknownNames)
{
  const contact::MetricSet m = contact::MetricSet::parse("cds,fds", "--metrics");
  EXPECT_TRUE(m.cds && m.fds && !m.sds && !m.tds && !m.wds);
  EXPECT_THROW(contact::MetricSet::parse("cds,xyz", "--metrics"), InputError);
  EXPECT_THROW(contact::MetricSet::parse("", "--metrics"), InputError);
  EXPECT_NO_THROW(contact::MetricSet::parse("all", "--metrics"));
}

/// A trajectory on an icosphere where every sample touches the same two faces.
struct Fixture
{
  geometry::SurfaceMesh mesh = geometry::icosphere(1.0, 1);
  oracle::PaperCompat compat = oracle::PaperCompat::reference();
  oracle::RollingBody body = oracle::make_rolling_body(mesh, compat);
  contact::ContactParameters parameters;
  contact::FaceCurvature curvature = contact::face_curvature(mesh, parameters.hertz, compat);
  contact::FacePressure pressure = contact::face_pressure(curvature.effective_radius_m, parameters.hertz, compat);
  oracle::Trajectory trajectory;

  explicit Fixture(int samples, Eigen::Vector3d omega)
  {
    trajectory.has_angular_velocity = true;
    for (int s = 0; s < samples; ++s)
    {
      trajectory.samples.push_back({Eigen::Matrix3d::Identity(), omega, 0, 0.0, 0});
      trajectory.contact_faces.insert(trajectory.contact_faces.end(), {3, 7});
      trajectory.contact_offsets.push_back(static_cast<int>(trajectory.contact_faces.size()));
    }
  }
};

TEST(TrajectoryScores, FixedContactSetGivesTheOneFaceClosedFormsAndZeroSlidingWithoutSpin)
{
  Fixture fx(10, Eigen::Vector3d::Zero());
  const contact::ScoreVector s = contact::score_trajectory({fx.body, fx.curvature, fx.pressure}, fx.trajectory, {},
                                                           fx.parameters, fx.compat, 5);
  EXPECT_EQ(s.n_samples, 10);
  EXPECT_EQ(s.contact.faces_with, 2);
  EXPECT_EQ(s.per_face.at("contact_counts")[3], 10.0);
  // SDS accumulates 10 p_f on faces 3 and 7.
  Eigen::VectorXd expected = Eigen::VectorXd::Zero(fx.body.face_areas.size());
  expected[3] = 10 * fx.pressure.peak_pressure_pa[3];
  expected[7] = 10 * fx.pressure.peak_pressure_pa[7];
  EXPECT_NEAR(*s.sds, oracle::distribution_score(expected, fx.body.face_areas), 1e-18);
  EXPECT_DOUBLE_EQ(s.peak_pressure_pa.max, std::max(fx.pressure.peak_pressure_pa[3], fx.pressure.peak_pressure_pa[7]));
  EXPECT_EQ(s.peak_pressure_pa.cv, 0.0);
  // No spin, no sliding: TDS and WDS have empty accumulators.
  EXPECT_TRUE(std::isinf(*s.tds));
  EXPECT_TRUE(std::isinf(*s.wds_vol));
  EXPECT_EQ(s.sliding_speed_m_s.cv, 0.0);
  ASSERT_EQ(s.convergence.at("cds").size(), 2u);
}

TEST(TrajectoryScores, FatigueBelowTheEnduranceLimitIsInfinite)
{
  Fixture fx(4, Eigen::Vector3d(0, 0, 1));
  fx.parameters.fatigue.endurance_limit_pa = 1e12;
  const contact::ScoreVector s = contact::score_trajectory({fx.body, fx.curvature, fx.pressure}, fx.trajectory, {},
                                                           fx.parameters, fx.compat, 0);
  EXPECT_TRUE(std::isinf(*s.fds));
  EXPECT_TRUE(std::isinf(s.first_failure_cycles));
  EXPECT_TRUE(std::isinf(s.damage_ratio));
  EXPECT_EQ(s.fraction_above_endurance, 0.0);
  EXPECT_TRUE(std::isfinite(*s.tds));
}

TEST(TrajectoryScores, SlidingMetricsNeedAngularVelocity)
{
  Fixture fx(2, Eigen::Vector3d::Zero());
  fx.trajectory.has_angular_velocity = false;
  EXPECT_THROW(contact::score_trajectory({fx.body, fx.curvature, fx.pressure}, fx.trajectory, {}, fx.parameters,
                                         fx.compat, 0),
               InputError);
  EXPECT_NO_THROW(contact::score_trajectory({fx.body, fx.curvature, fx.pressure}, fx.trajectory,
                                            contact::MetricSet::parse("cds,sds,fds", "test"), fx.parameters, fx.compat,
                                            0));
}
} // namespace
