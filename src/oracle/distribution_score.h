#pragma once
// The score template every distribution score shares (the preprint's CDS
// definition with the contact count replaced by any per-face accumulator x):
//   score = (1/A) sum_i a_i (x_i / sum_j x_j - a_i / A)^2,   A = sum_i a_i,
// 0 when x is proportional to the face areas. An accumulator that sums to 0
// (nothing ever touched) has no distribution: the score is +infinity, as in the
// reference code. Sums use numpy's pairwise summation so that values agree with
// the reference to rounding.
#include <Eigen/Core>
#include <vector>

namespace rollcheck::oracle
{
/// Sum with numpy's pairwise summation (blocks of 8 below 128 terms).
double pairwise_sum(const double* x, std::size_t n);

/// The template for one body, with its area fractions a_i / A formed once
/// (for repeated scoring, as in convergence snapshots).
class ScoreTemplate
{
public:
  explicit ScoreTemplate(const Eigen::VectorXd& face_areas);
  double operator()(const Eigen::VectorXd& accumulator) const;

private:
  Eigen::VectorXd areas_, fractions_;
  double total_area_;
};

double distribution_score(const Eigen::VectorXd& accumulator, const Eigen::VectorXd& face_areas);

struct DistributionSummary
{
  double score;              ///< the template above, +inf when sum x = 0
  double cv;                 ///< population std / mean of x over all faces, +inf when the mean is 0
  double max_mean_ratio;     ///< max x / mean x, +inf when the mean is 0
  long faces_with;           ///< faces with x > 0
  long faces_without;        ///< faces with x = 0
};

DistributionSummary summarize_distribution(const Eigen::VectorXd& accumulator, const Eigen::VectorXd& face_areas);

/// Statistics of a list of positive values (per-orientation peaks, per-face
/// damage): mean, max, min, population std / mean. Empty lists give mean,
/// max, min 0 and cv +inf, as the reference code.
struct ValueStatistics
{
  double mean = 0, max = 0, min = 0, cv = 0;
  std::size_t count = 0;
};
ValueStatistics value_statistics(const std::vector<double>& values);

/// Score after every `every` samples: (samples so far, score).
using Convergence = std::vector<std::pair<long, double>>;
} // namespace rollcheck::oracle
