// The oblique rim end's angles (fem/mesh/oblique_end_angle.h) against an
// independent construction: the square end's other face turned by Eigen's
// rotations (about y to the dihedral angle, about z to the crossing), its
// trace in the ruling's vertical plane y = 0 measured as an angle through the
// body, and the edge as the line where that face meets the sheet's heights.
#include "fem/mesh/oblique_end_angle.h"
#include <Eigen/Geometry>
#include <cmath>
#include <gtest/gtest.h>
#include <numbers>

using namespace rollcheck;

namespace
{
constexpr double pi = std::numbers::pi, degree = pi / 180;

/// The other face's outward normal for dihedral D and crossing c: +x (a
/// square end at 90 deg) turned about y by D - 90 deg, then about z by c - 90 deg.
Eigen::Vector3d other_face_normal(double dihedral, double crossing)
{
  const Eigen::Matrix3d turn = (Eigen::AngleAxisd(crossing - pi / 2, Eigen::Vector3d::UnitZ())
                                * Eigen::AngleAxisd(dihedral - pi / 2, Eigen::Vector3d::UnitY()))
                                   .toRotationMatrix();
  return turn * Eigen::Vector3d::UnitX();
}

/// The angle through the body (z > 0 side, x < 0 at the sheet) between the
/// sheet z = 0 and the face's trace in the plane y = 0.
double section_of(const Eigen::Vector3d& n)
{
  // The trace n_x x + n_z z = 0 rises from the origin into z > 0 along
  // (-n_z, n_x) (or its opposite); the body's sheet runs along -x.
  Eigen::Vector2d up(-n.z(), n.x());
  if (up.y() < 0)
    up = -up;
  return std::acos(std::clamp(-up.x() / up.norm(), -1.0, 1.0));
}
} // namespace

TEST(ObliqueEndAngle, SectionOfTheTurnedFaceIsTheGivenSection)
{
  for (const double section_deg : {70.0, 100.0, 129.0, 148.5, 175.0})
    for (const double crossing_deg : {20.0, 29.8, 60.0, 89.0})
    {
      const double S = section_deg * degree, c = crossing_deg * degree;
      const double D = fem::oblique_dihedral_angle(S, c);
      // The dihedral lies on the section's side of 90 deg, nearer to it.
      EXPECT_GE((S - pi / 2) * (D - pi / 2), 0.0);
      EXPECT_LE(std::abs(D - pi / 2), std::abs(S - pi / 2) + 1e-12);
      EXPECT_NEAR(section_of(other_face_normal(D, c)), S, 1e-12) << section_deg << " " << crossing_deg;
    }
  // docs/methods/rims.md: 148.5 deg at phi = 60.2 deg (c = 29.8 deg) is a 129 deg dihedral.
  EXPECT_NEAR(fem::oblique_dihedral_angle(148.5 * degree, 29.8 * degree) / degree, 129.0, 0.1);
}

TEST(ObliqueEndAngle, EdgeLiesOnTheTurnedFace)
{
  const double S = 148.5 * degree, c = 29.8 * degree;
  const Eigen::Vector3d n = other_face_normal(fem::oblique_dihedral_angle(S, c), c);
  for (const double y : {-1.0, -0.3, 0.0, 0.5, 1.0})
    for (const double z : {0.0, 0.01, 0.2})
    {
      const Eigen::Vector3d p(fem::oblique_edge_x(S, c, y, z), y, z);
      EXPECT_NEAR(n.dot(p), 0.0, 1e-12) << y << " " << z;
    }
  // The frame: the edge line itself is at distance 0 along the normal.
  double normal = 1, across = -1;
  fem::oblique_edge_frame(c, fem::oblique_edge_x(S, c, -0.4, 0), -0.4, normal, across);
  EXPECT_NEAR(normal, 0.0, 1e-15);
  EXPECT_DOUBLE_EQ(across, 0.4);
}

TEST(ObliqueEndAngle, SquareCrossingIsTheSquareEndBitForBit)
{
  const double c = 90 * degree; // through degrees, as the options give it
  EXPECT_FALSE(fem::crosses_obliquely(c));
  EXPECT_TRUE(fem::crosses_obliquely(89.999 * degree));
  for (const double S : {1.2, 2.0, 2.9})
  {
    EXPECT_EQ(fem::oblique_dihedral_angle(S, c), S);
    EXPECT_EQ(fem::oblique_edge_x(S, c, 0.3, 0.02), -0.02 / std::tan(S));
  }
  double normal = 0, across = 0;
  fem::oblique_edge_frame(c, -0.25, 0.75, normal, across);
  EXPECT_EQ(normal, -0.25);
  EXPECT_EQ(across, 0.75);
}
