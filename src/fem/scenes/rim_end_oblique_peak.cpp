// The end peak of an oblique rounded edge (fem/scenes/rim_end_oblique_peak.h).
#include "fem/scenes/rim_end_oblique_peak.h"
#include "core/error.h"
#include "fem/mesh/oblique_end_angle.h"
#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <vector>

namespace rollcheck::fem
{
ObliqueEndPeak oblique_end_peak(std::span<const SurfacePressureNode> nodes, double half_width_m, double edge_radius_m,
                                double fillet_start_m, double boundary_layer_m, double crossing_angle_rad)
{
  const double b = half_width_m;
  const double normal_window = std::min(b / 4, boundary_layer_m / 2), along_window = b / 8;
  const double from = -(2 * b + std::max(edge_radius_m, fillet_start_m)), to = edge_radius_m;
  // Each node near the edge in the edge's frame: x' along its normal, s along it.
  struct Near
  {
    double normal_m, across_m, along_m, pressure_pa;
    const SurfacePressureNode* node;
  };
  std::vector<Near> near;
  const double c = crossing_angle_rad;
  for (const SurfacePressureNode& n : nodes)
  {
    double normal_m = 0, across_m = 0;
    oblique_edge_frame(c, n.x[0], n.x[1], normal_m, across_m);
    // The windows reach w beyond the zone, so that its border nodes are read as its inner ones.
    if (normal_m > from - normal_window && normal_m <= to + normal_window && across_m <= 1.5 * b + along_window)
      near.push_back({normal_m, across_m, n.x[0] * std::cos(c) + n.x[1] * std::sin(c), n.pressure_pa, &n});
  }
  std::sort(near.begin(), near.end(), [](const Near& a, const Near& d) { return a.along_m < d.along_m; });
  ObliqueEndPeak peak;
  std::size_t first = 0;
  for (const Near& centre : near)
  {
    while (near[first].along_m < centre.along_m - along_window)
      ++first;
    if (!(centre.normal_m > from && centre.normal_m <= to && centre.across_m <= 1.5 * b))
      continue;
    double sum = 0;
    int count = 0;
    for (std::size_t k = first; k < near.size() && near[k].along_m <= centre.along_m + along_window; ++k)
      if (std::abs(near[k].normal_m - centre.normal_m) <= normal_window)
      {
        sum += near[k].pressure_pa;
        ++count;
      }
    if (sum / count > peak.pressure_pa)
      peak = {sum / count, centre.node->x[0], centre.node->x[1]};
  }
  if (!(peak.pressure_pa > 0))
    throw ComputationError(fmt::format("rim: no pressure near the oblique rounded edge (b = {:.3g} m)", b));
  return peak;
}

void read_oblique_end_peak(const RimEndStudy& study, std::span<const SurfacePressureNode> nodes, RimEndLevel& level)
{
  const RimEndSettings& s = study.setup;
  const ObliqueEndPeak peak = oblique_end_peak(nodes, study.half_width_m, s.edge_radius_m, study.fillet_start_m,
                                               study.boundary_layer_m, s.crossing_angle_rad);
  level.end_peak_pa = peak.pressure_pa;
  level.end_peak_x_m = peak.x_m;
  level.end_peak_y_m = peak.y_m;
}
} // namespace rollcheck::fem
