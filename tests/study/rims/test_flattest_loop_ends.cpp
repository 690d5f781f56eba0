// The loop's orientations by the interior angle of a loaded ruling end
// (study/rims/flattest_loop_ends.h), on the oloid, where the flattest end is known
// in closed form: at c = 1/4 the ruling from P = A(-60 deg) is circle A's
// tangent (180 deg), its sheet's radius across falls to 0 there, and the
// no-tension rule puts q(P) = 8 F / (3 L) on it (scripts/studies/oloid_vertex.py).
#include "study/rims/flattest_loop_ends.h"
#include "core/error.h"
#include "geometry/two_circle_roller.h"
#include "oracle/contact_density.h"
#include "oracle/support_set.h"
#include <cmath>
#include <gtest/gtest.h>
#include <numbers>

using namespace rollcheck;

namespace
{
constexpr double degree = std::numbers::pi / 180;

std::vector<oracle::Circle> oloid_circles(double r1)
{
  return oracle::roller_circles({90, 1, 1, 2}, geometry::RollerFamily::centre_line, r1);
}
} // namespace

TEST(FlattestLoopEnds, OloidsFlattestEndIsItsVertex)
{
  const double r1 = 0.01;
  const std::vector<oracle::Circle> circles = oloid_circles(r1);
  const Eigen::Vector3d centre_of_mass(r1 / 2, 0, 0);
  const study::rims::LoopEnd flattest = study::rims::flattest_loop_ends(circles, centre_of_mass, {}).flattest;
  EXPECT_NEAR(flattest.interior_angle_rad / degree, 180.0, 1e-3);
  EXPECT_NEAR(flattest.centre_of_pressure_from_end(), 0.25, 1e-5);
  EXPECT_LT(flattest.radius_m(), 1e-6 * r1);
  EXPECT_NEAR(flattest.ruling.length_m, std::sqrt(3.0) * r1, 1e-9 * r1);
  // The end is a point of its rim circle at 60 deg from the line of centres.
  const oracle::Circle& rim = circles[static_cast<std::size_t>(flattest.end)];
  EXPECT_NEAR((flattest.point_m() - rim.centre_m).norm(), r1, 1e-12);
  EXPECT_NEAR(std::abs((flattest.point_m() - rim.centre_m).normalized().dot(Eigen::Vector3d::UnitX())), 0.5, 1e-4);
  const double load = 800, c = flattest.centre_of_pressure_from_end();
  EXPECT_NEAR(oracle::line_load(load, c, flattest.ruling.length_m, 0) / (8 * load / (3 * flattest.ruling.length_m)),
              1.0, 1e-4);
}

TEST(FlattestLoopEnds, TheOloidsTwoSidesAreMirrorImages)
{
  const double r1 = 0.01;
  const double angles[] = {150 * degree, 170 * degree, 177.5 * degree};
  const study::rims::FlattestLoopEnds found = study::rims::flattest_loop_ends(oloid_circles(r1), Eigen::Vector3d(r1 / 2, 0, 0),
                                                                  angles);
  ASSERT_EQ(found.at_angle.size(), 3u);
  double last_radius = 1;
  for (std::size_t k = 0; k < 3; ++k)
  {
    const auto& [forward, backward] = found.at_angle[k];
    EXPECT_NEAR(forward.interior_angle_rad, angles[k], 1e-7);
    EXPECT_NEAR(backward.interior_angle_rad, angles[k], 1e-7);
    EXPECT_GT((forward.ruling.direction - backward.ruling.direction).norm(), 1e-3); // two orientations
    EXPECT_NEAR(forward.centre_of_pressure_from_end(), backward.centre_of_pressure_from_end(), 1e-6);
    EXPECT_NEAR(forward.radius_m(), backward.radius_m(), 1e-6 * r1);
    // Away from the vertex the end's sheet widens and c leaves 1/4.
    EXPECT_GT(forward.centre_of_pressure_from_end(), 0.25);
    EXPECT_LT(forward.radius_m(), last_radius);
    last_radius = forward.radius_m();
  }
}

TEST(FlattestLoopEnds, RefusesWhatItCannotFind)
{
  const double r1 = 0.01;
  std::vector<oracle::Circle> circles = oloid_circles(r1);
  const double above[] = {180.5 * degree};
  EXPECT_THROW(study::rims::flattest_loop_ends(circles, Eigen::Vector3d(r1 / 2, 0, 0), above), InputError);
  circles.push_back(circles.front());
  EXPECT_THROW(study::rims::flattest_loop_ends(circles, Eigen::Vector3d(r1 / 2, 0, 0), {}), InputError);
}
