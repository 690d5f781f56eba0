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

std::size_t own_stride(int stride, std::size_t n)
{
  return n >= 3 ? static_cast<std::size_t>(stride) : 1;
}
} // namespace rollcheck::study::rims
