// The rings of a structured contact cap (fem/mesh/cap_rings.h).
#include "fem/mesh/cap_rings.h"
#include "core/error.h"
#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <numbers>

namespace rollcheck::fem
{
namespace
{
/// 2^round(log2(x)), x > 0.
int nearest_power_of_two(double x)
{
  return 1 << std::max(0, static_cast<int>(std::lround(std::log2(x))));
}
} // namespace

CapRings cap_rings(const CapRingDesign& d)
{
  for (double size : {d.edge_radius_m, d.spacing_m, d.far_spacing_m, d.edge_segment_m, d.cap_radius_m, d.growth})
    if (!std::isfinite(size) || size <= 0)
      throw InputError(fmt::format("contact cap rings: every size must be positive and finite, got {}", size));
  const double c = d.edge_radius_m;
  if (d.spacing_m > d.far_spacing_m)
    throw InputError(fmt::format("contact cap rings: the spacing {:.3g} m must not exceed the largest one {:.3g} m",
                                 d.spacing_m, d.far_spacing_m));
  if (c + d.spacing_m >= d.cap_radius_m)
    throw InputError(fmt::format("contact cap rings: the edge {:.3g} m and a spacing {:.3g} m beyond it must lie "
                                 "inside the cap (radius {:.3g} m)",
                                 c, d.spacing_m, d.cap_radius_m));
  const int K = std::max(1, static_cast<int>(std::ceil(c / d.spacing_m - 0.5)));
  const double h = c / (K + 0.5);
  CapRings rings;
  for (int k = 0; k <= K; ++k)
    rings.radius_m.push_back(k * h);
  // Beyond the edge: gaps growing from h, scaled to end at s_cap.
  const double from = c + h / 2, length = d.cap_radius_m - from;
  std::vector<double> gaps;
  double covered = 0;
  while (covered < length)
  {
    gaps.push_back(std::min(d.far_spacing_m, h + d.growth * covered));
    covered += gaps.back();
  }
  if (gaps.size() > 1 && covered - length > 0.5 * gaps.back())
  {
    covered -= gaps.back();
    gaps.pop_back();
  }
  rings.radius_m.push_back(from);
  double distance = 0;
  for (double gap : gaps)
  {
    distance += gap * length / covered;
    rings.radius_m.push_back(from + distance);
  }
  rings.radius_m.back() = d.cap_radius_m;
  const int edge_segments = nearest_power_of_two(std::numbers::pi / 2 * c / d.edge_segment_m);
  rings.segments.push_back(0);
  rings.angles_rad.push_back({0.0});
  bool staggered = false;
  for (std::size_t j = 1; j < rings.radius_m.size(); ++j)
  {
    const int m = std::min(edge_segments, nearest_power_of_two(std::numbers::pi / 2 * rings.radius_m[j] / h));
    staggered = m == rings.segments.back() && !staggered;
    rings.segments.push_back(m);
    std::vector<double> angles;
    const double segment = std::numbers::pi / 2 / m;
    if (staggered)
    {
      angles.push_back(0.0);
      for (int k = 0; k < m; ++k)
        angles.push_back((k + 0.5) * segment);
    }
    else
      for (int k = 0; k < m; ++k)
        angles.push_back(k * segment);
    angles.push_back(std::numbers::pi / 2);
    rings.angles_rad.push_back(std::move(angles));
  }
  return rings;
}
} // namespace rollcheck::fem
