// Hertz's subsurface maxima (contact/hertz.h) against Johnson's values, and
// their per-thread memory of the last Poisson's ratio: asking for another
// ratio, and then the first again, gives each its own values.
#include "contact/hertz.h"
#include <gtest/gtest.h>

using namespace rollcheck;

TEST(HertzSubsurface, MaximaLieWhereJohnsonPutsThem)
{
  const double modulus = 2.2e11;
  // Line contact (Johnson, Contact Mechanics, sec. 4.2, fig. 4.6): the
  // principal shear stress peaks at 0.300 p0, 0.786 b deep, whatever nu.
  const contact::LineHertz line = contact::line_contact(1e4, 0.01, modulus, 0.3);
  EXPECT_NEAR(line.max_shear_pa / line.peak_pressure_pa, 0.300, 5e-4);
  EXPECT_NEAR(line.max_shear_depth_m / line.half_width_m, 0.786, 2e-3);
  // Plane strain, nu = 0.3: von Mises peaks at 0.56 p0, 0.70 b deep.
  EXPECT_NEAR(line.max_von_mises_pa / line.peak_pressure_pa, 0.56, 5e-3);
  EXPECT_NEAR(line.max_von_mises_depth_m / line.half_width_m, 0.70, 1e-2);
  // Point contact, nu = 0.3 (sec. 3.4, fig. 3.7): 0.31 p0, 0.48 a deep.
  const contact::PointHertz point = contact::point_contact(100, 0.01, modulus, 0.3);
  EXPECT_NEAR(point.max_shear_pa / point.peak_pressure_pa, 0.31, 5e-3);
  EXPECT_NEAR(point.max_shear_depth_m / point.contact_radius_m, 0.48, 1e-2);
}

TEST(HertzSubsurface, EachPoissonRatioKeepsItsOwnMaxima)
{
  const double modulus = 2.2e11;
  const contact::LineHertz first = contact::line_contact(1e4, 0.01, modulus, 0.3);
  const contact::LineHertz other = contact::line_contact(1e4, 0.01, modulus, 0.1);
  const contact::LineHertz again = contact::line_contact(1e4, 0.01, modulus, 0.3);
  // A lower nu loads sigma_y less: a higher von Mises peak.
  EXPECT_GT(other.max_von_mises_pa, 1.05 * first.max_von_mises_pa);
  EXPECT_EQ(again.max_von_mises_pa, first.max_von_mises_pa);
  EXPECT_EQ(again.max_von_mises_depth_m, first.max_von_mises_depth_m);
  const contact::PointHertz point_first = contact::point_contact(100, 0.01, modulus, 0.3);
  const contact::PointHertz point_other = contact::point_contact(100, 0.01, modulus, 0.1);
  const contact::PointHertz point_again = contact::point_contact(100, 0.01, modulus, 0.3);
  EXPECT_NE(point_other.max_shear_pa, point_first.max_shear_pa);
  EXPECT_EQ(point_again.max_shear_pa, point_first.max_shear_pa);
  EXPECT_EQ(point_again.max_shear_depth_m, point_first.max_shear_depth_m);
}
