// Rolling dynamics (rolling_dynamics.h): the parts both contacts share, the
// input checks, the Dormand-Prince 5(4) integrator and the sampled run with
// its energy-balance check, and the mass models. The line contact is in
// rolling_line_contact.cpp, the point contact in rolling_point_contact.cpp.
#include "oracle/rolling_dynamics.h"
#include "core/error.h"
#include "geometry/mass_properties.h"
#include "oracle/rolling_dynamics_internal.h"
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <fmt/format.h>

namespace rollcheck::oracle
{
namespace detail
{
void require_positive(double value, const char* what)
{
  if (!std::isfinite(value) || value <= 0)
    throw InputError(fmt::format("rolling: {} must be positive and finite, got {}", what, value));
}

void validate(const RollingParameters& p)
{
  require_positive(p.gravity_m_s2, "gravity (m/s^2)");
  require_positive(p.duration_s, "duration (s)");
  require_positive(p.sample_interval_s, "sample interval (s)");
  require_positive(p.relative_tolerance, "relative tolerance");
  require_positive(p.energy_tolerance, "energy tolerance");
  if (!std::isfinite(p.rolling_resistance_n_m_s) || p.rolling_resistance_n_m_s < 0)
    throw InputError(fmt::format("rolling: rolling resistance (N m s) must be finite and non-negative, got {}",
                                 p.rolling_resistance_n_m_s));
  if (p.duration_s / p.sample_interval_s > 1e8)
    throw InputError("rolling: more than 1e8 samples (duration / sample interval)");
}

void validate(const MassModel& mass)
{
  require_positive(mass.mass_kg, "mass (kg)");
  if (!mass.centre_of_mass_m.allFinite() || !mass.inertia_kg_m2.allFinite())
    throw InputError("rolling: centre of mass or inertia is not finite");
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(mass.inertia_kg_m2);
  if (eig.eigenvalues().minCoeff() <= 0)
    throw InputError("rolling: inertia tensor is not positive definite");
}

// Dormand-Prince 5(4) with step control and a projection after each accepted step.
void Dopri5::advance(Eigen::VectorXd& y, double duration)
{
  static constexpr double a21 = 1.0 / 5, a31 = 3.0 / 40, a32 = 9.0 / 40, a41 = 44.0 / 45, a42 = -56.0 / 15,
                          a43 = 32.0 / 9, a51 = 19372.0 / 6561, a52 = -25360.0 / 2187, a53 = 64448.0 / 6561,
                          a54 = -212.0 / 729, a61 = 9017.0 / 3168, a62 = -355.0 / 33, a63 = 46732.0 / 5247,
                          a64 = 49.0 / 176, a65 = -5103.0 / 18656, b1 = 35.0 / 384, b3 = 500.0 / 1113,
                          b4 = 125.0 / 192, b5 = -2187.0 / 6784, b6 = 11.0 / 84, e1 = 71.0 / 57600,
                          e3 = -71.0 / 16695, e4 = 71.0 / 1920, e5 = -17253.0 / 339200, e6 = 22.0 / 525,
                          e7 = -1.0 / 40;
  double t = 0;
  while (t < duration)
  {
    const bool last = h_ >= duration - t;
    const double h = last ? duration - t : h_;
    const Eigen::VectorXd k1 = rhs_(y);
    const Eigen::VectorXd k2 = rhs_(y + h * a21 * k1);
    const Eigen::VectorXd k3 = rhs_(y + h * (a31 * k1 + a32 * k2));
    const Eigen::VectorXd k4 = rhs_(y + h * (a41 * k1 + a42 * k2 + a43 * k3));
    const Eigen::VectorXd k5 = rhs_(y + h * (a51 * k1 + a52 * k2 + a53 * k3 + a54 * k4));
    const Eigen::VectorXd k6 = rhs_(y + h * (a61 * k1 + a62 * k2 + a63 * k3 + a64 * k4 + a65 * k5));
    Eigen::VectorXd next = y + h * (b1 * k1 + b3 * k3 + b4 * k4 + b5 * k5 + b6 * k6);
    const Eigen::VectorXd k7 = rhs_(next);
    const Eigen::VectorXd error = h * (e1 * k1 + e3 * k3 + e4 * k4 + e5 * k5 + e6 * k6 + e7 * k7);
    double norm = 0;
    for (Eigen::Index i = 0; i < y.size(); ++i)
    {
      const double scale = rtol_ * std::max({floor_[i], std::abs(y[i]), std::abs(next[i])});
      norm += (error[i] / scale) * (error[i] / scale);
    }
    norm = std::sqrt(norm / static_cast<double>(y.size()));
    if (!std::isfinite(norm))
      throw ComputationError("rolling: the integration produced a non-finite state");
    const double factor = std::clamp(0.9 * std::pow(std::max(norm, 1e-10), -0.2), 0.2, 5.0);
    if (norm <= 1)
    {
      ++accepted_;
      t = last ? duration : t + h;
      project_(next);
      y = std::move(next);
      if (!last || factor < 1)
        h_ = h * factor;
    }
    else
    {
      ++rejected_;
      h_ = h * factor;
    }
    if (h_ < 1e-14 * duration)
      throw ComputationError(fmt::format("rolling: step size underflow ({:.3g} s)", h_));
  }
}

void run_sampled(Dopri5& integrator, Eigen::VectorXd& y, const RollingParameters& p, RollingTrajectory& trajectory,
                 const SampleAt& sample_at)
{
  const long n_intervals = static_cast<long>(std::ceil(p.duration_s / p.sample_interval_s - 1e-9));
  trajectory.samples.reserve(static_cast<std::size_t>(n_intervals) + 1);
  double initial_energy = 0;
  for (long k = 0; k <= n_intervals; ++k)
  {
    const double time = std::min(static_cast<double>(k) * p.sample_interval_s, p.duration_s);
    if (k > 0)
      integrator.advance(y, time - trajectory.samples.back().time_s);
    RollingSample s = sample_at(y, time);
    const double energy = s.kinetic_energy_j + s.potential_energy_j;
    if (k == 0)
      initial_energy = energy;
    const double error = std::abs(energy + s.dissipated_energy_j - initial_energy) / initial_energy;
    trajectory.max_energy_error = std::max(trajectory.max_energy_error, error);
    if (error > p.energy_tolerance)
      throw ComputationError(fmt::format("rolling: energy balance error {:.3g} at t = {:.4g} s exceeds the bound "
                                         "{:.3g}; tighten the relative tolerance",
                                         error, time, p.energy_tolerance));
    const bool held = s.normal_force_n > 0 &&
                      (trajectory.mode == ContactMode::point || (s.centre_of_pressure >= 0 && s.centre_of_pressure <= 1));
    trajectory.samples.push_back(s);
    if (!held)
    {
      trajectory.contact_held = false;
      break;
    }
  }
  trajectory.accepted_steps = integrator.accepted();
  trajectory.rejected_steps = integrator.rejected();
}
} // namespace detail

// Mass models.
MassModel mass_model_of_mesh(const geometry::SurfaceMesh& mesh, double mass_kg)
{
  detail::require_positive(mass_kg, "mass (kg)");
  const geometry::MassProperties mp = geometry::mass_properties(mesh);
  if (!(mp.volume_m3 > 0))
    throw InputError("rolling: the mesh encloses no volume");
  return {mass_kg, mp.centre_of_mass, mp.inertia * (mass_kg / mp.volume_m3)};
}

MassModel mass_model_of_ellipsoid(const Ellipsoid& body, double mass_kg)
{
  detail::require_positive(mass_kg, "mass (kg)");
  const Eigen::Vector3d a = body.semi_axes_m;
  for (int i = 0; i < 3; ++i)
    detail::require_positive(a[i], "ellipsoid semi-axis (m)");
  const Eigen::Vector3d sq = a.cwiseProduct(a);
  MassModel m;
  m.mass_kg = mass_kg;
  m.inertia_kg_m2 = (mass_kg / 5 * Eigen::Vector3d(sq.y() + sq.z(), sq.x() + sq.z(), sq.x() + sq.y())).asDiagonal();
  return m;
}
} // namespace rollcheck::oracle
