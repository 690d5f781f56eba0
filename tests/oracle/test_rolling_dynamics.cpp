// Rolling without slipping: energy, closed-form motions, and the trajectory's
// own Newton-Euler balance recomputed by finite differences.
#include "core/error.h"
#include "geometry/primitives.h"
#include "geometry/two_circle_roller.h"
#include "oracle/rolling_dynamics.h"
#include <Eigen/Geometry>
#include <cmath>
#include <gtest/gtest.h>
#include <numbers>

using namespace rollcheck;
using namespace rollcheck::oracle;
constexpr double pi = std::numbers::pi;
const Eigen::Vector3d up = Eigen::Vector3d::UnitZ();

namespace
{
struct Roller
{
  TwoCircleBody body;
  MassModel mass;
  Eigen::Vector3d rest;
};

Roller roller(const geometry::RollerGenome& genome, geometry::RollerFamily family)
{
  Roller r{two_circle_body(roller_circles(genome, family, 1.0)),
           mass_model_of_mesh(geometry::two_circle_roller(genome, family, 1.0, 2048), 1.0), {}};
  r.rest = resting_direction(r.body, r.mass, contact_curve_point(r.body, -up));
  return r;
}

Roller oloid() { return roller({90, 1, 1, 2}, geometry::RollerFamily::centre_line); }

double total_energy(const RollingSample& s) { return s.kinetic_energy_j + s.potential_energy_j; }

Eigen::Vector3d axial(const Eigen::Matrix3d& skew) { return {skew(2, 1), skew(0, 2), skew(1, 0)}; }

/// Newton-Euler from central differences of the trajectory: the velocities of
/// the contact points vanish, and the contact force and the moment about the
/// ruling balance the motion as reported.
void expect_newton_euler(const RollingTrajectory& tr, const MassModel& mass, double gravity)
{
  const double h = tr.samples[1].time_s - tr.samples[0].time_s;
  const double size = 1.0;
  for (std::size_t k = 1; k + 1 < tr.samples.size(); k += tr.samples.size() / 7)
  {
    const RollingSample &a = tr.samples[k - 1], &s = tr.samples[k], &b = tr.samples[k + 1];
    const Eigen::Matrix3d w = (b.rotation - a.rotation) / (2 * h) * s.rotation.transpose();
    const Eigen::Vector3d omega = axial((w - w.transpose()) / 2);
    const Eigen::Vector3d velocity = (b.centre_of_mass_m - a.centre_of_mass_m) / (2 * h);
    EXPECT_NEAR((omega - s.angular_velocity_rad_s).norm(), 0, 1e-6 * (1 + omega.norm())) << "t=" << s.time_s;
    for (const Eigen::Vector3d& contact : {s.contact_start_m, s.contact_end_m})
    {
      const Eigen::Vector3d arm = s.rotation * (contact - mass.centre_of_mass_m);
      EXPECT_NEAR((velocity + omega.cross(arm)).norm(), 0, 1e-6 * size) << "slip at t=" << s.time_s;
      EXPECT_NEAR(s.centre_of_mass_m.z() + arm.z(), 0, 1e-12) << "contact point on the plane";
    }
    const Eigen::Vector3d acceleration =
        (b.centre_of_mass_m - 2 * s.centre_of_mass_m + a.centre_of_mass_m) / (h * h);
    const Eigen::Vector3d force = mass.mass_kg * (acceleration + gravity * up);
    EXPECT_NEAR(force.z(), s.normal_force_n, 1e-4 * mass.mass_kg * gravity) << "t=" << s.time_s;
    if (tr.mode == ContactMode::line)
    {
      const Eigen::Vector3d omega_rate = (b.angular_velocity_rad_s - a.angular_velocity_rad_s) / (2 * h);
      const Eigen::Matrix3d inertia = s.rotation * mass.inertia_kg_m2 * s.rotation.transpose();
      const Eigen::Vector3d moment_cm = inertia * omega_rate + omega.cross(inertia * omega);
      const Eigen::Vector3d start = s.rotation * (s.contact_start_m - mass.centre_of_mass_m);
      Eigen::Vector3d axis = s.rotation * (s.contact_end_m - s.contact_start_m);
      const double length = axis.norm();
      axis /= length;
      const Eigen::Vector3d moment_start = moment_cm - start.cross(force);
      EXPECT_NEAR(moment_start.dot(axis), 0, 1e-4) << "forces on the ruling have no moment about it";
      const double end_load = -moment_start.dot(up.cross(axis)) / length;
      EXPECT_NEAR(end_load / force.z(), s.centre_of_pressure, 1e-4) << "t=" << s.time_s;
    }
  }
}
} // namespace

TEST(LineContact, UndampedOloidConservesEnergyOverTenSeconds)
{
  const Roller o = oloid();
  RollingParameters p; // 10 s, undamped
  const RollingTrajectory tr = roll_on_ruling(o.body, o.mass, {o.rest, 1.2, 0}, p);
  ASSERT_TRUE(tr.contact_held);
  ASSERT_DOUBLE_EQ(tr.samples.back().time_s, 10.0);
  EXPECT_GT(tr.samples.back().turning_angle_rad, tr.loop_turning_angle_rad) << "it rolls over, not back and forth";
  const double e0 = total_energy(tr.samples.front());
  double drift = 0;
  for (const RollingSample& s : tr.samples)
    drift = std::max(drift, std::abs(total_energy(s) - e0) / e0);
  EXPECT_LT(drift, 1e-6);
  EXPECT_EQ(drift, tr.max_energy_error);
  std::printf("oloid, 10 s undamped: max relative energy drift %.3g, %ld steps\n", drift, tr.accepted_steps);
}

TEST(LineContact, WithRollingResistanceEnergyFallsMonotonically)
{
  const Roller o = oloid();
  RollingParameters p;
  p.rolling_resistance_n_m_s = 0.02; // the preprint's gamma
  const RollingTrajectory tr = roll_on_ruling(o.body, o.mass, {o.rest, 1.2, 0}, p);
  ASSERT_TRUE(tr.contact_held);
  for (std::size_t k = 1; k < tr.samples.size(); ++k)
  {
    const RollingSample &a = tr.samples[k - 1], &b = tr.samples[k];
    ASSERT_LT(total_energy(b), total_energy(a)) << "t=" << b.time_s;
    // The loss is the work of the resistance, C |omega|^2 dt (trapezoid).
    const double work = 0.01 * (a.rolling_rate_rad_s * a.rolling_rate_rad_s + b.rolling_rate_rad_s * b.rolling_rate_rad_s) *
                        (b.time_s - a.time_s);
    EXPECT_NEAR(total_energy(a) - total_energy(b), work, 1e-3 * work + 1e-12);
  }
  EXPECT_LT(tr.max_energy_error, 1e-9) << "E + W stays E(0)";
}

TEST(LineContact, TrajectorySatisfiesNewtonEulerAndNoSlip)
{
  const Roller o = oloid();
  RollingParameters p;
  p.duration_s = 0.6;
  p.sample_interval_s = 1e-4;
  const RollingTrajectory tr = roll_on_ruling(o.body, o.mass, {o.rest, 2.0, 0.3}, p);
  ASSERT_TRUE(tr.contact_held);
  expect_newton_euler(tr, o.mass, p.gravity_m_s2);
}

TEST(LineContact, ContactRulingIsTheExactSupportSet)
{
  // At every sample the analytic support set of the turned body is the segment
  // the dynamics rolls on, and it touches the plane z = 0.
  const auto circles = roller_circles({90, 1, 1, 2}, geometry::RollerFamily::centre_line, 1.0);
  const Roller o = oloid();
  RollingParameters p;
  p.duration_s = 3;
  const RollingTrajectory tr = roll_on_ruling(o.body, o.mass, {o.rest, 1.2, 0}, p);
  for (std::size_t k = 0; k < tr.samples.size(); k += 100)
  {
    const RollingSample& s = tr.samples[k];
    const CircleSupportSet set = circle_hull_support_set(circles, s.rotation, 1e-9);
    ASSERT_EQ(set.kind, CircleSupportKind::segment) << "t=" << s.time_s;
    EXPECT_NEAR((set.points_m[0] - s.contact_start_m).norm(), 0, 1e-9);
    EXPECT_NEAR((set.points_m[1] - s.contact_end_m).norm(), 0, 1e-9);
    EXPECT_NEAR(set.lowest_height_m + s.centre_of_mass_m.z() - (s.rotation * o.mass.centre_of_mass_m).z(), 0, 1e-12);
  }
}

TEST(LineContact, OloidCentreOfMassHeightSpansItsClosedForm)
{
  // On the contact curve sqrt(x^2 + z^2) = x + sqrt(x^2 + y^2) (u = (x, y, z)),
  // with B = sqrt(x^2 + y^2), 2 x B = 1 - 2 B^2 and the height of the centre
  // (1/2, 0, 0) above the plane is (2 B^2 + 1) / (4 B): between 1/sqrt(2)
  // (B = 1/sqrt(2)) and 3/4 (B = 1/2 and B = 1).
  const Roller o = oloid();
  const ContactLoop loop = trace_contact_loop(o.body, o.rest, 4000);
  double lowest = 1, highest = 0;
  for (const Eigen::Vector3d& u : loop.directions)
  {
    const double h = centre_of_mass_height(ruling_at(o.body, u), o.mass);
    lowest = std::min(lowest, h);
    highest = std::max(highest, h);
  }
  EXPECT_NEAR(lowest, 1 / std::sqrt(2.0), 1e-6);
  EXPECT_NEAR(highest, 0.75, 1e-6);
  EXPECT_NEAR(centre_of_mass_height(ruling_at(o.body, o.rest), o.mass), 1 / std::sqrt(2.0), 1e-9);
}

TEST(LineContact, StewartsTwoCircleRollerKeepsItsCentreOfMassLevel)
{
  // Two perpendicular unit circles with centres sqrt(2) apart (A. T. Stewart,
  // Am. J. Phys. 34 (1966) 166): the centre of mass rolls at constant height.
  const Roller r = roller({90, std::sqrt(2.0), 1, 2}, geometry::RollerFamily::centre_line);
  RollingParameters p;
  p.duration_s = 5;
  const RollingTrajectory tr = roll_on_ruling(r.body, r.mass, {r.rest, 2.0, 0}, p);
  ASSERT_TRUE(tr.contact_held);
  for (const RollingSample& s : tr.samples)
    EXPECT_NEAR(s.centre_of_mass_m.z(), tr.samples.front().centre_of_mass_m.z(), 1e-6);
  EXPECT_NEAR(tr.samples.front().centre_of_mass_m.z(), 1 / std::sqrt(2.0), 1e-6);
}

TEST(LineContact, CylinderRollsStraightAtConstantRate)
{
  const TwoCircleBody body = two_circle_body(cylinder_rims(0.5, 2.0));
  const MassModel mass = mass_model_of_mesh(geometry::cylinder(0.5, 2.0, 2048), 3.0);
  RollingParameters p;
  p.duration_s = 2;
  const double rate = 4.0;
  const RollingTrajectory tr = roll_on_ruling(body, mass, {Eigen::Vector3d::UnitX(), rate, 0.4}, p);
  ASSERT_TRUE(tr.contact_held);
  for (const RollingSample& s : tr.samples)
  {
    EXPECT_NEAR(s.rolling_rate_rad_s, rate, 1e-12);
    EXPECT_NEAR(s.centre_of_pressure, 0.5, 1e-9);
    EXPECT_NEAR(s.normal_force_n, 3.0 * 9.81, 1e-9);
    // The axis stays along the heading; the centre moves across it at r * rate.
    EXPECT_NEAR(s.centre_of_mass_m.head<2>().norm(), 0.5 * rate * s.time_s, 1e-9);
    const Eigen::Vector3d axis = s.rotation * Eigen::Vector3d::UnitZ();
    EXPECT_NEAR(std::abs(axis.dot(Eigen::Vector3d(std::cos(0.4), std::sin(0.4), 0))), 1, 1e-12);
    EXPECT_NEAR(s.centre_of_mass_m.head<2>().dot(axis.head<2>()), 0, 1e-9);
  }
  EXPECT_NEAR(tr.loop_turning_angle_rad, 2 * pi, 1e-6);
}

TEST(LineContact, SmallOscillationsHaveThePendulumPeriod)
{
  // About the resting ruling, J sigma'' = -V''(sigma) sigma: period 2 pi sqrt(J / V''),
  // V'' from a central difference of the centre's height along the contact curve.
  const Roller o = oloid();
  const ContactLoop loop = trace_contact_loop(o.body, o.rest, 20000);
  const double h = loop.turning_angle_rad / 20000;
  auto potential = [&](std::size_t k) { return 9.81 * centre_of_mass_height(ruling_at(o.body, loop.directions[k]), o.mass); };
  const double curvature = (potential(1) - 2 * potential(0) + potential(loop.directions.size() - 1)) / (h * h);
  const double period = 2 * pi * std::sqrt(ruling_inertia(ruling_at(o.body, o.rest), o.mass) / curvature);
  RollingParameters p;
  p.duration_s = 2.5 * period;
  p.sample_interval_s = 1e-4;
  const double amplitude_rate = 1e-3;
  const RollingTrajectory tr = roll_on_ruling(o.body, o.mass, {o.rest, amplitude_rate, 0}, p);
  // Upward zero crossings of sigma after the start are one period apart.
  std::vector<double> crossings;
  for (std::size_t k = 1; k < tr.samples.size(); ++k)
  {
    const double a = tr.samples[k - 1].turning_angle_rad, b = tr.samples[k].turning_angle_rad;
    if (a < 0 && b >= 0)
      crossings.push_back(tr.samples[k - 1].time_s + (tr.samples[k].time_s - tr.samples[k - 1].time_s) * (-a) / (b - a));
  }
  ASSERT_GE(crossings.size(), 2u);
  EXPECT_NEAR(crossings[1] - crossings[0], period, 1e-4 * period);
}

TEST(LineContact, FastRollersLiftARim)
{
  // At 6 rad/s the oloid's centre of pressure leaves its ruling: the run stops there.
  const Roller o = oloid();
  RollingParameters p;
  const RollingTrajectory tr = roll_on_ruling(o.body, o.mass, {o.rest, 6.0, 0}, p);
  EXPECT_FALSE(tr.contact_held);
  const RollingSample& last = tr.samples.back();
  EXPECT_TRUE(last.centre_of_pressure < 0 || last.centre_of_pressure > 1);
  EXPECT_LT(last.time_s, p.duration_s);
  for (std::size_t k = 0; k + 1 < tr.samples.size(); ++k)
    EXPECT_TRUE(tr.samples[k].centre_of_pressure >= 0 && tr.samples[k].centre_of_pressure <= 1);
}

TEST(PointContact, SphereRollsStraightAtConstantSpeed)
{
  const double r = 0.3, rate = 5.0;
  const Ellipsoid sphere{Eigen::Vector3d::Constant(r)};
  const Eigen::Matrix3d tilted = Eigen::AngleAxisd(0.8, Eigen::Vector3d(1, -2, 0.5).normalized()).toRotationMatrix();
  const Eigen::Vector3d omega(rate * std::cos(1.0), rate * std::sin(1.0), 0);
  const RollingTrajectory tr = roll_on_point(sphere, mass_model_of_ellipsoid(sphere, 2.0), {tilted, omega}, {});
  ASSERT_TRUE(tr.contact_held);
  for (const RollingSample& s : tr.samples)
  {
    EXPECT_NEAR((s.angular_velocity_rad_s - omega).norm(), 0, 1e-10);
    EXPECT_NEAR(s.centre_of_mass_m.z(), r, 1e-12);
    // v = a x omega with a = -r e_z: the centre moves along omega x e_z at r |omega|.
    const Eigen::Vector3d expected = r * s.time_s * omega.cross(up);
    EXPECT_NEAR((s.centre_of_mass_m.head<2>() - expected.head<2>()).norm(), 0, 1e-9) << "t=" << s.time_s;
  }
  EXPECT_LT(tr.max_energy_error, 1e-12);
}

TEST(PointContact, EllipsoidConservesEnergyAndRollsWithoutSlip)
{
  const Ellipsoid body{Eigen::Vector3d(1.0, 0.8, 0.6)};
  const MassModel mass = mass_model_of_ellipsoid(body, 1.0);
  const Eigen::Matrix3d start = Eigen::AngleAxisd(0.4, Eigen::Vector3d(1, 1, 0).normalized()).toRotationMatrix();
  RollingParameters p; // 10 s, undamped
  const RollingTrajectory tr = roll_on_point(body, mass, {start, Eigen::Vector3d(1.5, -2.0, 3.0)}, p);
  ASSERT_TRUE(tr.contact_held);
  EXPECT_LT(tr.max_energy_error, 1e-6);
  std::printf("ellipsoid, 10 s undamped: max relative energy drift %.3g, %ld steps\n", tr.max_energy_error,
              tr.accepted_steps);

  RollingParameters fine = p;
  fine.duration_s = 0.5;
  fine.sample_interval_s = 1e-4;
  expect_newton_euler(roll_on_point(body, mass, {start, Eigen::Vector3d(1.5, -2.0, 3.0)}, fine), mass,
                      fine.gravity_m_s2);
}

TEST(PointContact, EnergyErrorFollowsTheLocalTolerance)
{
  // With samples 0.1 s apart the step controller chooses the steps; the energy
  // error over 10 s then stays within a small multiple of the local tolerance.
  const Ellipsoid body{Eigen::Vector3d(1.0, 0.8, 0.6)};
  const Eigen::Matrix3d start = Eigen::AngleAxisd(0.4, Eigen::Vector3d(1, 1, 0).normalized()).toRotationMatrix();
  long previous_steps = 0;
  for (double tolerance : {1e-8, 1e-10, 1e-12})
  {
    RollingParameters p;
    p.sample_interval_s = 0.1;
    p.relative_tolerance = tolerance;
    p.energy_tolerance = 1e3 * tolerance;
    const RollingTrajectory tr =
        roll_on_point(body, mass_model_of_ellipsoid(body, 1.0), {start, Eigen::Vector3d(1.5, -2.0, 3.0)}, p);
    EXPECT_LT(tr.max_energy_error, 100 * tolerance);
    EXPECT_GT(tr.accepted_steps, previous_steps + 100) << "tighter tolerance, more steps";
    previous_steps = tr.accepted_steps;
    std::printf("ellipsoid, tolerance %.0e: %ld steps (%ld rejected), energy error %.3g\n", tolerance,
                tr.accepted_steps, tr.rejected_steps, tr.max_energy_error);
  }
}

TEST(PointContact, EllipsoidWithResistanceLosesEnergyMonotonically)
{
  const Ellipsoid body{Eigen::Vector3d(1.0, 0.8, 0.6)};
  RollingParameters p;
  p.rolling_resistance_n_m_s = 0.02;
  const RollingTrajectory tr = roll_on_point(body, mass_model_of_ellipsoid(body, 1.0),
                                             {Eigen::Matrix3d::Identity(), Eigen::Vector3d(1.5, -2.0, 3.0)}, p);
  for (std::size_t k = 1; k < tr.samples.size(); ++k)
    ASSERT_LT(total_energy(tr.samples[k]), total_energy(tr.samples[k - 1]));
  EXPECT_LT(tr.max_energy_error, 1e-9);
}

TEST(Rolling, RejectsBadInput)
{
  const Roller o = oloid();
  RollingParameters p;
  p.duration_s = -1;
  EXPECT_THROW(roll_on_ruling(o.body, o.mass, {o.rest, 1, 0}, p), InputError);
  p = {};
  p.rolling_resistance_n_m_s = -0.1;
  EXPECT_THROW(roll_on_ruling(o.body, o.mass, {o.rest, 1, 0}, p), InputError);
  p = {};
  MassModel no_mass = o.mass;
  no_mass.mass_kg = 0;
  EXPECT_THROW(roll_on_ruling(o.body, no_mass, {o.rest, 1, 0}, p), InputError);
  EXPECT_THROW(roll_on_ruling(o.body, o.mass, {Eigen::Vector3d::Zero(), 1, 0}, p), InputError);
  const std::vector<Circle> concentric{{Eigen::Vector3d::Zero(), up, 1}, {Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX(), 1}};
  EXPECT_THROW(two_circle_body(concentric), InputError);
}
