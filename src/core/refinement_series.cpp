#include "core/refinement_series.h"
#include <cmath>
#include <limits>

namespace rollcheck
{
double relative_change(double before, double last) { return last / before - 1; }

double last_change(const RefinementSeries& series, const LevelChange& change)
{
  const std::size_t n = series.size();
  if (n < 2)
    return std::numeric_limits<double>::quiet_NaN();
  return change(series.value[n - 2], series.value[n - 1]);
}

bool converged(const RefinementSeries& series, double tolerance, const LevelChange& change)
{
  return series.size() >= 2 && std::abs(last_change(series, change)) < tolerance;
}

double fitted_exponent(const RefinementSeries& series)
{
  const std::size_t n = series.size();
  if (n < 2)
    return std::numeric_limits<double>::quiet_NaN();
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < n; ++i)
  {
    if (series.value[i] == 0)
      return std::numeric_limits<double>::quiet_NaN();
    const double lx = std::log(series.element_size_m[i]), ly = std::log(std::abs(series.value[i]));
    sx += lx;
    sy += ly;
    sxx += lx * lx;
    sxy += lx * ly;
  }
  const double m = static_cast<double>(n);
  return (m * sxy - sx * sy) / (m * sxx - sx * sx);
}
} // namespace rollcheck
