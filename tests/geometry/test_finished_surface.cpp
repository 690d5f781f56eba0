// The surface a finished part presents to the ground near a ruling's end:
// the two circles' hull (geometry/two_circle_hull_height.h) against the
// oloid's exact geometry at a vertex, and the rolling ball's rounding
// (geometry/rolling_ball_opening.h) against its closed forms.
#include "geometry/rolling_ball_opening.h"
#include "geometry/two_circle_hull_height.h"
#include "core/error.h"
#include <Eigen/Geometry>
#include <cmath>
#include <gtest/gtest.h>
#include <numbers>

using namespace rollcheck;

namespace
{
constexpr double r1 = 0.01;

/// The oloid (r1) standing on the ruling from P = A(-60 deg) to B's far
/// point, P at the origin (scripts/studies/oloid_vertex.py's frame).
struct OloidAtVertex
{
  geometry::SpaceCircle a{Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitZ(), r1};
  geometry::SpaceCircle b{Eigen::Vector3d(r1, 0, 0), Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), r1};
  geometry::GroundFrame ground;
  geometry::SegmentSearch search{-std::numbers::pi / 3 - 0.3, -std::numbers::pi / 3 + 0.3, 64};

  OloidAtVertex()
  {
    const Eigen::Vector3d p = a.at(-std::numbers::pi / 3), end(2 * r1, 0, 0);
    ground.origin = p;
    ground.down = p / r1;
    ground.along = (end - p).normalized();
    ground.across = ground.down.cross(ground.along);
  }
  double height(double x, double y) const { return geometry::two_circle_hull_height(a, b, ground, search, x, y); }
};
} // namespace

TEST(FinishedSurface, OloidHullAtAVertexIsItsSheetAndItsRim)
{
  const OloidAtVertex oloid;
  // The ruling lies on the ground.
  for (const double x : {1e-4, 1e-3, 5e-3})
    EXPECT_NEAR(oloid.height(x, 0), 0.0, 1e-12);
  // Across it the sheet's radius falls linearly to the apex: R = 2 x / sqrt 3.
  for (const double x : {2e-4, 1e-3, 4e-3})
  {
    const double y = 1e-6;
    EXPECT_NEAR(y * y / (2 * oloid.height(x, y)) / (2 * x / std::sqrt(3.0)), 1.0, 0.01) << "x = " << x;
  }
  // Beyond the apex the hull's lowest line is the rim circle A, along the
  // ruling (A's tangent at P).
  for (const double x : {-1e-4, -1e-3})
    EXPECT_NEAR(oloid.height(x, 0) / (r1 - std::sqrt(r1 * r1 - x * x)), 1.0, 1e-3) << "x = " << x;
  // scripts/studies/oloid_vertex.py's table (r1 = 10 mm) off the ruling at the apex.
  EXPECT_NEAR(oloid.height(0, 1e-4) / 1.863e-05, 1.0, 1e-3);
  EXPECT_NEAR(oloid.height(-5e-4, 5e-5) / 2.836e-05, 1.0, 1e-3);
}

// A truncated cone standing on its base: the base disc is a face of the hull,
// so the lower surface over it is the ground itself, which no segment
// between the circles reaches (they all rise from the base's rim).
TEST(FinishedSurface, HullHeightFindsADiscThatIsAFace)
{
  const geometry::SpaceCircle base{Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), 1.0};
  const geometry::SpaceCircle top{Eigen::Vector3d(0, 0, 1), Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), 0.5};
  const geometry::GroundFrame ground{Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(),
                                     -Eigen::Vector3d::UnitZ()};
  const geometry::SegmentSearch search{-std::numbers::pi, std::numbers::pi, 64};
  EXPECT_NEAR(geometry::two_circle_hull_height(base, top, ground, search, 0.3, 0.2), 0.0, 1e-12);
  EXPECT_NEAR(geometry::two_circle_hull_height(top, base, ground, search, -0.6, 0.1), 0.0, 1e-12);
  EXPECT_FALSE(std::isfinite(geometry::two_circle_hull_height(base, top, ground, search, 1.2, 0.0)));
}

TEST(FinishedSurface, RollingBallRoundsACreaseAndLeavesAGentleSurface)
{
  // A crease z = k |y| along x: rounded to k^2 r / 2 + y^2 / (2 r) for
  // |y| <= k r, untouched beyond.
  const double k = 0.2, r = 4e-4, cell = 1e-6;
  const std::size_t nx = 8, ny = 401;
  std::vector<double> crease(nx * ny);
  const auto y_of = [&](std::size_t j) { return (static_cast<double>(j) - 200) * cell; };
  for (std::size_t i = 0; i < nx; ++i)
    for (std::size_t j = 0; j < ny; ++j)
      crease[i * ny + j] = k * std::abs(y_of(j));
  const std::vector<double> rounded = geometry::rolling_ball_opening(crease, nx, ny, cell, cell, r);
  for (std::size_t j = 0; j < ny; ++j)
  {
    const double y = y_of(j);
    const double expected = std::abs(y) <= k * r ? k * k * r / 2 + y * y / (2 * r) : k * std::abs(y);
    EXPECT_NEAR(rounded[3 * ny + j], expected, cell * cell / (100 * r)) << "y = " << y;
  }
  // A paraboloid of radius 2 r: every radius above r, so no change but the
  // grid's, where the ball's touching point (twice as far from the axis as
  // its centre) lies on the grid.
  const std::size_t n = 101;
  std::vector<double> bowl(n * n);
  const auto offset = [](std::size_t i) { return static_cast<double>(i) - 50; };
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j)
      bowl[i * n + j] = (offset(i) * offset(i) + offset(j) * offset(j)) * cell * cell / (4 * r);
  const std::vector<double> same = geometry::rolling_ball_opening(bowl, n, n, cell, cell, r);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j)
      if (std::abs(offset(i)) < 24 && std::abs(offset(j)) < 24)
        EXPECT_NEAR(same[i * n + j], bowl[i * n + j], cell * cell / (100 * r));
  EXPECT_THROW(geometry::rolling_ball_opening(bowl, n, n, cell, cell, -r), InputError);
  EXPECT_THROW(geometry::rolling_ball_opening(bowl, n + 1, n, cell, cell, r), InputError);
}

TEST(FinishedSurface, RollingBallRoundsACreaseBetweenSamples)
{
  // The crease z = k |y - y0| with y0 a third of a cell off the grid: the
  // rounded surface k^2 r / 2 + (y - y0)^2 / (2 r) needs the crease's
  // position between samples: second order, within h^2 / r (the
  // first-order error k h / 3 without it is 27 times that).
  const double k = 0.2, r = 4e-4, cell = 1e-6, y0 = cell / 3;
  const std::size_t nx = 4, ny = 401;
  const auto y_of = [&](std::size_t j) { return (static_cast<double>(j) - 200) * cell; };
  std::vector<double> crease(nx * ny);
  for (std::size_t i = 0; i < nx; ++i)
    for (std::size_t j = 0; j < ny; ++j)
      crease[i * ny + j] = k * std::abs(y_of(j) - y0);
  const std::vector<double> rounded = geometry::rolling_ball_opening(crease, nx, ny, cell, cell, r);
  for (std::size_t j = 100; j <= 300; ++j)
  {
    const double d = y_of(j) - y0;
    const double expected = std::abs(d) <= k * r ? k * k * r / 2 + d * d / (2 * r) : k * std::abs(d);
    EXPECT_NEAR(rounded[ny + j], expected, cell * cell / r) << "y = " << y_of(j);
  }
}
