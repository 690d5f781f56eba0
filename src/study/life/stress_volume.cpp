#include "study/life/stress_volume.h"
#include <algorithm>
#include <cmath>

namespace rollcheck::study::life
{
namespace
{
constexpr int depths = 2000, thresholds = 400;
constexpr double zeta_lo = 1e-3, zeta_hi = 10;
} // namespace

double derived_load_life_exponent(const LifeConstants& k)
{
  return (k.stress_exponent + 1 - k.depth_exponent) / (2 * k.weibull_slope);
}

DepthIntegrals::DepthIntegrals(contact::FatigueCriterion criterion, const LifeConstants& k)
{
  log_lo_ = std::log(zeta_lo);
  log_step_ = (std::log(zeta_hi) - log_lo_) / (depths - 1);
  f_.resize(depths);
  for (int i = 0; i < depths; ++i)
  {
    const double zeta = std::exp(log_lo_ + i * log_step_);
    f_[i] = contact::pass_stress(criterion, zeta, k.poisson_ratio, k.dang_van_alpha).value_over_p0;
    if (f_[i] > peak_)
      peak_ = f_[i], peak_depth_ = zeta;
  }
  // H(t) = integral (f - t)_+^c zeta^(1 - h) d ln(zeta), trapezoid rule.
  h_.resize(thresholds + 1);
  for (int j = 0; j <= thresholds; ++j)
  {
    const double t = peak_ * j / thresholds;
    double sum = 0;
    for (int i = 0; i < depths; ++i)
    {
      const double excess = f_[i] - t;
      if (excess <= 0)
        continue;
      const double zeta = std::exp(log_lo_ + i * log_step_);
      sum += (i == 0 || i == depths - 1 ? 0.5 : 1.0) * std::pow(excess, k.stress_exponent)
             * std::pow(zeta, 1 - k.depth_exponent);
    }
    h_[j] = std::pow(sum * log_step_, 1 / k.stress_exponent); // H^(1/c): nearly linear in t up to the peak
  }
}

double DepthIntegrals::profile(double zeta) const
{
  if (!(zeta >= zeta_lo) || !(zeta <= zeta_hi))
    return 0;
  const double u = (std::log(zeta) - log_lo_) / log_step_;
  const int i = std::min(depths - 2, static_cast<int>(u));
  const double w = u - i;
  return (1 - w) * f_[i] + w * f_[i + 1];
}

double DepthIntegrals::integral(double t, double stress_exponent) const
{
  if (!(t < peak_ * (1 - 1e-9))) // at the limit to rounding (the cylinder at its own limit load): none
    return 0;
  const double u = std::max(0.0, t) / peak_ * thresholds;
  const int j = std::min(thresholds - 1, static_cast<int>(u));
  const double w = u - j;
  return std::pow((1 - w) * h_[j] + w * h_[j + 1], stress_exponent);
}
} // namespace rollcheck::study::life
