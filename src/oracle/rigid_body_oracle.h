#pragma once
// The preprint's rigid-body oracle (Algorithm 2). Each run starts at the
// identity orientation with an initial spin omega_0 and repeats, for
// N = floor(T / dt) steps:
//   R = R(q); s = lowest vertex under R;
//   tau = (r_o - s) x (0, 0, -m g) - gamma omega          (r_o: the point turned about)
//   omega += I^-1 (tau - omega x I omega) dt;  |omega| capped at omega_max
//   q = dq(omega, dt) q, normalised, dq = [cos(|omega| dt / 2), omega/|omega| sin(|omega| dt / 2)];
// and every `sample_every` steps (the first at step 0) records R, the support
// vertex and the faces within eps of the ground. Counts from all runs are
// pooled. In paper-compatible mode the arithmetic follows the reference's
// numpy/OpenBLAS operations one by one (fused multiply-adds where its BLAS
// uses them), so that trajectories agree with it to rounding for as long as
// the chaotic dynamics let them (about 1000 steps to 1e-10).
#include "oracle/paper_compat.h"
#include "oracle/rolling_body.h"
#include "oracle/trajectory.h"
#include <Eigen/Core>
#include <vector>

namespace rollcheck::oracle
{
/// The reference code's five initial spins (rad/s); runs use the first n.
const std::vector<Eigen::Vector3d>& reference_initial_spins();

struct RigidBodySettings
{
  double duration_s = 10.0;            ///< T per run (the preprint's parameter table)
  double time_step_s = 0.002;          ///< dt (the preprint's)
  long sample_every = 25;              ///< steps between samples (the preprint's)
  double contact_threshold_m = 0.04;   ///< eps (the preprint's)
  double damping_n_m_s = 0.02;         ///< gamma, torque per angular velocity (the preprint's)
  double mass_kg = 1.0;                ///< m (the preprint's)
  double gravity_m_s2 = 9.81;          ///< g (the preprint's)
  double max_angular_speed_rad_s = 50; ///< cap on |omega| (the reference code's)
  /// One run per spin; the reference's first three by default.
  std::vector<Eigen::Vector3d> initial_spins{reference_initial_spins().begin(),
                                             reference_initial_spins().begin() + 3};
};

/// InputError for a non-positive or non-finite dt or duration, fewer steps
/// than one, sample_every < 1, a negative threshold, damping, mass or gravity,
/// no runs, or a non-finite spin.
void validate(const RigidBodySettings& options);

/// Integration steps per run, floor(T / dt) as the reference's int(T / dt).
long steps_per_run(const RigidBodySettings& options);

Trajectory rigid_body_oracle(const RollingBody& body, const RigidBodySettings& options, const PaperCompat& compat);

/// Orientation before steps 0 .. n_steps-1 of one run from `initial_spin`
/// (element 0 is the identity): the reference's `simulate_rolling` list.
std::vector<Eigen::Matrix3d> rigid_body_rotations(const RollingBody& body, const Eigen::Vector3d& initial_spin,
                                                  long n_steps, const RigidBodySettings& options,
                                                  const PaperCompat& compat);
} // namespace rollcheck::oracle
