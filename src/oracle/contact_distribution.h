#pragma once
// The contact distribution score (the preprint's definition 3): the score
// template applied to c_i, the number of samples in which face i touched.
#include "oracle/distribution_score.h"
#include "oracle/trajectory.h"
#include <Eigen/Core>

namespace rollcheck::oracle
{
struct ContactDistribution
{
  Eigen::VectorXd counts;          ///< samples in contact, per face
  DistributionSummary summary;     ///< summary.score is the CDS
  Convergence convergence;         ///< CDS after every `convergence_every` samples
};

ContactDistribution contact_distribution(const Trajectory& trajectory, const Eigen::VectorXd& face_areas,
                                         long convergence_every);
} // namespace rollcheck::oracle
