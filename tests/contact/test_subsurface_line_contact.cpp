// The closed-form subsurface field of line contact (McEwen) against Johnson's
// landmarks and against an independent integration of the Boussinesq-Flamant
// kernel over the Hertz pressure; the criteria of one rolling pass.
#include "contact/subsurface_line_contact.h"
#include "contact/subsurface_pass.h"
#include "core/error.h"
#include <cmath>
#include <gtest/gtest.h>
#include <numbers>

using namespace rollcheck::contact;

namespace
{
/// Stress over p0 at (x, z) (over b) of the Hertz pressure sqrt(1 - s^2) on
/// |s| < 1 by the Flamant kernel (Johnson eq. 2.23), with s = sin(t) and
/// composite Gauss-Legendre (5 points) on 4000 pieces of t in [-pi/2, pi/2].
LineContactStress flamant(double x, double z)
{
  const double g[5] = {-0.9061798459386640, -0.5384693101056831, 0, 0.5384693101056831, 0.9061798459386640};
  const double w[5] = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889, 0.4786286704993665,
                       0.2369268850561891};
  const int pieces = 4000;
  const double h = std::numbers::pi / pieces;
  LineContactStress s;
  for (int k = 0; k < pieces; ++k)
    for (int j = 0; j < 5; ++j)
    {
      const double t = -std::numbers::pi / 2 + (k + 0.5) * h + g[j] * h / 2;
      const double p = std::cos(t), ds = std::cos(t) * w[j] * h / 2, d = x - std::sin(t);
      const double r2 = d * d + z * z, r4 = r2 * r2;
      s.xx += -2 * z / std::numbers::pi * p * d * d / r4 * ds;
      s.zz += -2 * z * z * z / std::numbers::pi * p / r4 * ds;
      s.xz += -2 * z * z / std::numbers::pi * p * d / r4 * ds;
    }
  return s;
}
} // namespace

TEST(SubsurfaceLineContact, AxisAgreesWithJohnsonsClosedForm)
{
  for (double z : {0.1, 0.5, 0.786, 2.0})
  {
    const LineContactStress s = line_contact_subsurface_stress(0, z, 0.3);
    EXPECT_NEAR(s.zz, -1 / std::sqrt(1 + z * z), 1e-14);
    EXPECT_NEAR(s.xx, -((1 + 2 * z * z) / std::sqrt(1 + z * z) - 2 * z), 1e-14);
    EXPECT_NEAR(s.xz, 0, 1e-14);
    EXPECT_NEAR(s.yy, 0.3 * (s.xx + s.zz), 1e-14);
  }
  // On the surface: sigma_x = sigma_z = -p(x) inside, 0 outside.
  const LineContactStress inside = line_contact_subsurface_stress(0.6, 0, 0.3);
  EXPECT_NEAR(inside.zz, -0.8, 1e-12);
  EXPECT_NEAR(inside.xx, -0.8, 1e-12);
  const LineContactStress outside = line_contact_subsurface_stress(1.5, 0, 0.3);
  EXPECT_NEAR(outside.zz, 0, 1e-12);
  EXPECT_NEAR(outside.xz, 0, 1e-12);
  EXPECT_THROW(line_contact_subsurface_stress(0, -0.1, 0.3), rollcheck::InputError);
}

TEST(SubsurfaceLineContact, AgreesWithTheFlamantIntegralOfTheHertzPressure)
{
  for (double x : {-2.0, -0.87, -0.3, 0.0, 0.5, 0.87, 1.2, 3.0})
    for (double z : {0.25, 0.5, 0.786, 1.5})
    {
      const LineContactStress closed = line_contact_subsurface_stress(x, z, 0.3), integral = flamant(x, z);
      EXPECT_NEAR(closed.xx, integral.xx, 2e-8) << "x " << x << " z " << z;
      EXPECT_NEAR(closed.zz, integral.zz, 2e-8) << "x " << x << " z " << z;
      EXPECT_NEAR(closed.xz, integral.xz, 2e-8) << "x " << x << " z " << z;
    }
}

TEST(SubsurfaceLineContact, LandmarksOfJohnsonSection43)
{
  const DepthExtremum shear = largest_over_depth(FatigueCriterion::largest_shear, 0.3, 0.3);
  EXPECT_NEAR(shear.value_over_p0, 0.3004, 5e-4);
  EXPECT_NEAR(shear.z_over_b, 0.7861, 5e-4);
  EXPECT_NEAR(shear.x_over_b, 0, 1e-6);
  const DepthExtremum orthogonal = largest_over_depth(FatigueCriterion::orthogonal_shear, 0.3, 0.3);
  EXPECT_NEAR(orthogonal.value_over_p0, 0.250, 5e-4);
  EXPECT_NEAR(orthogonal.z_over_b, 0.5, 2e-3);
  EXPECT_NEAR(orthogonal.x_over_b, std::sqrt(3.0) / 2, 2e-3);
  // Dang Van: finite, below the surface, larger than the shear's amplitude
  // alone where the pass is compressive (alpha p_h < 0 lowers it).
  const DepthExtremum dang_van = largest_over_depth(FatigueCriterion::dang_van, 0.3, 0.3);
  EXPECT_GT(dang_van.z_over_b, 0.1);
  EXPECT_LT(dang_van.value_over_p0, 0.3);
  EXPECT_GT(dang_van.value_over_p0, 0.1);
}
