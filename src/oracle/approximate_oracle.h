#pragma once
// The preprint's approximate oracle (Algorithm 1): a prescribed rotation
// sequence, no dynamics. At step t = 0 .. T-1 (the reference code's range;
// the preprint writes 1 .. T)
//   R_t = R_x(alpha_t) R_y(beta_t),  beta_t = (2 pi / T) t n_cycles,
//   alpha_t = A_w sin(pi t / T),
// the face centroids are rotated, the body is grounded, and faces whose
// centroid lies less than eps above the ground touch.
#include "oracle/paper_compat.h"
#include "oracle/rolling_body.h"
#include "oracle/trajectory.h"
#include <Eigen/Core>

namespace rollcheck::oracle
{
struct ApproximateSettings
{
  long steps = 600;                   ///< T (the reference's run_oracle default; its search uses 200 or 300)
  double contact_threshold_m = 0.04;  ///< eps (the preprint's)
  double roll_cycles = 2.5;           ///< n_cycles, turns about y over the T steps (the preprint's)
  double wobble_amplitude_rad = 0.6;  ///< A_w (the preprint's)
};

/// InputError for steps < 1, a negative or non-finite threshold, non-finite angles.
void validate(const ApproximateSettings& options);

/// R_x(alpha_t) R_y(beta_t).
Eigen::Matrix3d approximate_rotation(long step, const ApproximateSettings& options);

Trajectory approximate_oracle(const RollingBody& body, const ApproximateSettings& options, const PaperCompat& compat);
} // namespace rollcheck::oracle
