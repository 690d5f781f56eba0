// The family search (study/optimize/optimize.h) against functions whose minimum,
// derivatives and noise are known in closed form, and against a body family
// whose optimum geometry alone decides.
#include "study/optimize/optimize.h"
#include "core/error.h"
#include "geometry/body.h"
#include "geometry/mass_properties.h"
#include <bit>
#include <cmath>
#include <cstdint>
#include <gtest/gtest.h>
#include <numbers>

using namespace rollcheck;
using namespace rollcheck::study::optimize;

namespace
{
/// 0.5 sum w_i (x_i - c_i)^2: minimum 0 at c, gradient w (x - c), Hessian diag(w).
const std::vector<double> centre{0.3, -0.2, 0.7};
const std::vector<double> weights{1.0, 4.0, 0.5};

double quadratic(std::span<const double> x)
{
  double f = 0;
  for (std::size_t i = 0; i < x.size(); ++i)
    f += 0.5 * weights[i] * (x[i] - centre[i]) * (x[i] - centre[i]);
  return f;
}

double rosenbrock(std::span<const double> x)
{
  return 100 * (x[1] - x[0] * x[0]) * (x[1] - x[0] * x[0]) + (1 - x[0]) * (1 - x[0]);
}

std::uint64_t splitmix(std::uint64_t z)
{
  z += 0x9e3779b97f4a7c15ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

/// A standard normal draw that is a deterministic, discontinuous function of
/// the point, like the chaotic oracle's: a hash of x's bits, then Box-Muller.
double pseudo_normal(std::span<const double> x)
{
  std::uint64_t h = 0x243f6a8885a308d3ULL;
  for (const double v : x)
    h = splitmix(h ^ std::bit_cast<std::uint64_t>(v));
  const double u1 = (static_cast<double>(h >> 11) + 0.5) / 9007199254740992.0;
  const double u2 = static_cast<double>(splitmix(h) >> 11) / 9007199254740992.0;
  return std::sqrt(-2 * std::log(u1)) * std::cos(2 * std::numbers::pi * u2);
}

Score with_noise(Score f, double sigma)
{
  return [f, sigma](std::span<const double> x) { return f(x) + sigma * pseudo_normal(x); };
}

OptimizeSettings quadratic_search(Method method)
{
  OptimizeSettings s;
  s.method = method;
  s.start = {-0.5, 0.5, 0.0};
  s.box = {{-1, -1, -1}, {1, 1, 1}};
  s.max_evaluations = 2000;
  s.xtol = 1e-7;
  return s;
}

double distance(std::span<const double> a, std::span<const double> b)
{
  double d2 = 0;
  for (std::size_t i = 0; i < a.size(); ++i)
    d2 += (a[i] - b[i]) * (a[i] - b[i]);
  return std::sqrt(d2);
}
} // namespace

TEST(Minimize, LocalMethodsFindAShiftedQuadratic)
{
  for (const Method method : {Method::bobyqa, Method::nelder_mead, Method::sbplx})
  {
    const OptimizeResult r = minimize(quadratic, quadratic_search(method));
    EXPECT_LT(distance(r.best_x, centre), 1e-5) << method_name(method);
    EXPECT_LT(r.best_value, 1e-10) << method_name(method);
    EXPECT_EQ(r.start_value, quadratic(std::vector<double>{-0.5, 0.5, 0.0}));
    EXPECT_EQ(r.history.front().x, r.start) << "the start is the first evaluation";
    EXPECT_EQ(r.evaluations, static_cast<int>(r.history.size()));
    EXPECT_LE(r.evaluations, 2000);
    EXPECT_TRUE(r.beats_start);
  }
}

TEST(Minimize, GlobalMethodsFindRosenbrocksMinimumInABox)
{
  // Minimum 0 at (1, 1), at the end of a curved valley.
  for (const Method method : {Method::direct_l, Method::crs2_lm, Method::multistart})
  {
    OptimizeSettings s;
    s.method = method;
    s.start = {-1.5, 2.5};
    s.box = {{-2, -1}, {2, 3}};
    s.max_evaluations = 3000;
    s.xtol = 1e-8;
    const OptimizeResult r = minimize(rosenbrock, s);
    EXPECT_LT(distance(r.best_x, std::vector<double>{1, 1}), 1e-2) << method_name(method) << ": " << r.stop_reason;
    EXPECT_LT(r.best_value, 1e-4) << method_name(method);
    EXPECT_LE(r.evaluations, 3000);
  }
}

TEST(Minimize, NoisyScoreStaysWithinTheNoiseBand)
{
  const double sigma = 1e-3;
  const Score noisy = with_noise(quadratic, sigma);

  // From the optimum itself: no point can beat it beyond the noise, however
  // many evaluations were drawn.
  OptimizeSettings s = quadratic_search(Method::bobyqa);
  s.start = centre;
  s.noise = sigma;
  s.max_evaluations = 300;
  s.xtol = 1e-4;
  OptimizeResult r = minimize(noisy, s);
  EXPECT_FALSE(r.beats_start) << "improvement " << r.start_value - r.best_value << " threshold "
                              << r.significance_threshold;
  EXPECT_LT(quadratic(r.best_x), r.significance_threshold);

  // From far away: a real improvement, ending where the true score is within
  // the noise band of the minimum.
  for (const Method method : {Method::bobyqa, Method::multistart})
  {
    s = quadratic_search(method);
    s.noise = sigma;
    s.max_evaluations = 300;
    s.xtol = 1e-4;
    r = minimize(noisy, s);
    EXPECT_TRUE(r.beats_start) << method_name(method);
    EXPECT_LT(quadratic(r.best_x), r.significance_threshold) << method_name(method);
  }
}

TEST(Minimize, TheBestOfManyNoisyDrawsDoesNotBeatTheStart)
{
  // A flat score plus noise: the best of 500 draws lies about 3 sigma below
  // the start, an "improvement" that is only selection. The threshold's
  // sqrt(2 ln n) sigma accounts for it; a bare 2 sigma would not.
  const double sigma = 0.01;
  OptimizeSettings s;
  s.method = Method::crs2_lm;
  s.start = {0, 0};
  s.box = {{-1, -1}, {1, 1}};
  s.noise = sigma;
  s.max_evaluations = 500;
  const OptimizeResult r = minimize(with_noise([](std::span<const double>) { return 1.0; }, sigma), s);
  ASSERT_GT(r.start_value - r.best_value, 2 * sigma) << "premise: selection alone beats 2 sigma";
  EXPECT_FALSE(r.beats_start) << "improvement " << r.start_value - r.best_value << " threshold "
                              << r.significance_threshold;
}

TEST(Minimize, FixedParametersStayAtTheStart)
{
  OptimizeSettings s = quadratic_search(Method::bobyqa);
  s.box.lower[1] = s.box.upper[1] = s.start[1] = 0.25;
  const OptimizeResult r = minimize(quadratic, s);
  for (const Evaluation& e : r.history)
    ASSERT_EQ(e.x[1], 0.25);
  EXPECT_NEAR(r.best_x[0], centre[0], 1e-5);
  EXPECT_NEAR(r.best_x[2], centre[2], 1e-5);
}

TEST(Minimize, FailuresNameThePointAndTheInput)
{
  const Score fails_right = [](std::span<const double> x) {
    if (x[0] > 0.1)
      throw std::runtime_error("mesh not convex");
    return quadratic(x);
  };
  try
  {
    minimize(fails_right, quadratic_search(Method::bobyqa));
    FAIL() << "no ComputationError";
  }
  catch (const ComputationError& e)
  {
    const std::string message = e.what();
    EXPECT_NE(message.find("the score failed at x = ("), std::string::npos) << message;
    EXPECT_NE(message.find("mesh not convex"), std::string::npos) << message;
  }
  OptimizeSettings outside = quadratic_search(Method::bobyqa);
  outside.start[2] = 1.5;
  EXPECT_THROW(minimize(quadratic, outside), InputError);
  OptimizeSettings global_local = quadratic_search(Method::multistart);
  global_local.local_method = Method::direct_l;
  EXPECT_THROW(minimize(quadratic, global_local), InputError);
}

TEST(EstimateNoise, MeanSpreadAndStandardError)
{
  // Replicates 0..3 give 1, 2, 3, 4 above the point's sum: mean 2.5 + 0.5,
  // sample variance 5/3, standard error sqrt(5/3) / 2.
  const ReplicateScore score = [](std::span<const double> x, int replicate) { return x[0] + x[1] + replicate + 1; };
  const NoiseEstimate e = estimate_noise(score, std::vector<double>{0.25, 0.25}, 4);
  EXPECT_DOUBLE_EQ(e.mean, 3.0);
  EXPECT_DOUBLE_EQ(e.standard_deviation, std::sqrt(5.0 / 3.0));
  EXPECT_DOUBLE_EQ(e.standard_error, std::sqrt(5.0 / 3.0) / 2);
  EXPECT_THROW(estimate_noise(score, std::vector<double>{0, 0}, 1), InputError);
}

TEST(FiniteDifferences, RecoverAQuadraticsGradientAndHessianWithinTheirUncertainty)
{
  const double sigma = 1e-4;
  const std::vector<double> x{0.1, 0.2, 0.3}, steps{0.05, 0.04, 0.1};
  // An off-diagonal term, so every Hessian entry is tested: f = quadratic + 1.5 x0 x2.
  const Score exact = [](std::span<const double> p) { return quadratic(p) + 1.5 * p[0] * p[2]; };
  const Eigen::Vector3d gradient{weights[0] * (x[0] - centre[0]) + 1.5 * x[2],
                                 weights[1] * (x[1] - centre[1]),
                                 weights[2] * (x[2] - centre[2]) + 1.5 * x[0]};
  Eigen::Matrix3d hessian = Eigen::Vector3d(weights[0], weights[1], weights[2]).asDiagonal();
  hessian(0, 2) = hessian(2, 0) = 1.5;

  const Derivatives d = finite_differences(with_noise(exact, sigma), x, steps, sigma);
  EXPECT_EQ(d.evaluations, 2 * 3 * 3 + 1);
  for (int i = 0; i < 3; ++i)
  {
    EXPECT_NEAR(d.gradient[i], gradient[i], 3 * d.gradient_sigma[i]) << i;
    EXPECT_DOUBLE_EQ(d.gradient_sigma[i], sigma * std::sqrt(2.0) / (2 * steps[i]));
    for (int j = 0; j < 3; ++j)
      EXPECT_NEAR(d.hessian(i, j), hessian(i, j), 3 * d.hessian_sigma(i, j)) << i << ", " << j;
  }
  EXPECT_DOUBLE_EQ(d.hessian_sigma(1, 1), sigma * std::sqrt(6.0) / (steps[1] * steps[1]));
  EXPECT_DOUBLE_EQ(d.hessian_sigma(0, 1), sigma / (2 * steps[0] * steps[1]));

  // Without noise, central differences of a quadratic are exact to rounding.
  const Derivatives clean = finite_differences(exact, x, steps, 1e-12);
  EXPECT_LT((clean.gradient - gradient).norm(), 1e-9);
  EXPECT_LT((clean.hessian - hessian).norm(), 1e-7);
}

TEST(FiniteDifferences, EigenvalueSigmaIsTheLinearPropagation)
{
  // In one dimension the eigenvalue is H_11 itself, and along a diagonal
  // Hessian's axes each eigenvalue is its entry: same sigma.
  const Derivatives one = finite_differences([](std::span<const double> x) { return x[0] * x[0]; },
                                             std::vector<double>{0.0}, std::vector<double>{0.1}, 1e-3);
  EXPECT_DOUBLE_EQ(one.eigenvalue_sigma[0], one.hessian_sigma(0, 0));
  const Derivatives diagonal
      = finite_differences(quadratic, std::vector<double>(centre), std::vector<double>{0.1, 0.2, 0.3}, 1e-3);
  for (int k = 0; k < 3; ++k)
  {
    int axis;
    Eigen::VectorXd(diagonal.hessian.diagonal().array() - diagonal.eigenvalues[k]).cwiseAbs().minCoeff(&axis);
    const double entry_sigma = diagonal.hessian_sigma(axis, axis);
    EXPECT_NEAR(diagonal.eigenvalue_sigma[k], entry_sigma, 1e-6 * entry_sigma);
  }
}

TEST(FiniteDifferences, Verdicts)
{
  const double sigma = 1e-6;
  const std::vector<double> origin{0, 0}, steps{0.1, 0.1};
  const auto verdict = [&](Score f) { return finite_differences(with_noise(f, sigma), origin, steps, sigma).verdict; };
  EXPECT_EQ(verdict([](std::span<const double> x) { return x[0] * x[0] + 2 * x[1] * x[1] + x[0] * x[1]; }),
            Verdict::local_minimum);
  EXPECT_EQ(verdict([](std::span<const double> x) { return -x[0] * x[0] - x[1] * x[1]; }), Verdict::local_maximum);
  EXPECT_EQ(verdict([](std::span<const double> x) { return x[0] * x[0] - x[1] * x[1]; }), Verdict::saddle);
  EXPECT_EQ(verdict([](std::span<const double> x) { return 0.01 * x[0] - 0.02 * x[1]; }), Verdict::not_stationary);
  // Flat along x1: the curvature's sign there is within the noise.
  EXPECT_EQ(verdict([](std::span<const double> x) { return x[0] * x[0]; }), Verdict::undetermined);
  // A slope the noise hides is stationary as far as the data can tell.
  EXPECT_EQ(verdict([](std::span<const double> x) { return x[0] * x[0] + x[1] * x[1] + 1e-8 * x[0]; }),
            Verdict::local_minimum);
  EXPECT_EQ(verdict_name(Verdict::not_stationary), "not stationary");
}

TEST(BalancedSteps, BalanceTruncationAgainstNoise)
{
  const double sigma = 1e-6, a = 2.0;
  const Box box{{-1, -1}, {1, 1}};
  // f''' = 6 a along x0 (the stencil is exact for a cubic); none along x1.
  const Score cubic = [a](std::span<const double> x) { return a * x[0] * x[0] * x[0] + x[1] * x[1]; };
  const StepChoice c = balanced_steps(cubic, std::vector<double>{0.2, 0.0}, box, sigma, std::vector<double>{0.1, 0.1});
  EXPECT_NEAR(c.third_derivative[0], 6 * a, 1e-6);
  EXPECT_NEAR(c.steps[0], std::cbrt(3 * sigma / (std::sqrt(2.0) * 6 * a)), 1e-12);
  // Unresolved f''': taken at 2 of its sigma, the step stays near the pilot's.
  EXPECT_NEAR(c.steps[1], std::cbrt(3 / std::sqrt(20.0)) * 0.1, 1e-12);
  EXPECT_EQ(c.evaluations, 8);
  // Near a bound the pilot and the step shrink to the room there.
  const StepChoice edge
      = balanced_steps(cubic, std::vector<double>{0.95, 0.0}, box, 1.0, std::vector<double>{0.1, 0.1});
  EXPECT_NEAR(edge.pilot_steps[0], 0.025, 1e-15);
  EXPECT_LE(edge.steps[0], 0.05 + 1e-15);
  EXPECT_THROW(balanced_steps(cubic, std::vector<double>{1.0, 0.0}, box, sigma, std::vector<double>{0.1, 0.1}),
               InputError);
}

TEST(SweepAxes, ValuesAlongEachFreeAxis)
{
  const Box box{{-1, 0.25, -1}, {1, 0.25, 1}};
  const std::vector<double> x{0.0, 0.25, 0.5};
  const std::vector<AxisSweep> sweeps = sweep_axes(quadratic, x, box, 5);
  ASSERT_EQ(sweeps.size(), 2u) << "the fixed axis 1 is not swept";
  EXPECT_EQ(sweeps[1].axis, 2);
  for (const AxisSweep& s : sweeps)
    for (int k = 0; k < 5; ++k)
    {
      std::vector<double> p = x;
      p[s.axis] = -1 + 0.5 * k;
      EXPECT_DOUBLE_EQ(s.coordinates[k], p[s.axis]);
      EXPECT_DOUBLE_EQ(s.values[k], quadratic(p));
    }
}

TEST(BodyFamily, RollerAreaAlongTheOffsetIsOptimalOnTheBound)
{
  // Centre-line rollers (theta 90, rho 1) get longer with the offset d, and
  // their surface area grows with it: the least area over d in [0.6, 1.4] is
  // at d = 0.6, the largest at d = 1.4. theta and rho are fixed by the box.
  const auto area = [](std::span<const double> p) {
    geometry::BodySpec spec;
    spec.body = "roller";
    spec.family = geometry::RollerFamily::centre_line;
    spec.genome = {.theta_deg = p[0], .offset = p[1], .ratio = p[2]};
    spec.points = 100;
    return geometry::mass_properties(geometry::make_body(spec)).area_m2;
  };
  OptimizeSettings s;
  s.start = {90, 1, 1};
  s.box = {{90, 0.6, 1}, {90, 1.4, 1}};
  s.max_evaluations = 60;

  const std::vector<AxisSweep> sweep = sweep_axes(area, s.start, s.box, 9);
  ASSERT_EQ(sweep.size(), 1u);
  for (std::size_t k = 1; k < sweep[0].values.size(); ++k)
    ASSERT_GT(sweep[0].values[k], sweep[0].values[k - 1]) << "area not increasing at d = " << sweep[0].coordinates[k];

  const OptimizeResult least = minimize(area, s);
  EXPECT_DOUBLE_EQ(least.best_x[1], 0.6) << least.stop_reason;
  EXPECT_DOUBLE_EQ(least.best_value, sweep[0].values.front());
  const OptimizeResult largest = minimize([&](std::span<const double> p) { return -area(p); }, s);
  EXPECT_DOUBLE_EQ(largest.best_x[1], 1.4) << largest.stop_reason;
  EXPECT_EQ(largest.best_x[0], 90);
  EXPECT_EQ(largest.best_x[2], 1);
}

TEST(OptimizeJson, NamedKeys)
{
  const OptimizeResult r = minimize(quadratic, quadratic_search(Method::sbplx));
  const nlohmann::json j = to_json(r);
  EXPECT_EQ(j.at("method"), "sbplx");
  EXPECT_EQ(j.at("history").size(), r.history.size());
  EXPECT_EQ(j.at("best_value").get<double>(), r.best_value);
  EXPECT_EQ(j.at("beats_start"), true);
  const nlohmann::json d = to_json(finite_differences(quadratic, centre, std::vector<double>{0.1, 0.1, 0.1}, 1e-6));
  EXPECT_EQ(d.at("verdict"), "local minimum");
  EXPECT_EQ(d.at("hessian").size(), 3u);
}
