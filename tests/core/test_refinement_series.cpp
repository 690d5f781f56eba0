// The shared refinement bookkeeping against series with known answers.
#include "core/refinement_series.h"
#include <cmath>
#include <gtest/gtest.h>

using namespace rollcheck;

TEST(RefinementSeries, FittedExponentRecoversAPowerLaw)
{
  // v = 3 h^-0.433 (a wedge's singular pressure) over four halvings, with a
  // 1 % alternating scatter that two levels alone would carry into the slope.
  RefinementSeries s;
  for (int k = 0; k < 4; ++k)
  {
    const double h = 1e-3 / std::pow(2.0, k);
    s.add(h, 3 * std::pow(h, -0.433) * (k % 2 ? 1.01 : 0.99));
  }
  EXPECT_NEAR(fitted_exponent(s), -0.433, 0.01);
  RefinementSeries exact;
  for (int k = 0; k < 3; ++k)
    exact.add(std::pow(2.0, -k), std::pow(2.0, -k * 1.5));
  EXPECT_NEAR(fitted_exponent(exact), 1.5, 1e-12);
}

TEST(RefinementSeries, ChangeAndConvergenceUseTheSolversCriterion)
{
  RefinementSeries s;
  s.add(1.0, 2.0);
  EXPECT_TRUE(std::isnan(last_change(s)));
  EXPECT_FALSE(converged(s, 1.0)); // one level says nothing
  s.add(0.5, 2.05);
  EXPECT_NEAR(last_change(s), 0.025, 1e-15);
  EXPECT_TRUE(converged(s, 0.03));
  EXPECT_FALSE(converged(s, 0.02));
  // A solver's own change: against the larger of the value and 1.
  const LevelChange against_one = [](double before, double last) { return (last - before) / std::max(last, 1.0); };
  RefinementSeries small;
  small.add(1.0, 0.10);
  small.add(0.5, 0.12);
  EXPECT_NEAR(last_change(small, against_one), 0.02, 1e-15);
  EXPECT_NEAR(last_change(small), 0.2, 1e-12);
  EXPECT_TRUE(converged(small, 0.03, against_one));
  EXPECT_TRUE(std::isnan(fitted_exponent(RefinementSeries{{1.0, 0.5}, {0.0, 1.0}})));
}
