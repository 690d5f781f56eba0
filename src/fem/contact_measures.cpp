#include "fem/contact_measures.h"
#include <algorithm>
#include <cmath>
#include <set>

namespace rollcheck::fem
{
ProfileFit fit_hertz_profile(const std::vector<SurfaceNode>& nodes, double peak)
{
  // Linear least squares for y = A - B t with t = s^2, y = p^2.
  double n = 0, st = 0, sy = 0, stt = 0, sty = 0;
  std::set<double> radii;
  for (const SurfaceNode& node : nodes)
    if (node.pressure >= peak / 2)
    {
      const double t = node.s * node.s, y = node.pressure * node.pressure;
      n += 1;
      st += t;
      sy += y;
      stt += t * t;
      sty += t * y;
      radii.insert(node.s);
    }
  ProfileFit fit{0, 0, static_cast<int>(radii.size())};
  const double det = n * stt - st * st;
  if (radii.size() < 2 || !(det > 0))
  {
    fit.nodes_used = std::min(fit.nodes_used, 1);
    return fit;
  }
  const double slope = (n * sty - st * sy) / det; // = -B
  const double intercept = (sy - slope * st) / n; // = A
  if (!(intercept > 0) || !(slope < 0))
  {
    fit.nodes_used = std::min(fit.nodes_used, 1);
    return fit;
  }
  fit.peak_pressure_pa = std::sqrt(intercept);
  fit.contact_size_m = std::sqrt(-intercept / slope);
  fit.nodes_used = static_cast<int>(n);
  return fit;
}

double contact_edge(std::vector<SurfaceNode> nodes)
{
  std::sort(nodes.begin(), nodes.end(), [](const auto& a, const auto& b) { return a.s < b.s; });
  double edge = 0;
  for (std::size_t i = 0; i + 1 < nodes.size(); ++i)
  {
    const SurfaceNode &in = nodes[i], &out = nodes[i + 1];
    if (in.gap < 0 && out.gap >= 0)
      edge = in.s + (out.s - in.s) * (-in.gap) / (out.gap - in.gap);
  }
  if (!nodes.empty() && nodes.back().gap < 0)
    edge = nodes.back().s;
  return edge;
}

DepthMaximum maximum_along_axis(std::vector<AxisNode> nodes)
{
  if (nodes.empty())
    return {0, 0};
  std::sort(nodes.begin(), nodes.end(), [](const auto& a, const auto& b) { return a.depth < b.depth; });
  std::size_t k = 0;
  for (std::size_t i = 1; i < nodes.size(); ++i)
    if (nodes[i].value > nodes[k].value)
      k = i;
  if (k == 0 || k + 1 == nodes.size())
    return {nodes[k].value, nodes[k].depth};
  // Parabola through (z0, f0), (z1, f1), (z2, f2), vertex by Newton's divided differences.
  const double z0 = nodes[k - 1].depth, z1 = nodes[k].depth, z2 = nodes[k + 1].depth;
  const double f0 = nodes[k - 1].value, f1 = nodes[k].value, f2 = nodes[k + 1].value;
  const double d01 = (f1 - f0) / (z1 - z0), d12 = (f2 - f1) / (z2 - z1);
  const double curvature = (d12 - d01) / (z2 - z0);
  if (!(curvature < 0))
    return {f1, z1};
  // f(z) = f1 + d(z - z1) + curvature (z - z1)^2 with d the slope at z1.
  const double slope_at_z1 = d01 + curvature * (z1 - z0);
  const double dz = std::clamp(-slope_at_z1 / (2 * curvature), z0 - z1, z2 - z1);
  return {f1 + slope_at_z1 * dz + curvature * dz * dz, z1 + dz};
}
} // namespace rollcheck::fem
