// The distribution-score template on hand-made accumulators with known answers.
#include "oracle/contact_distribution.h"
#include "oracle/distribution_score.h"
#include <gtest/gtest.h>
#include <random>

namespace
{
using namespace rollcheck::oracle;

Eigen::VectorXd unequal_areas(int n)
{
  Eigen::VectorXd a(n);
  for (int i = 0; i < n; ++i)
    a[i] = 0.5 + 0.25 * (i % 7) + 0.01 * i;
  return a;
}

TEST(ScoreTemplate, ContactProportionalToAreaScoresZero)
{
  const Eigen::VectorXd areas = unequal_areas(50);
  EXPECT_EQ(distribution_score(areas, areas), 0.0);
  EXPECT_NEAR(distribution_score(3.7 * areas, areas), 0.0, 1e-30);
  const Eigen::VectorXd equal = Eigen::VectorXd::Constant(40, 0.25);
  EXPECT_EQ(distribution_score(Eigen::VectorXd::Constant(40, 12.0), equal), 0.0);
}

TEST(ScoreTemplate, AllContactOnOneFaceGivesTheClosedForm)
{
  // x = e_k: score = (1/A) [a_k (1 - a_k/A)^2 + sum_{i != k} a_i (a_i/A)^2].
  const Eigen::VectorXd areas = unequal_areas(30);
  const double total = areas.sum();
  for (const int k : {0, 13, 29})
  {
    Eigen::VectorXd x = Eigen::VectorXd::Zero(30);
    x[k] = 17.0;
    double expected = areas[k] * std::pow(1 - areas[k] / total, 2);
    for (int i = 0; i < 30; ++i)
      if (i != k)
        expected += areas[i] * std::pow(areas[i] / total, 2);
    expected /= total;
    EXPECT_NEAR(distribution_score(x, areas), expected, 1e-15 * expected);
  }
  // Equal areas: (N - 1) / N^2, contact CV sqrt(N - 1), max/mean N.
  const int n = 64;
  Eigen::VectorXd x = Eigen::VectorXd::Zero(n);
  x[5] = 1.0;
  const DistributionSummary s = summarize_distribution(x, Eigen::VectorXd::Constant(n, 0.1));
  EXPECT_NEAR(s.score, (n - 1.0) / (n * n), 1e-16);
  EXPECT_NEAR(s.cv, std::sqrt(n - 1.0), 1e-13);
  EXPECT_NEAR(s.max_mean_ratio, n, 1e-12);
  EXPECT_EQ(s.faces_with, 1);
  EXPECT_EQ(s.faces_without, n - 1);
}

TEST(ScoreTemplate, EmptyAccumulatorIsInfinite)
{
  const DistributionSummary s = summarize_distribution(Eigen::VectorXd::Zero(10), Eigen::VectorXd::Ones(10));
  EXPECT_TRUE(std::isinf(s.score) && s.score > 0);
  EXPECT_TRUE(std::isinf(s.cv));
  EXPECT_TRUE(std::isinf(s.max_mean_ratio));
  EXPECT_EQ(s.faces_with, 0);
}

TEST(ScoreTemplate, TwoFacesHalfAndHalfAgainstAreasOneAndThree)
{
  // a = (1, 3), x = (1, 1): deviations (1/2 - 1/4, 1/2 - 3/4) = (1/4, -1/4);
  // score = (1 * 1/16 + 3 * 1/16) / 4 = 1/16.
  EXPECT_EQ(distribution_score(Eigen::Vector2d(1, 1), Eigen::Vector2d(1, 3)), 1.0 / 16);
}

TEST(PairwiseSum, AgreesWithExactSumOfIntegersAndNaiveSumOfReals)
{
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0, 1);
  for (const std::size_t n : {0u, 1u, 7u, 8u, 9u, 127u, 128u, 129u, 1000u, 4097u})
  {
    std::vector<double> ints(n), reals(n);
    double exact = 0;
    long double naive = 0;
    for (std::size_t i = 0; i < n; ++i)
    {
      ints[i] = static_cast<double>(i % 13);
      exact += ints[i];
      reals[i] = u(rng);
      naive += reals[i];
    }
    EXPECT_EQ(pairwise_sum(ints.data(), n), exact);
    EXPECT_NEAR(pairwise_sum(reals.data(), n), static_cast<double>(naive), 1e-13 * (1.0 + n));
  }
}

TEST(ContactDistribution, CountsAndConvergenceOfAHandMadeTrajectory)
{
  // Three faces of areas 1, 1, 2; samples touch {0}, {1, 2}, {2}, {0, 2}.
  Trajectory t;
  const std::vector<std::vector<int>> contacts = {{0}, {1, 2}, {2}, {0, 2}};
  for (const auto& c : contacts)
  {
    t.samples.push_back({Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero(), 0, 0.0, 0});
    t.contact_faces.insert(t.contact_faces.end(), c.begin(), c.end());
    t.contact_offsets.push_back(static_cast<int>(t.contact_faces.size()));
  }
  const ContactDistribution d = contact_distribution(t, Eigen::Vector3d(1, 1, 2), 2);
  EXPECT_EQ(d.counts, Eigen::Vector3d(2, 1, 3));
  ASSERT_EQ(d.convergence.size(), 2u);
  EXPECT_EQ(d.convergence[0].first, 2);
  // After 2 samples counts (1, 1, 1): deviations (1/3 - 1/4, 1/3 - 1/4, 1/3 - 1/2).
  const double after_two = (1 * std::pow(1.0 / 12, 2) * 2 + 2 * std::pow(1.0 / 6, 2)) / 4;
  EXPECT_NEAR(d.convergence[0].second, after_two, 1e-17);
  // Final counts proportional to (2, 1, 3) / 6 against (1, 1, 2) / 4.
  const double final_score = (std::pow(2.0 / 6 - 0.25, 2) + std::pow(1.0 / 6 - 0.25, 2) + 2 * std::pow(0.5 - 0.5, 2)) / 4;
  EXPECT_NEAR(d.summary.score, final_score, 1e-17);
  EXPECT_EQ(d.convergence[1], std::make_pair(4L, d.summary.score));
}

TEST(ValueStatistics, MeanMinMaxAndCoefficientOfVariation)
{
  const ValueStatistics s = value_statistics({2.0, 4.0, 6.0});
  EXPECT_EQ(s.mean, 4.0);
  EXPECT_EQ(s.min, 2.0);
  EXPECT_EQ(s.max, 6.0);
  EXPECT_NEAR(s.cv, std::sqrt(8.0 / 3.0) / 4.0, 1e-16);
  EXPECT_TRUE(std::isinf(value_statistics({}).cv));
}
} // namespace
