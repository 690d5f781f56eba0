// geometry/convex_ray.h: chords of a line through a convex mesh, against the
// exact chords of the body it approximates.
#include "core/error.h"
#include "geometry/convex_ray.h"
#include "geometry/primitives.h"
#include <cmath>
#include <gtest/gtest.h>

using namespace rollcheck;

TEST(ConvexRay, ChordsOfACylinderAreItsHeightAndItsInscribedPolygonsWidth)
{
  // Radius 1, height 2 about the origin (z from -1 to 1), 64 sides.
  const int sides = 64;
  const geometry::HalfSpaces body = geometry::half_spaces(geometry::cylinder(1.0, 2.0, sides));
  const auto along_axis = geometry::line_chord(body, {0.3, -0.2, 5.0}, {0, 0, 1});
  EXPECT_NEAR(along_axis[0], -6.0, 1e-12);
  EXPECT_NEAR(along_axis[1], -4.0, 1e-12);
  // Across, through the axis: between the inscribed polygon's apothem and the radius.
  const auto across = geometry::line_chord(body, {0, 0, 0.5}, {1, 0, 0});
  const double apothem = std::cos(M_PI / sides);
  EXPECT_GE(across[1], apothem - 1e-12);
  EXPECT_LE(across[1], 1.0 + 1e-12);
  EXPECT_NEAR(across[0], -across[1], 1e-12);
}

TEST(ConvexRay, ALineMissingTheBodyIsAComputationError)
{
  const geometry::HalfSpaces body = geometry::half_spaces(geometry::cylinder(1.0, 2.0, 32));
  EXPECT_THROW(geometry::line_chord(body, {0, 0, 3.0}, {1, 0, 0}), ComputationError);
}
