// The singular exponent of an edge on an elastic block
// (contact/edge_on_elastic_block_exponent.h) against results it does not
// compute itself: its limits, Williams' free-free wedge
// (contact/wedge_exponent.h) for a rigid block and the flat punch's r^-1/2 for
// a rigid body; and, for finite moduli, the full 8 x 8 eigenproblem set up
// here independently, with Kolosov-Muskhelishvili complex potentials instead
// of Williams' Airy function, with the two bodies' kappa and mu separately
// (not only the E* the header's reduced equation keeps) and its determinant's
// roots found by a different scan and regula falsi. No published number for
// like materials was found to compare with; the steel-on-steel values below
// (90 deg: lambda = 0.774013) come from that independent determinant.
#include "contact/edge_on_elastic_block_exponent.h"
#include "contact/wedge_exponent.h"
#include "core/error.h"
#include <Eigen/Dense>
#include <cmath>
#include <complex>
#include <gtest/gtest.h>
#include <limits>
#include <numbers>
#include <optional>
#include <string>
#include <utility>

using namespace rollcheck;

namespace
{
constexpr double pi = std::numbers::pi;
constexpr double deg = pi / 180;
using cplx = std::complex<double>;

struct Material
{
  double youngs_modulus_pa;
  double poisson_ratio;
};
constexpr Material steel{200e9, 0.3};
constexpr Material aluminium{70e9, 0.33};
constexpr Material polymer{3e9, 0.4};

double exponent(double theta, Material body, Material block)
{
  return contact::edge_on_elastic_block_exponent(theta, body.youngs_modulus_pa, body.poisson_ratio,
                                                 block.youngs_modulus_pa, block.poisson_ratio);
}

// phi(z) = a z^l, psi(z) = b z^l (a, b complex: 4 real unknowns a body). On
// the ray arg z = t at r = 1, with Phi = phi', Psi = psi':
//   sigma_tt + i sigma_rt = Phi + conj Phi + e^(2 i t) (conj(z) Phi' + Psi),
//   2 mu (u_x + i u_y) = kappa phi - z conj(Phi) - conj(psi).
struct OnRay
{
  cplx traction;     ///< sigma_tt + i sigma_rt
  cplx displacement; ///< 2 mu (u_x + i u_y)
};

OnRay on_ray(double l, double kappa, cplx a, cplx b, double t)
{
  auto z_to = [t](double m) { return std::polar(1.0, m * t); }; // z^m on the ray, the branch of arg in [-pi, pi]
  const cplx z = z_to(1);
  const cplx Phi = l * a * z_to(l - 1), dPhi = l * (l - 1) * a * z_to(l - 2), Psi = l * b * z_to(l - 1);
  return {Phi + std::conj(Phi) + z_to(2) * (std::conj(z) * dPhi + Psi),
          kappa * a * z_to(l) - z * std::conj(Phi) - std::conj(b * z_to(l))};
}

// The wedge on 0 <= t <= theta, the block on -pi <= t <= 0, in contact along
// t = 0; unknowns (Re a, Im a, Re b, Im b) of the wedge, then of the block.
double determinant(double l, double theta, Material body, Material block)
{
  const double kappa1 = 3 - 4 * body.poisson_ratio, kappa2 = 3 - 4 * block.poisson_ratio;
  const double mu1 = body.youngs_modulus_pa / (2 * (1 + body.poisson_ratio));
  const double mu2 = block.youngs_modulus_pa / (2 * (1 + block.poisson_ratio));
  const cplx unit[4][2] = {{1.0, 0.0}, {cplx(0, 1), 0.0}, {0.0, 1.0}, {0.0, cplx(0, 1)}};
  Eigen::Matrix<double, 8, 8> m = Eigen::Matrix<double, 8, 8>::Zero();
  for (int j = 0; j < 4; ++j)
  {
    const cplx a = unit[j][0], b = unit[j][1];
    const OnRay wedge_free = on_ray(l, kappa1, a, b, theta), block_free = on_ray(l, kappa2, a, b, -pi);
    const OnRay wedge_face = on_ray(l, kappa1, a, b, 0), block_face = on_ray(l, kappa2, a, b, 0);
    m(0, j) = wedge_free.traction.real(); // free faces: no normal, no shear traction
    m(1, j) = wedge_free.traction.imag();
    m(2, 4 + j) = block_free.traction.real();
    m(3, 4 + j) = block_free.traction.imag();
    m(4, j) = wedge_face.traction.imag(); // frictionless: no shear on either side
    m(5, 4 + j) = block_face.traction.imag();
    m(6, j) = wedge_face.traction.real(); // equal normal tractions
    m(6, 4 + j) = -block_face.traction.real();
    m(7, j) = wedge_face.displacement.imag() / (mu1 / mu2); // equal normal displacements u_y
    m(7, 4 + j) = -block_face.displacement.imag();
  }
  return m.determinant();
}

// The least root of the determinant in [0.01, 0.999] (it vanishes trivially
// at lambda = 1: a rigid rotation and the block's uniform stress along its
// surface), by a scan and the Illinois variant of regula falsi.
std::optional<double> least_determinant_root(double theta, Material body, Material block)
{
  auto f = [&](double l) { return determinant(l, theta, body, block); };
  double a = 0.01, fa = f(a);
  for (double b = a + 7e-4; b <= 0.999; b += 7e-4)
  {
    double fb = f(b);
    if ((fa < 0) == (fb < 0))
    {
      a = b, fa = fb;
      continue;
    }
    int side = 0;
    for (int i = 0; i < 200 && b - a > 1e-14; ++i)
    {
      const double c = (a * fb - b * fa) / (fb - fa), fc = f(c);
      if ((fc < 0) == (fa < 0))
      {
        a = c, fa = fc;
        if (side == -1)
          fb /= 2;
        side = -1;
      }
      else
      {
        b = c, fb = fc;
        if (side == 1)
          fa /= 2;
        side = 1;
      }
      if (fc == 0)
        return c;
    }
    return 0.5 * (a + b);
  }
  return std::nullopt;
}
} // namespace

TEST(EdgeOnElasticBlockExponent, RigidBlockIsWilliamsFreeFreeWedgeOfTwiceTheAngle)
{
  constexpr Material body{1e9, 0.3}, rigid_block{1e15, 0.3};
  for (double theta_deg : {95.0, 100.0, 110.0, 120.0, 135.0, 150.0, 170.0, 180.0})
  {
    const double williams = contact::edge_on_rigid_plane_exponent(theta_deg * deg);
    EXPECT_NEAR(exponent(theta_deg * deg, body, rigid_block), williams, 1e-3 * std::abs(williams)) << theta_deg;
    EXPECT_NEAR(contact::edge_on_elastic_block_exponent_for_alpha(theta_deg * deg, -1), williams, 1e-12) << theta_deg;
  }
  // Not singular on a rigid plane at or below 90 deg; a block 1e6 times stiffer
  // leaves at 90 deg a root 4 E1* / (pi^2 E2*) below 1.
  for (double theta_deg : {10.0, 30.0, 60.0, 85.0, 89.0, 90.0})
  {
    const double x = exponent(theta_deg * deg, body, rigid_block);
    EXPECT_LE(x, 0.0) << theta_deg;
    EXPECT_GT(x, -1e-5) << theta_deg;
    EXPECT_EQ(contact::edge_on_elastic_block_exponent_for_alpha(theta_deg * deg, -1), 0.0) << theta_deg;
  }
  EXPECT_NEAR(exponent(90 * deg, body, rigid_block), -4e-6 / (pi * pi), 1e-8);
}

TEST(EdgeOnElasticBlockExponent, RigidBodyIsTheFlatPunchEdge)
{
  // A rigid body's face moves as a whole, so the block alone decides: the edge
  // of a rigid flat punch on an elastic half-plane, p ~ r^-1/2, for any angle.
  constexpr Material rigid_body{1e15, 0.3}, block{1e9, 0.3};
  for (double theta_deg : {30.0, 60.0, 90.0, 120.0, 150.0, 180.0})
  {
    EXPECT_NEAR(exponent(theta_deg * deg, rigid_body, block), -0.5, 1e-4) << theta_deg;
    EXPECT_NEAR(contact::edge_on_elastic_block_exponent_for_alpha(theta_deg * deg, 1), -0.5, 1e-14) << theta_deg;
  }
  // A needle-sharp rigid wedge too (the equation's Q vanishes as theta^4 there).
  EXPECT_NEAR(contact::edge_on_elastic_block_exponent_for_alpha(1e-6, 1), -0.5, 1e-14);
}

TEST(EdgeOnElasticBlockExponent, SquareSteelEdgeOnSteelIsSingular)
{
  // The square end of a steel roller on a steel block: singular, although the
  // same edge on a rigid plane is not.
  const double x = exponent(90 * deg, steel, steel);
  EXPECT_LT(x, -0.2);
  EXPECT_EQ(contact::edge_on_rigid_plane_exponent(90 * deg), 0.0);
  const auto root = least_determinant_root(90 * deg, steel, steel);
  ASSERT_TRUE(root.has_value());
  EXPECT_NEAR(x, *root - 1, 1e-9);
  EXPECT_NEAR(x, 0.774013 - 1, 1e-6);
}

TEST(EdgeOnElasticBlockExponent, AgreesWithTheEightByEightDeterminant)
{
  const Material pairs[][2] = {{steel, steel}, {steel, aluminium}, {aluminium, steel}, {steel, polymer},
                               {polymer, steel}, {aluminium, aluminium}};
  for (const auto& pair : pairs)
    for (double theta_deg : {45.0, 70.0, 80.0, 90.0, 100.0, 110.0, 120.0, 135.0, 150.0, 165.0, 180.0})
    {
      const double theta = theta_deg * deg;
      const double x = exponent(theta, pair[0], pair[1]);
      const auto root = least_determinant_root(theta, pair[0], pair[1]);
      const std::string where = std::to_string(theta_deg) + " deg, E " + std::to_string(pair[0].youngs_modulus_pa)
                                + " on " + std::to_string(pair[1].youngs_modulus_pa);
      if (x > -1e-3) // no root, or one within 0.001 of 1, beyond the scan
        EXPECT_FALSE(root.has_value()) << where << ": the determinant vanishes at " << *root;
      else
      {
        ASSERT_TRUE(root.has_value()) << where;
        EXPECT_NEAR(x, *root - 1, 1e-9) << where;
      }
    }
}

TEST(EdgeOnElasticBlockExponent, TwoHalfPlanesGiveTheCrackTip)
{
  // theta = pi: two half-planes touching along x > 0, free along x < 0. The
  // mode-I crack-tip field of a whole plane cut along x < 0 has no shear on
  // y = 0 ahead of the tip and equal u_y on both sides there, so it meets every
  // condition: lambda = 1/2 for any pair of materials, the value of
  // edge_on_rigid_plane_exponent(pi) (the crack is that problem's mirror image).
  for (const auto& [body, block] : {std::pair{steel, steel}, std::pair{steel, polymer}, std::pair{polymer, aluminium}})
  {
    EXPECT_NEAR(exponent(pi, body, block), -0.5, 1e-14);
    const auto root = least_determinant_root(pi, body, block);
    ASSERT_TRUE(root.has_value());
    EXPECT_NEAR(*root, 0.5, 1e-10);
  }
  EXPECT_NEAR(contact::edge_on_rigid_plane_exponent(pi), -0.5, 1e-12);
}

TEST(EdgeOnElasticBlockExponent, DependsOnlyOnDundursAlpha)
{
  // Pairs of materials with the same E* = E / (1 - nu^2), and so the same
  // alpha, but other Poisson ratios (other beta): the same exponent, by the
  // reduced equation and by the determinant, which sees kappa and mu apart.
  const double body_star = steel.youngs_modulus_pa / (1 - 0.09), block_star = aluminium.youngs_modulus_pa / (1 - 0.33 * 0.33);
  const Material body_nu0{body_star, 0.0}, block_nu049{block_star * (1 - 0.49 * 0.49), 0.49};
  const double alpha = (body_star - block_star) / (body_star + block_star);
  EXPECT_NEAR(contact::dundurs_alpha_plane_strain(200e9, 0.3, 70e9, 0.33), alpha, 1e-15);
  for (double theta_deg : {80.0, 90.0, 120.0, 150.0})
  {
    const double theta = theta_deg * deg;
    const double x = exponent(theta, steel, aluminium);
    EXPECT_NEAR(exponent(theta, body_nu0, block_nu049), x, 1e-13) << theta_deg;
    EXPECT_NEAR(contact::edge_on_elastic_block_exponent_for_alpha(theta, alpha), x, 1e-13) << theta_deg;
    const auto root = least_determinant_root(theta, body_nu0, block_nu049);
    ASSERT_TRUE(root.has_value()) << theta_deg;
    EXPECT_NEAR(*root - 1, x, 1e-9) << theta_deg;
  }
}

TEST(EdgeOnElasticBlockExponent, LikeMaterialsTurnSingularAt77Degrees)
{
  // The root leaves lambda = 1 where tan theta = theta + pi (alpha = 0).
  double lo = 60 * deg, hi = 89 * deg;
  for (int i = 0; i < 100; ++i)
  {
    const double mid = 0.5 * (lo + hi);
    (std::tan(mid) < mid + pi ? lo : hi) = mid;
  }
  EXPECT_NEAR(lo / deg, 77.45, 0.01);
  EXPECT_EQ(exponent(lo - 0.2 * deg, steel, steel), 0.0);
  EXPECT_LT(exponent(lo + 0.2 * deg, steel, steel), 0.0);
  EXPECT_EQ(exponent(60 * deg, steel, steel), 0.0);
}

TEST(EdgeOnElasticBlockExponent, LiesBetweenThePunchAndTheRigidPlane)
{
  // A stiffer body (or a softer block) is more singular, from Williams'
  // value on a rigid block to the punch's -1/2.
  for (double theta_deg : {95.0, 110.0, 135.0, 160.0})
  {
    const double theta = theta_deg * deg;
    double previous = contact::edge_on_rigid_plane_exponent(theta);
    for (double ratio : {1e-3, 0.1, 0.5, 1.0, 2.0, 10.0, 1e3})
    {
      const double x = exponent(theta, Material{ratio * 1e9, 0.3}, Material{1e9, 0.3});
      EXPECT_LT(x, previous) << theta_deg << " deg, body " << ratio << " x the block";
      EXPECT_GT(x, -0.5) << theta_deg;
      previous = x;
    }
  }
}

TEST(EdgeOnElasticBlockExponent, BadInputIsRejected)
{
  const double nan = std::nan("");
  EXPECT_THROW(exponent(0.0, steel, steel), InputError);
  EXPECT_THROW(exponent(-1.0, steel, steel), InputError);
  EXPECT_THROW(exponent(pi + 1e-9, steel, steel), InputError);
  EXPECT_THROW(exponent(nan, steel, steel), InputError);
  EXPECT_THROW(exponent(pi / 2, Material{0.0, 0.3}, steel), InputError);
  EXPECT_THROW(exponent(pi / 2, steel, Material{-1e9, 0.3}), InputError);
  EXPECT_THROW(exponent(pi / 2, Material{nan, 0.3}, steel), InputError);
  EXPECT_THROW(exponent(pi / 2, steel, Material{std::numeric_limits<double>::infinity(), 0.3}), InputError);
  EXPECT_THROW(exponent(pi / 2, Material{200e9, 0.5}, steel), InputError);
  EXPECT_THROW(exponent(pi / 2, steel, Material{200e9, -0.1}), InputError);
  EXPECT_THROW(exponent(pi / 2, steel, Material{200e9, nan}), InputError);
  EXPECT_THROW(contact::edge_on_elastic_block_exponent_for_alpha(pi / 2, 1.5), InputError);
  EXPECT_THROW(contact::edge_on_elastic_block_exponent_for_alpha(pi / 2, nan), InputError);
  EXPECT_THROW(contact::edge_on_elastic_block_exponent_for_alpha(4.0, 0.0), InputError);
  EXPECT_THROW(contact::dundurs_alpha_plane_strain(200e9, 0.3, 0.0, 0.3), InputError);
}
