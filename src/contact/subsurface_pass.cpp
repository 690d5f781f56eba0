#include "contact/subsurface_pass.h"
#include "contact/subsurface_line_contact.h"
#include "core/error.h"
#include <algorithm>
#include <array>
#include <cmath>
#include <fmt/format.h>
#include <functional>

namespace rollcheck::contact
{
namespace
{
constexpr int pass_points = 801;
constexpr double pass_half_length = 4; // in b: beyond it every criterion has decayed below its peak
const double golden = (std::sqrt(5.0) - 1) / 2;

/// Golden-section maximum of f on [lo, hi]: (argument, value).
std::pair<double, double> golden_maximum(const std::function<double(double)>& f, double lo, double hi)
{
  double a = hi - golden * (hi - lo), b = lo + golden * (hi - lo);
  double fa = f(a), fb = f(b);
  for (int k = 0; k < 60 && hi - lo > 1e-12 * std::max(1.0, std::abs(hi)); ++k)
  {
    if (fa < fb)
      lo = a, a = b, fa = fb, b = lo + golden * (hi - lo), fb = f(b);
    else
      hi = b, b = a, fb = fa, a = hi - golden * (hi - lo), fa = f(a);
  }
  return fa > fb ? std::pair{a, fa} : std::pair{b, fb};
}

/// The largest of f over `points` equal steps of [lo, hi], refined about the best.
std::pair<double, double> scan_maximum(const std::function<double(double)>& f, double lo, double hi, int points)
{
  const double step = (hi - lo) / (points - 1);
  int best = 0;
  double best_value = -INFINITY;
  for (int i = 0; i < points; ++i)
    if (const double v = f(lo + i * step); v > best_value)
      best_value = v, best = i;
  return golden_maximum(f, lo + std::max(0, best - 1) * step, lo + std::min(points - 1, best + 1) * step);
}

/// The Dang Van stress of a pass at depth z: the history on the scan's grid
/// gives the shakedown centre (mid-range of each deviator component); the
/// largest tau_meso + alpha p_h is then refined along x.
PassStress dang_van(double z, double nu, double alpha)
{
  std::array<double, 4> low{INFINITY, INFINITY, INFINITY, INFINITY}, high{-INFINITY, -INFINITY, -INFINITY, -INFINITY};
  auto deviator = [&](const LineContactStress& s) {
    const double p = s.hydrostatic();
    return std::array<double, 4>{s.xx - p, s.yy - p, s.zz - p, s.xz};
  };
  const double step = 2 * pass_half_length / (pass_points - 1);
  for (int i = 0; i < pass_points; ++i)
  {
    const auto d = deviator(line_contact_subsurface_stress(-pass_half_length + i * step, z, nu));
    for (int k = 0; k < 4; ++k)
      low[k] = std::min(low[k], d[k]), high[k] = std::max(high[k], d[k]);
  }
  std::array<double, 4> centre{};
  for (int k = 0; k < 4; ++k)
    centre[k] = (low[k] + high[k]) / 2;
  auto equivalent = [&](double x) {
    const LineContactStress s = line_contact_subsurface_stress(x, z, nu);
    const auto d = deviator(s);
    const double xx = d[0] - centre[0], yy = d[1] - centre[1], zz = d[2] - centre[2], xz = d[3] - centre[3];
    const double mid = (xx + zz) / 2, radius = std::hypot((xx - zz) / 2, xz);
    const double top = std::max(mid + radius, yy), bottom = std::min(mid - radius, yy);
    return (top - bottom) / 2 + alpha * s.hydrostatic();
  };
  const auto [x, value] = scan_maximum(equivalent, -pass_half_length, pass_half_length, pass_points);
  return {value, x};
}
} // namespace

PassStress pass_stress(FatigueCriterion criterion, double z, double nu, double alpha)
{
  if (!(z > 0))
    throw InputError(fmt::format("pass stress: the depth z / b must be positive, got {}", z));
  switch (criterion)
  {
  case FatigueCriterion::orthogonal_shear: {
    // tau_xz is odd in x: its amplitude is its largest magnitude over x >= 0.
    const auto [x, value] = scan_maximum(
        [&](double x) { return std::abs(line_contact_subsurface_stress(x, z, nu).xz); }, 0, pass_half_length,
        pass_points);
    return {value, x};
  }
  case FatigueCriterion::largest_shear: {
    const auto [x, value] = scan_maximum(
        [&](double x) { return line_contact_subsurface_stress(x, z, nu).in_plane_shear(); }, -pass_half_length,
        pass_half_length, pass_points);
    return {value, x};
  }
  case FatigueCriterion::dang_van: return dang_van(z, nu, alpha);
  }
  throw InputError("pass stress: unknown criterion");
}

DepthExtremum largest_over_depth(FatigueCriterion criterion, double nu, double alpha)
{
  auto value = [&](double z) { return pass_stress(criterion, z, nu, alpha).value_over_p0; };
  const auto [z, v] = scan_maximum(value, 3.0 / 400, 3, 400);
  return {v, z, pass_stress(criterion, z, nu, alpha).x_over_b};
}
} // namespace rollcheck::contact
