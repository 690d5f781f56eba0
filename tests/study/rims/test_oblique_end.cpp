// The loop's most oblique rim end (study/rims/oblique_end.h most_oblique_end):
// its section, dihedral and crossing angles obey the oblique end model's
// relation tan S = sin(c) tan D (fem/mesh/oblique_end_angle.h, a different
// construction from contact/rim_dihedral_angle.h's normals), and no end of a
// finer loop moves the exponent further.
#include "contact/wedge_exponent.h"
#include "core/error.h"
#include "fem/mesh/oblique_end_angle.h"
#include "study/rims/oblique_end.h"
#include <cmath>
#include <cstdio>
#include <gtest/gtest.h>
#include <numbers>

using namespace rollcheck;

TEST(ObliqueEnd, OloidsMostObliqueEndObeysTheCrossingRelation)
{
  constexpr double degree = std::numbers::pi / 180;
  geometry::BodySpec oloid;
  oloid.radius_m = 0.01;
  const study::rims::LoopRimEnd e = study::rims::most_oblique_end(oloid, 512);
  std::printf("section %.3f deg, dihedral %.3f deg, crossing %.3f deg, exponent shift %.4f\n",
              e.section_angle_rad / degree, e.dihedral_angle_rad / degree, e.crossing_angle_rad / degree,
              e.exponent_shift);
  EXPECT_NEAR(fem::oblique_dihedral_angle(e.section_angle_rad, e.crossing_angle_rad), e.dihedral_angle_rad, 1e-6);
  EXPECT_DOUBLE_EQ(e.exponent_shift, contact::edge_on_rigid_plane_exponent(e.dihedral_angle_rad)
                                         - contact::edge_on_rigid_plane_exponent(e.section_angle_rad));
  // The rim loop's loaded ends reach a shift of 0.076 (docs/results/rims.md);
  // every end of the loop, loaded or not, at least that.
  EXPECT_GT(e.exponent_shift, 0.07);
  EXPECT_LT(e.crossing_angle_rad, 80 * degree);
  // The same end on a loop sampled twice as finely: within a sample's step.
  const study::rims::LoopRimEnd finer = study::rims::most_oblique_end(oloid, 1024);
  EXPECT_NEAR(finer.exponent_shift, e.exponent_shift, 0.01);
  EXPECT_NEAR(finer.section_angle_rad, e.section_angle_rad, 2 * degree);
}

TEST(ObliqueEnd, OnlyTwoCircleBodiesHaveTheirLoopSearched)
{
  geometry::BodySpec cylinder;
  cylinder.body = "cylinder";
  EXPECT_THROW(study::rims::most_oblique_end(cylinder, 64), InputError);
}
