#include "fem/contact_measures.h"
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
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

DepthMaximum maximum_along_axis(std::vector<AxisNode> nodes, double axis_tolerance)
{
  std::vector<AxisNode> axis;
  for (const AxisNode& node : nodes)
    if (node.s <= axis_tolerance)
      axis.push_back(node);
  if (axis.empty())
    return {0, 0};
  std::sort(axis.begin(), axis.end(), [](const auto& a, const auto& b) { return a.depth < b.depth; });
  std::size_t k = 0;
  for (std::size_t i = 1; i < axis.size(); ++i)
    if (axis[i].value > axis[k].value)
      k = i;
  if (k == 0 || k + 1 == axis.size())
    return {axis[k].value, axis[k].depth};
  // The depth band: axis nodes around the largest one within 3 % of it, at
  // least its two neighbours.
  constexpr double band = 0.03;
  std::size_t first = k - 1, last = k + 1;
  while (first > 0 && axis[first - 1].value >= (1 - band) * axis[k].value)
    --first;
  while (last + 1 < axis.size() && axis[last + 1].value >= (1 - band) * axis[k].value)
    ++last;
  const double z_k = axis[k].depth, z_lo = axis[first].depth, z_hi = axis[last].depth;
  const double w = std::max(z_hi - z_k, z_k - z_lo);

  // Least squares over every node of the band: f = sum_j c_j t^j + d (s/w)^2
  // with t = (z - z_k) / w; the s^2 term carries the even variation off the
  // axis. Cubic in t from eight nodes on (it absorbs the skew of the
  // profile), quadratic below.
  std::vector<const AxisNode*> data;
  for (const AxisNode& node : nodes)
    if (node.depth >= z_lo && node.depth <= z_hi)
      data.push_back(&node);
  const bool off_axis = std::any_of(data.begin(), data.end(), [&](auto n) { return n->s > axis_tolerance; });
  const int order = data.size() >= 8 ? 3 : 2;
  const int columns = order + 1 + (off_axis ? 1 : 0);
  Eigen::MatrixXd basis(data.size(), columns);
  Eigen::VectorXd values(data.size());
  for (std::size_t i = 0; i < data.size(); ++i)
  {
    const double t = (data[i]->depth - z_k) / w;
    for (int j = 0; j <= order; ++j)
      basis(i, j) = std::pow(t, j);
    if (off_axis)
      basis(i, order + 1) = std::pow(data[i]->s / w, 2);
    values[i] = data[i]->value;
  }
  const Eigen::VectorXd c = basis.colPivHouseholderQr().solve(values);
  const double c3 = order == 3 ? c[3] : 0.0;
  auto f = [&](double t) { return c[0] + t * (c[1] + t * (c[2] + t * c3)); };
  // Stationary points: roots of c1 + 2 c2 t + 3 c3 t^2; the maximum nearest
  // to the largest node, inside the band.
  std::vector<double> roots;
  if (std::abs(3 * c3) <= 1e-12 * std::abs(c[2]))
    roots.push_back(-c[1] / (2 * c[2]));
  else if (const double d = 4 * c[2] * c[2] - 12 * c3 * c[1]; d >= 0)
    for (double sign : {-1.0, 1.0})
      roots.push_back((-2 * c[2] + sign * std::sqrt(d)) / (6 * c3));
  DepthMaximum best{axis[k].value, z_k};
  double nearest = std::numeric_limits<double>::infinity();
  for (double t : roots)
    if (t >= (z_lo - z_k) / w && t <= (z_hi - z_k) / w && 2 * c[2] + 6 * c3 * t < 0 && std::abs(t) < nearest)
    {
      nearest = std::abs(t);
      best = {f(t), z_k + t * w};
    }
  return best;
}
} // namespace rollcheck::fem
