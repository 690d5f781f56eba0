// The rim's dihedral angle (contact/rim_dihedral_angle.h) against an
// independent construction: the two support planes of the hull through the
// rim's tangent line at a ruling's end are the planes through that line
// tangent to the other circle (the two sheets of the developable hull, each
// holding a ruling from the end point), found here by the root of
// (q - s) . (t x t_q) = 0 over the other circle's points q (t_q its tangent
// there), not by turning the ground's normal as rim_overhang does. One of
// them is the ground's plane (normal u); the other's outward normal n gives
// the dihedral pi - arccos(u . n). Also the relation to the section angle
// of rim_overhang: tan(pi - section) = cos(phi) tan(pi - dihedral).
#include "contact/rim_dihedral_angle.h"
#include "contact/rim_overhang.h"
#include "geometry/two_circle_roller.h"
#include "oracle/rolling_dynamics.h"
#include "oracle/support_set.h"
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <numbers>
#include <vector>

using namespace rollcheck;

namespace
{
constexpr double pi = std::numbers::pi;

/// Outward unit normals of the planes through the line s + l t tangent to
/// `other` that leave both circles' centres on their inner side.
std::vector<Eigen::Vector3d> tangent_planes_through_line(const oracle::Circle& on, const oracle::Circle& other,
                                                         const Eigen::Vector3d& s, const Eigen::Vector3d& t)
{
  const Eigen::Vector3d e1 = other.normal.unitOrthogonal(), e2 = other.normal.cross(e1);
  auto point = [&](double a) {
    return Eigen::Vector3d(other.centre_m + other.radius_m * (std::cos(a) * e1 + std::sin(a) * e2));
  };
  auto residual = [&](double a) {
    const Eigen::Vector3d tangent = -std::sin(a) * e1 + std::cos(a) * e2;
    return (point(a) - s).dot(t.cross(tangent));
  };
  std::vector<Eigen::Vector3d> normals;
  const int n = 7200;
  for (int k = 0; k < n; ++k)
  {
    double lo = 2 * pi * k / n, hi = 2 * pi * (k + 1) / n;
    if (residual(lo) * residual(hi) > 0)
      continue;
    for (int i = 0; i < 80; ++i)
    {
      const double mid = 0.5 * (lo + hi);
      (residual(lo) * residual(mid) <= 0 ? hi : lo) = mid;
    }
    Eigen::Vector3d normal = t.cross(point(lo) - s).normalized();
    if (normal.dot(other.centre_m - s) > 0)
      normal = -normal;
    if (normal.dot(on.centre_m - s) <= 1e-12 * on.radius_m)
      normals.push_back(normal);
  }
  return normals;
}

/// Over the loop of a two-circle body, every loaded or not end away from
/// the points where the ruling runs along the rim: the construction's
/// dihedral, rim_dihedral_angle's, and the section relation.
void check_loop(const geometry::RollerGenome& genome, double r1)
{
  const std::vector<oracle::Circle> circles
      = oracle::roller_circles(genome, geometry::RollerFamily::centre_line, r1);
  const oracle::TwoCircleBody body = oracle::two_circle_body(circles);
  const oracle::ContactLoop loop
      = oracle::trace_contact_loop(body, oracle::contact_curve_point(body, -Eigen::Vector3d::UnitZ()), 97);
  int checked = 0;
  double oblique_most = 0;
  for (const Eigen::Vector3d& direction : loop.directions)
  {
    const oracle::Ruling ruling = oracle::ruling_at(body, direction);
    const std::array<double, 2> dihedral = contact::rim_dihedral_angle(circles, 0, 1, ruling);
    const std::array<double, 2> overhang = contact::rim_overhang(circles, 0, 1, ruling);
    for (const int e : {0, 1})
    {
      const oracle::Circle& on = circles[static_cast<std::size_t>(e)];
      const oracle::Circle& other = circles[static_cast<std::size_t>(1 - e)];
      const Eigen::Vector3d s = e == 0 ? ruling.start_m : ruling.end_m;
      const Eigen::Vector3d t = on.normal.cross(s - on.centre_m).normalized();
      const double along_rim = std::abs(t.dot(ruling.axis));
      if (along_rim > 0.97) // near the oloid's vertex: the two sheets' rulings meet the rim tangentially
        continue;
      const std::vector<Eigen::Vector3d> normals = tangent_planes_through_line(on, other, s, t);
      ASSERT_EQ(normals.size(), 2u) << "end " << e << " at u = " << direction.transpose();
      const bool first_is_ground = (normals[0] - ruling.direction).norm() < (normals[1] - ruling.direction).norm();
      const Eigen::Vector3d& ground = normals[first_is_ground ? 0 : 1];
      const Eigen::Vector3d& beyond = normals[first_is_ground ? 1 : 0];
      EXPECT_LT((ground - ruling.direction).norm(), 1e-6);
      const double expected = pi - std::acos(std::clamp(ruling.direction.dot(beyond), -1.0, 1.0));
      EXPECT_NEAR(dihedral[static_cast<std::size_t>(e)], expected, 1e-6);

      // The section in the ruling's vertical plane from the dihedral and the crossing angle.
      const double section = pi / 2 + overhang[static_cast<std::size_t>(e)];
      const double cos_phi = std::abs(ruling.axis.dot(t.cross(ruling.direction)));
      const double d = dihedral[static_cast<std::size_t>(e)];
      // The relation holds for the angles modulo pi (atan's branch).
      const double mismatch = (pi - section) - std::atan(cos_phi * std::tan(pi - d));
      EXPECT_NEAR(std::remainder(mismatch, pi), 0.0, 1e-6);
      // Both on the same side of 90 deg, the dihedral nearer to it.
      EXPECT_GE((section - pi / 2) * (d - pi / 2), 0.0);
      EXPECT_LE(std::abs(d - pi / 2), std::abs(section - pi / 2) + 1e-9);
      oblique_most = std::max(oblique_most, std::abs(section - d));
      ++checked;
    }
  }
  EXPECT_GT(checked, 100);
  EXPECT_GT(oblique_most, 5 * pi / 180); // the loop has obtuse ends crossed obliquely
}
} // namespace

TEST(RimDihedralAngle, OloidAgreesWithTheTangentPlanesOfTheOtherCircle) { check_loop({90, 1, 1, 2}, 0.01); }

TEST(RimDihedralAngle, UnequalCirclesAgreeWithTheTangentPlanesOfTheOtherCircle)
{
  check_loop({120, 1.0, 0.8, 2}, 0.01);
}

