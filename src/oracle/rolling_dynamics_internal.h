#pragma once
// Internal to rolling dynamics (rolling_dynamics.h): what the line contact
// (rolling_line_contact.cpp) and the point contact (rolling_point_contact.cpp)
// share, defined in rolling_dynamics.cpp: input checks, the Dormand-Prince
// integrator and the sampled run with its energy-balance check.
#include "oracle/rolling_dynamics.h"
#include <Eigen/Core>
#include <functional>

namespace rollcheck::oracle::detail
{
/// InputError naming `what` unless `value` is positive and finite.
void require_positive(double value, const char* what);

/// InputError for a non-positive or non-finite gravity, duration, sample
/// interval or tolerance, a negative resistance, or more than 1e8 samples.
void validate(const RollingParameters& p);

/// InputError for a non-positive mass, a non-finite centre of mass or inertia,
/// or an inertia tensor that is not positive definite.
void validate(const MassModel& mass);

/// Dormand-Prince 5(4), autonomous, with a projection after each accepted step.
class Dopri5
{
public:
  using Rhs = std::function<Eigen::VectorXd(const Eigen::VectorXd&)>;
  using Project = std::function<void(Eigen::VectorXd&)>;

  Dopri5(Rhs rhs, Project project, Eigen::VectorXd floor, double rtol, double initial_step)
      : rhs_(std::move(rhs)), project_(std::move(project)), floor_(std::move(floor)), rtol_(rtol), h_(initial_step)
  {
  }

  /// Advances y by `duration` (s), landing exactly on its end.
  void advance(Eigen::VectorXd& y, double duration);

  long accepted() const { return accepted_; }
  long rejected() const { return rejected_; }

private:
  Rhs rhs_;
  Project project_;
  Eigen::VectorXd floor_;
  double rtol_;
  double h_;
  long accepted_ = 0;
  long rejected_ = 0;
};

/// The sample of the motion at state y and time t.
using SampleAt = std::function<RollingSample(const Eigen::VectorXd& y, double time)>;

/// Integrates over the run, one sample per interval; checks the energy balance
/// at each sample and stops after the first sample whose contact does not hold
/// (normal force not positive, or centre of pressure off the ruling).
void run_sampled(Dopri5& integrator, Eigen::VectorXd& y, const RollingParameters& p, RollingTrajectory& trajectory,
                 const SampleAt& sample_at);
} // namespace rollcheck::oracle::detail
