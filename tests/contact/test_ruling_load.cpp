// The load one ruling carries under each load rule (contact/ruling_load.h),
// against hand computations on a ruling of length 2 along x: the centre of
// pressure of the static rule is the centre of mass's foot on it, the
// no-tension linear rule loads [0, 3c] for c < 1/3 and integrates to N, the
// dynamic rule scales the motion's normal force by F / (m g), the uniform
// rule spreads F evenly, a centre off the ruling carries nothing; and where
// a peak pressure is held near the loaded ends.
#include "contact/ruling_load.h"
#include <gtest/gtest.h>

using namespace rollcheck;

namespace
{
oracle::RollingSample ruling_along_x()
{
  oracle::RollingSample sample;
  sample.contact_start_m = {0, 0, 0};
  sample.contact_end_m = {2, 0, 0};
  sample.normal_force_n = 4.905; // half the weight of 1 kg
  sample.centre_of_pressure = 0.75;
  return sample;
}

/// integral_0^1 q(f) L df by the midpoint rule.
double total_load(const contact::RulingLoad& load, double length_m)
{
  const int n = 100000;
  double sum = 0;
  for (int k = 0; k < n; ++k)
    sum += load.line_load(length_m, (k + 0.5) / n);
  return sum * length_m / n;
}
} // namespace

TEST(RulingLoad, StaticRuleCentresOnTheCentreOfMassFootAndLoadsThreeTimesItNearAnEnd)
{
  const contact::RollingBodyMass mass{{0.5, 0.3, 0.7}, 1.0};
  const contact::RulingLoad load
      = contact::ruling_load(ruling_along_x(), contact::LoadRule::static_through_centre_of_mass, 100, mass);
  EXPECT_DOUBLE_EQ(load.normal_n, 100);
  EXPECT_DOUBLE_EQ(load.centre, 0.25);
  EXPECT_DOUBLE_EQ(load.from, 0);
  EXPECT_DOUBLE_EQ(load.to, 0.75);
  EXPECT_EQ(load.line_load(2, 0.8), 0);
  EXPECT_NEAR(total_load(load, 2), 100, 1e-6);
}

TEST(RulingLoad, DynamicRuleScalesTheMotionsForceAndTakesItsCentre)
{
  const contact::RollingBodyMass mass{{1, 0, 0}, 1.0};
  const contact::RulingLoad load = contact::ruling_load(ruling_along_x(), contact::LoadRule::dynamic, 100, mass);
  EXPECT_NEAR(load.normal_n, 50, 1e-12);
  EXPECT_DOUBLE_EQ(load.centre, 0.75);
  EXPECT_NEAR(load.from, 0.25, 1e-15);
  EXPECT_DOUBLE_EQ(load.to, 1);
  EXPECT_NEAR(total_load(load, 2), 50, 1e-6);
}

TEST(RulingLoad, UniformRuleSpreadsFEvenlyAndAnOffRulingCentreCarriesNothing)
{
  const contact::RollingBodyMass off{{3, 0, 0}, 1.0};
  const contact::RulingLoad uniform = contact::ruling_load(ruling_along_x(), contact::LoadRule::uniform, 100, off);
  for (const double f : {0.0, 0.5, 1.0})
    EXPECT_DOUBLE_EQ(uniform.line_load(2, f), 50);
  const contact::RulingLoad on_rim
      = contact::ruling_load(ruling_along_x(), contact::LoadRule::static_through_centre_of_mass, 100, off);
  EXPECT_EQ(on_rim.normal_n, 0);
  EXPECT_EQ(on_rim.line_load(2, 0.5), 0);
}

TEST(RulingLoad, TheResultantKeepsARimPointsLoadThatTheNoTensionRuleDrops)
{
  // The centre of mass's foot 1.5 ruling lengths along: the body stands on
  // the rim point, whose load the rims' study takes from the resultant.
  const contact::RollingBodyMass off{{3, 0, 0}, 1.0};
  const contact::RulingLoad resultant
      = contact::ruling_resultant(ruling_along_x(), contact::LoadRule::static_through_centre_of_mass, 100, off);
  EXPECT_DOUBLE_EQ(resultant.normal_n, 100);
  EXPECT_DOUBLE_EQ(resultant.centre, 1.5);
  const contact::RulingLoad dynamic = contact::ruling_resultant(ruling_along_x(), contact::LoadRule::dynamic, 100, off);
  EXPECT_NEAR(dynamic.normal_n, 50, 1e-12);
  EXPECT_DOUBLE_EQ(dynamic.centre, 0.75);
  const contact::RulingLoad uniform = contact::ruling_resultant(ruling_along_x(), contact::LoadRule::uniform, 100, off);
  EXPECT_TRUE(uniform.uniform);
  EXPECT_DOUBLE_EQ(uniform.centre, 0.5);
  EXPECT_EQ(contact::ruling_load(ruling_along_x(), contact::LoadRule::static_through_centre_of_mass, 100, off).normal_n,
            0);
}

TEST(RulingLoad, PeaksAreHeldTheMarginInsideTheLoadedEnds)
{
  EXPECT_DOUBLE_EQ(contact::held_fraction(0.21, 0.2, 0.6, 0.05), 0.25);
  EXPECT_DOUBLE_EQ(contact::held_fraction(0.4, 0.2, 0.6, 0.05), 0.4);
  EXPECT_DOUBLE_EQ(contact::held_fraction(0.59, 0.2, 0.6, 0.05), 0.55);
  // ... or at its middle when the loaded part is shorter than two margins.
  EXPECT_DOUBLE_EQ(contact::held_fraction(0.0, 0.0, 0.06, 0.05), 0.03);
}
