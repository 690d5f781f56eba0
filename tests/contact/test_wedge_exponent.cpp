// The free-free wedge's singular exponent (contact/wedge_exponent.h) against
// the values of fracture mechanics and Williams (1952): a crack (360 deg)
// r^-1/2; the 270 deg notch lambda = 0.5445 (the mode-I V-notch value); the
// 240 deg wedge of a 120 deg rim on the rigid plane lambda = 0.6157
// (tests/fem/test_slab_contact.cpp); no singularity at or below 180 deg; and,
// independently of the bisection, the root satisfies the equation and no
// smaller root exists (a sign scan).
#include "contact/wedge_exponent.h"
#include "core/error.h"
#include <cmath>
#include <gtest/gtest.h>
#include <numbers>

using namespace rollcheck;

namespace
{
constexpr double degree_rad = std::numbers::pi / 180;
}

TEST(WedgeExponent, KnownWedges)
{
  EXPECT_NEAR(contact::wedge_stress_exponent(360 * degree_rad), -0.5, 1e-12);
  EXPECT_NEAR(contact::wedge_stress_exponent(270 * degree_rad), 0.5445 - 1, 5e-5);
  EXPECT_NEAR(contact::wedge_stress_exponent(240 * degree_rad), 0.6157 - 1, 5e-5);
  EXPECT_NEAR(contact::edge_on_rigid_plane_exponent(120 * degree_rad), 0.6157 - 1, 5e-5);
  EXPECT_EQ(contact::wedge_stress_exponent(180 * degree_rad), 0.0);
  EXPECT_EQ(contact::edge_on_rigid_plane_exponent(90 * degree_rad), 0.0); // the cylinder's square rim
  EXPECT_EQ(contact::wedge_stress_exponent(60 * degree_rad), 0.0);
}

TEST(WedgeExponent, TheLeastRootOfWilliamsEquation)
{
  for (double w_deg = 181; w_deg <= 360; w_deg += 7)
  {
    const double w = w_deg * degree_rad;
    const double lambda = 1 + contact::wedge_stress_exponent(w);
    auto f = [w](double l) { return std::sin(l * w) + l * std::sin(w); };
    EXPECT_NEAR(f(lambda), 0.0, 1e-12) << w_deg;
    ASSERT_GT(lambda, 0.0);
    for (int k = 1; k < 1000; ++k)
      EXPECT_GT(f(lambda * k / 1000.0), 0.0) << w_deg << " deg has a smaller root near " << lambda * k / 1000.0;
  }
  // Sharper wedges are more singular.
  EXPECT_LT(contact::wedge_stress_exponent(300 * degree_rad), contact::wedge_stress_exponent(250 * degree_rad));
}

TEST(WedgeExponent, AnglesOutsideTheCircleAreRejected)
{
  EXPECT_THROW(contact::wedge_stress_exponent(0.0), InputError);
  EXPECT_THROW(contact::wedge_stress_exponent(7.0), InputError);
  EXPECT_THROW(contact::wedge_stress_exponent(std::nan("")), InputError);
}
