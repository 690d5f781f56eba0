#include "oracle/distribution_score.h"
#include <algorithm>
#include <cmath>
#include <limits>

namespace rollcheck::oracle
{
double pairwise_sum(const double* x, std::size_t n)
{
  if (n < 8)
  {
    double s = 0.0;
    for (std::size_t i = 0; i < n; ++i)
      s += x[i];
    return s;
  }
  if (n <= 128)
  {
    double r[8];
    for (int k = 0; k < 8; ++k)
      r[k] = x[k];
    std::size_t i = 8;
    for (; i + 8 <= n; i += 8)
      for (int k = 0; k < 8; ++k)
        r[k] += x[i + k];
    double s = ((r[0] + r[1]) + (r[2] + r[3])) + ((r[4] + r[5]) + (r[6] + r[7]));
    for (; i < n; ++i)
      s += x[i];
    return s;
  }
  std::size_t half = n / 2;
  half -= half % 8;
  return pairwise_sum(x, half) + pairwise_sum(x + half, n - half);
}

namespace
{
double sum(const Eigen::VectorXd& v) { return pairwise_sum(v.data(), static_cast<std::size_t>(v.size())); }
constexpr double infinity = std::numeric_limits<double>::infinity();
} // namespace

ScoreTemplate::ScoreTemplate(const Eigen::VectorXd& face_areas)
    : areas_(face_areas), fractions_(face_areas.size()), total_area_(sum(face_areas))
{
  for (Eigen::Index i = 0; i < areas_.size(); ++i)
    fractions_[i] = areas_[i] / total_area_;
}

double ScoreTemplate::operator()(const Eigen::VectorXd& accumulator) const
{
  const double total = sum(accumulator);
  if (total == 0)
    return infinity;
  thread_local std::vector<double> weighted;
  weighted.resize(static_cast<std::size_t>(accumulator.size()));
  for (Eigen::Index i = 0; i < accumulator.size(); ++i)
  {
    const double deviation = accumulator[i] / total - fractions_[i];
    weighted[static_cast<std::size_t>(i)] = areas_[i] * (deviation * deviation);
  }
  return pairwise_sum(weighted.data(), weighted.size()) / total_area_;
}

double distribution_score(const Eigen::VectorXd& accumulator, const Eigen::VectorXd& face_areas)
{
  return ScoreTemplate(face_areas)(accumulator);
}

DistributionSummary summarize_distribution(const Eigen::VectorXd& accumulator, const Eigen::VectorXd& face_areas)
{
  DistributionSummary s;
  s.score = distribution_score(accumulator, face_areas);
  const auto n = static_cast<double>(accumulator.size());
  const double mean = sum(accumulator) / n;
  s.faces_with = static_cast<long>((accumulator.array() > 0).count());
  s.faces_without = static_cast<long>(accumulator.size()) - s.faces_with;
  if (mean > 0)
  {
    Eigen::VectorXd squared(accumulator.size());
    for (Eigen::Index i = 0; i < accumulator.size(); ++i)
      squared[i] = (accumulator[i] - mean) * (accumulator[i] - mean);
    s.cv = std::sqrt(sum(squared) / n) / mean;
    s.max_mean_ratio = accumulator.maxCoeff() / mean;
  }
  else
    s.cv = s.max_mean_ratio = infinity;
  return s;
}

ValueStatistics value_statistics(const std::vector<double>& values)
{
  ValueStatistics s;
  s.count = values.size();
  if (values.empty())
  {
    s.cv = infinity;
    return s;
  }
  const auto n = static_cast<double>(values.size());
  s.mean = pairwise_sum(values.data(), values.size()) / n;
  s.max = *std::max_element(values.begin(), values.end());
  s.min = *std::min_element(values.begin(), values.end());
  std::vector<double> squared(values.size());
  for (std::size_t i = 0; i < values.size(); ++i)
    squared[i] = (values[i] - s.mean) * (values[i] - s.mean);
  s.cv = s.mean > 0 ? std::sqrt(pairwise_sum(squared.data(), squared.size()) / n) / s.mean : infinity;
  return s;
}
} // namespace rollcheck::oracle
