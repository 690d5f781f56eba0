#pragma once
// A quantity solved at successively finer levels of one discretisation
// (element or cell size h_0 > h_1 > ...), and what the levels say of it:
//
//   relative change of the last level   c = g(v_{n-1}, v_n), by default
//                                        v_n / v_{n-1} - 1
//   converged                            n >= 2 and |c| < tolerance
//   fitted exponent                      the least-squares slope of ln|v| on
//                                        ln h over every level, the power of a
//                                        singular quantity v ~ h^lambda
//
// Every per-level solver keeps its levels in one of these and passes its own
// change g where its quantity needs one (a ratio against the interior, a
// peak scaled by the larger of itself and 1), so that its verdicts are its
// own while the bookkeeping is shared.
#include <functional>
#include <vector>

namespace rollcheck
{
struct RefinementSeries
{
  std::vector<double> element_size_m; ///< h of each level, coarsest first
  std::vector<double> value;          ///< the quantity at each level

  void add(double element_size, double quantity)
  {
    element_size_m.push_back(element_size);
    value.push_back(quantity);
  }
  std::size_t size() const { return value.size(); }
};

/// g(before, last) of two successive levels.
using LevelChange = std::function<double(double before, double last)>;

/// last / before - 1.
double relative_change(double before, double last);

/// g of the last two levels (relative_change by default); NaN with fewer than two.
double last_change(const RefinementSeries& series, const LevelChange& change = relative_change);

/// At least two levels and |last_change| < tolerance.
bool converged(const RefinementSeries& series, double tolerance, const LevelChange& change = relative_change);

/// Least-squares slope of ln|v| on ln h over every level; NaN with fewer than
/// two levels or a zero value.
double fitted_exponent(const RefinementSeries& series);
} // namespace rollcheck
