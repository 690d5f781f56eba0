// The tables' nodes and their interpolation (study/rims/table_nodes.h).
#include "study/rims/table_nodes.h"
#include <algorithm>
#include <cmath>

namespace rollcheck::study::rims
{
std::vector<double> even_nodes(double lo, double hi, double step)
{
  if (!(hi - lo > 1e-9))
    return {lo};
  // Less 1e-9: a range of exactly 2 k steps (30 deg at 15, in radians) has k halves, not k + 1.
  const int halves = std::max(1, static_cast<int>(std::ceil((hi - lo) / (2 * step) - 1e-9)));
  std::vector<double> nodes;
  for (int k = 0; k <= 2 * halves; ++k)
    nodes.push_back(lo + (hi - lo) * k / (2 * halves));
  return nodes;
}

double interpolate_held(const std::vector<std::pair<double, double>>& nodes, double x)
{
  if (nodes.size() == 1 || x <= nodes.front().first)
    return nodes.front().second;
  if (x >= nodes.back().first)
    return nodes.back().second;
  const auto right = std::upper_bound(nodes.begin(), nodes.end(), x,
                                      [](double a, const std::pair<double, double>& n) { return a < n.first; });
  const auto left = right - 1;
  const double t = (x - left->first) / (right->first - left->first);
  return (1 - t) * left->second + t * right->second;
}

std::vector<std::pair<std::size_t, double>> held_bracket(std::span<const double> positions, std::size_t step,
                                                         double x)
{
  if (positions.empty())
    return {};
  std::vector<std::size_t> taken;
  for (std::size_t k = 0; k < positions.size(); k += step)
    taken.push_back(k);
  if (taken.size() == 1 || x <= positions[taken.front()])
    return {{taken.front(), 1.0}};
  if (x >= positions[taken.back()])
    return {{taken.back(), 1.0}};
  const auto right = std::upper_bound(taken.begin(), taken.end(), x,
                                      [&](double a, std::size_t k) { return a < positions[k]; });
  const std::size_t r = *right, l = *(right - 1);
  const double t = (x - positions[l]) / (positions[r] - positions[l]);
  return {{l, 1 - t}, {r, t}};
}

std::size_t own_stride(int stride, std::size_t n)
{
  return n >= 3 ? static_cast<std::size_t>(stride) : 1;
}
} // namespace rollcheck::study::rims
