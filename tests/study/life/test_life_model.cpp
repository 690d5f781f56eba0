// The life model (study/life): the depth integrals of one pass against an
// independent quadrature, the cylinder's loop integral against its closed
// form (every generator carries F / L), and the Lundberg-Palmgren load-life
// exponent measured from the integral by direct quadrature over absolute
// depth against the derived (c + 1 - h) / (2 e) = 4; the rounded rim ends'
// integral on the cylinder against its closed form (two ends per ruling).
#include "contact/hertz.h"
#include "contact/subsurface_pass.h"
#include "oracle/rolling_study.h"
#include "study/life/loop_life.h"
#include "study/life/stress_volume.h"
#include <cmath>
#include <gtest/gtest.h>
#include <numbers>

using namespace rollcheck;
using namespace rollcheck::study::life;

namespace
{
const oracle::RealRolling& cylinder_run()
{
  static const oracle::RealRolling run = [] {
    geometry::BodySpec spec;
    spec.body = "cylinder";
    oracle::RollingStudyParameters p;
    p.samples_per_loop = 400;
    return oracle::real_rolling(spec, p);
  }();
  return run;
}

/// Every ruling of the loop carries F / L.
LoopLifeSettings uniform_load(double load_n)
{
  LoopLifeSettings s;
  s.load_rule = contact::LoadRule::uniform;
  s.normal_load_n = load_n;
  return s;
}
} // namespace

TEST(LifeModel, DerivedLoadLifeExponentOfLineContactIsFour)
{
  EXPECT_DOUBLE_EQ(derived_load_life_exponent(LifeConstants{}), 4.0);
  LifeConstants point_weibull;
  point_weibull.weibull_slope = 10.0 / 9;
  EXPECT_NEAR(derived_load_life_exponent(point_weibull), 4.05, 1e-12);
}

TEST(LifeModel, DepthIntegralAgreesWithSimpsonOnThePassStress)
{
  const LifeConstants k;
  const DepthIntegrals table(contact::FatigueCriterion::orthogonal_shear, k);
  EXPECT_NEAR(table.peak(), 0.25, 1e-4);
  EXPECT_NEAR(table.peak_depth(), 0.5, 5e-3);
  // Simpson on z in [0.01, 4] (1200 intervals) of (f(z) - t)_+^c z^-h, f
  // straight from the pass (no table).
  for (const double t : {0.0, 0.15, 0.22})
  {
    const int n = 1200;
    const double lo = 0.01, hi = 4, h = (hi - lo) / n;
    double sum = 0;
    for (int i = 0; i <= n; ++i)
    {
      const double z = lo + i * h;
      const double f = contact::pass_stress(contact::FatigueCriterion::orthogonal_shear, z, 0.3, 0).value_over_p0;
      const double g = f > t ? std::pow(f - t, k.stress_exponent) * std::pow(z, -k.depth_exponent) : 0;
      sum += (i == 0 || i == n ? 1 : (i % 2 ? 4 : 2)) * g;
    }
    EXPECT_NEAR(table.integral(t, k.stress_exponent) / (sum * h / 3), 1, 2e-3) << "t = " << t;
  }
  EXPECT_EQ(table.integral(0.2501, k.stress_exponent), 0.0);
}

TEST(LifeModel, CylinderLoopIntegralMatchesItsClosedForm)
{
  const LifeConstants k;
  const DepthIntegrals orthogonal(contact::FatigueCriterion::orthogonal_shear, k);
  const DepthIntegrals largest(contact::FatigueCriterion::largest_shear, k);
  LoopLifeSettings s;
  s.normal_load_n = 5000;
  s.load_rule = contact::LoadRule::uniform;
  const LoopIntegrals li = loop_integrals(cylinder_run(), s, k, {&orthogonal, &largest}, {1.0, 1.0}, largest);
  // Radius 1 m, length 2 m: one loop sweeps the side 2 pi r L once at q = F / L.
  const contact::LineHertz h = contact::line_contact(s.normal_load_n / 2, 1, s.effective_modulus_pa, 0.3);
  const double expected = 2 * std::numbers::pi * 2 * std::pow(h.peak_pressure_pa, k.stress_exponent)
                          * std::pow(h.half_width_m, 1 - k.depth_exponent) * orthogonal.integral(0, k.stress_exponent);
  EXPECT_NEAR(li.lundberg_palmgren[0] / expected, 1, 1e-3);
  EXPECT_NEAR(li.max_peak_pressure_pa / h.peak_pressure_pa, 1, 1e-9);
  // Below the fatigue limit (p0 of 9 MPa against 1.5 GPa): Ioannides-Harris's life is infinite.
  EXPECT_EQ(li.ioannides_harris[0], 0.0);
}

TEST(LifeModel, LoadLifeExponentMeasuredFromTheIntegral)
{
  const LifeConstants k;
  const DepthIntegrals orthogonal(contact::FatigueCriterion::orthogonal_shear, k);
  LoopLifeSettings s = uniform_load(100);
  s.pieces = 2;
  // One depth grid for both loads, from 1e-3 of the smaller b to 10 times the larger.
  const double z_lo = 1e-3 * contact::line_contact(50, 1, s.effective_modulus_pa, 0.3).half_width_m;
  const double z_hi = 10 * contact::line_contact(5000, 1, s.effective_modulus_pa, 0.3).half_width_m;
  s.normal_load_n = 100;
  const double low = lundberg_palmgren_by_depth(cylinder_run(), s, k, orthogonal, z_lo, z_hi, 2500);
  s.normal_load_n = 10000;
  const double high = lundberg_palmgren_by_depth(cylinder_run(), s, k, orthogonal, z_lo, z_hi, 2500);
  const double exponent = std::log(high / low) / std::log(100.0) / k.weibull_slope;
  EXPECT_NEAR(exponent / derived_load_life_exponent(k), 1, 0.005);
}

TEST(LifeModel, CylinderRimEndIntegralMatchesItsClosedForm)
{
  const LifeConstants k;
  const DepthIntegrals orthogonal(contact::FatigueCriterion::orthogonal_shear, k);
  const LoopLifeSettings s = uniform_load(5000);
  const RoundedEndRatios t{{1, 4, 16}, {1.5, 2, 3}, 87.5, "hand-made"};
  for (const double re : {0.05, 0.5, 2.0}) // R / r_e = 20 (held), 2, and r_e above R
  {
    const RoundedEnds ends{re, &t, 1.5};
    const LoopIntegrals li
        = loop_integrals(cylinder_run(), s, k, {&orthogonal, &orthogonal}, {1.0, 1.0}, orthogonal, &ends);
    // Each of the loop's rulings has two loaded ends at q = F / L on R = max(1 m, r_e): over one loop (2 pi
    // of sigma) each sweeps 2 pi R, on a patch 1.5 b long.
    const double r = std::max(1.0, re);
    const contact::LineHertz h = contact::line_contact(s.normal_load_n / 2, r, s.effective_modulus_pa, 0.3);
    const double expected = 2 * 2 * std::numbers::pi * r * 1.5 * h.half_width_m
                            * std::pow(t(1 / re) * h.peak_pressure_pa, k.stress_exponent)
                            * std::pow(h.half_width_m, 1 - k.depth_exponent) * orthogonal.integral(0, k.stress_exponent);
    EXPECT_NEAR(li.end_lundberg_palmgren[0] / expected, 1, 1e-3) << "r_e = " << re;
    EXPECT_EQ(li.ends_outside_table > 0, re == 0.05);
  }
}
