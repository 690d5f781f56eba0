// The rings of a structured contact cap (fem/mesh/cap_rings.h).
#include "fem/mesh/cap_rings.h"
#include "core/error.h"
#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <functional>
#include <numbers>
#include <numeric>

namespace rollcheck::fem
{
namespace
{
/// Rings from `from` to `to` (either direction), the gaps h(s) stepped from
/// `from` and scaled to end exactly at `to` (cap_rings.h); `from` excluded.
std::vector<double> rings_towards(double from, double to, const std::function<double(double)>& spacing)
{
  const double length = std::abs(to - from), direction = to > from ? 1.0 : -1.0;
  std::vector<double> gaps;
  double covered = 0;
  while (covered < length)
  {
    gaps.push_back(spacing(from + direction * covered));
    covered += gaps.back();
  }
  if (gaps.size() > 1 && covered - length > 0.5 * gaps.back())
  {
    covered -= gaps.back();
    gaps.pop_back();
  }
  std::vector<double> rings;
  double distance = 0;
  for (double gap : gaps)
  {
    distance += gap * length / covered;
    rings.push_back(from + direction * distance);
  }
  rings.back() = to;
  return rings;
}
} // namespace

CapRings cap_rings(const CapRingDesign& d)
{
  for (double size : {d.edge_radius_m, d.edge_spacing_m, d.pole_spacing_m, d.pole_radius_m, d.far_spacing_m,
                      d.edge_segment_m, d.cap_radius_m, d.growth})
    if (!std::isfinite(size) || size <= 0)
      throw InputError(fmt::format("contact cap rings: every size must be positive and finite, got {}", size));
  const double c = d.edge_radius_m, h_e = d.edge_spacing_m;
  if (h_e > d.far_spacing_m || d.pole_spacing_m > d.far_spacing_m)
    throw InputError(fmt::format("contact cap rings: the edge and pole spacings ({:.3g}, {:.3g} m) must not exceed "
                                 "the largest one ({:.3g} m)",
                                 h_e, d.pole_spacing_m, d.far_spacing_m));
  if (c + h_e / 2 >= d.cap_radius_m || h_e / 2 >= c)
    throw InputError(fmt::format("contact cap rings: the edge {:.3g} m +- {:.3g} m must lie inside the cap "
                                 "(radius {:.3g} m)",
                                 c, h_e / 2, d.cap_radius_m));
  const auto spacing = [&](double s) {
    return std::min({d.far_spacing_m, h_e + d.growth * std::abs(s - c),
                     d.pole_spacing_m + d.growth * std::max(0.0, s - d.pole_radius_m)});
  };
  CapRings rings;
  std::vector<double> inner = rings_towards(c - h_e / 2, 0, spacing);
  inner.pop_back(); // the pole, added first
  rings.radius_m = {0.0};
  rings.radius_m.insert(rings.radius_m.end(), inner.rbegin(), inner.rend());
  rings.radius_m.push_back(c - h_e / 2);
  rings.radius_m.push_back(c + h_e / 2);
  for (double s : rings_towards(c + h_e / 2, d.cap_radius_m, spacing))
    rings.radius_m.push_back(s);
  const std::vector<double>& s = rings.radius_m;
  const std::size_t n = s.size();
  rings.segments.assign(n, 0);
  const long edge_segments = std::max(1L, std::lround(std::numbers::pi / 2 * c / d.edge_segment_m));
  for (std::size_t j = 1; j < n; ++j)
  {
    const double gap = j + 1 < n ? 0.5 * (s[j + 1] - s[j - 1]) : s[j] - s[j - 1];
    rings.segments[j]
        = static_cast<int>(std::max(1L, std::min(edge_segments, std::lround(std::numbers::pi / 2 * s[j] / gap))));
  }
  return rings;
}
} // namespace rollcheck::fem
