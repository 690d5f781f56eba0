#include "oracle/uniformity_score.h"
#include "core/error.h"
#include <cmath>
#include <fmt/format.h>
#include <numbers>

namespace rollcheck::oracle
{
namespace
{
/// integral_0^1 ds / ((1 - s) r0 + s r1), stable when r1 is close to r0.
double mean_reciprocal_radius(double r0, double r1)
{
  const double x = (r1 - r0) / r0;
  if (std::abs(x) < 1e-4)
    return (1 - x / 2 + x * x / 3 - x * x * x / 4) / r0;
  return std::log(r1 / r0) / (r1 - r0);
}
} // namespace

UniformityScore uniformity_score(const Eigen::VectorXd& measure, const Eigen::VectorXd& face_areas_m2)
{
  if (measure.size() != face_areas_m2.size() || measure.size() == 0)
    throw InputError(fmt::format("uniformity score: {} measures for {} face areas", measure.size(),
                                 face_areas_m2.size()));
  if (!measure.allFinite() || measure.minCoeff() < 0)
    throw InputError("uniformity score: contact measures must be finite and non-negative");
  if (!face_areas_m2.allFinite() || !(face_areas_m2.minCoeff() > 0))
    throw InputError("uniformity score: face areas must be finite and positive");
  const double total = measure.sum();
  if (!(total > 0))
    throw InputError("uniformity score: the body has no contact");
  UniformityScore score;
  score.surface_area_m2 = face_areas_m2.sum();
  const double mean_density = total / score.surface_area_m2;
  double variance = 0, covered = 0;
  for (Eigen::Index f = 0; f < measure.size(); ++f)
  {
    const double relative = measure[f] / face_areas_m2[f] / mean_density;
    variance += face_areas_m2[f] * (relative - 1) * (relative - 1);
    if (relative > 1e-6) // above rounding: clipped shares of elements lying on a cone boundary
      covered += face_areas_m2[f];
    score.max_over_mean = std::max(score.max_over_mean, relative);
  }
  score.normalised_variance = variance / score.surface_area_m2;
  score.coverage = covered / score.surface_area_m2;
  return score;
}

double continuum_uniformity(const RollingTrajectory& trajectory, double begin_s, double end_s,
                            double surface_area_m2, const ContactWidth& width)
{
  if (trajectory.mode != ContactMode::line)
    throw InputError("continuum uniformity: defined for line contact only (point contact has no area density)");
  if (!(end_s > begin_s) || !(surface_area_m2 > 0))
    throw InputError("continuum uniformity: needs end > begin and a positive surface area");
  double first = 0, second = 0; // integral rho dA, integral rho^2 dA
  const auto& samples = trajectory.samples;
  for (std::size_t k = 0; k + 1 < samples.size(); ++k)
  {
    const double t0 = std::max(samples[k].time_s, begin_s), t1 = std::min(samples[k + 1].time_s, end_s);
    if (!(t1 > t0))
      continue;
    // Trapezoid rule on the integrands at the interval's samples.
    auto integrands = [&](const RollingSample& s) {
      const double first_rate = contact_measure_rate(s, trajectory.mode, width);
      if (width.model == ContactWidthModel::hertz)
        return std::pair{first_rate, 16 * s.normal_force_n /
                                         (std::numbers::pi * width.effective_modulus_pa * std::abs(s.rolling_rate_rad_s))};
      return std::pair{first_rate,
                       first_rate / std::abs(s.rolling_rate_rad_s) * mean_reciprocal_radius(s.start_radius_m, s.end_radius_m)};
    };
    const auto [l0, q0] = integrands(samples[k]);
    const auto [l1, q1] = integrands(samples[k + 1]);
    first += (t1 - t0) * (l0 + l1) / 2;
    second += (t1 - t0) * (q0 + q1) / 2;
  }
  if (!(first > 0) || !std::isfinite(second))
    throw ComputationError("continuum uniformity: no contact in the window, or the ruling stops (infinite density)");
  return surface_area_m2 * second / (first * first) - 1;
}
} // namespace rollcheck::oracle
