#pragma once
// A body's lower surface h(x, y) finished with edge radius r_e, on a
// half-space contact grid (contact/half_space_contact.h): h sampled over the
// grid and a margin of
//   m = ceil(0.6 r_e / cell)   cells on every side
// (the reach of the rolling ball that rounds the grid's own cells), opened
// by a ball of r_e rolled inside the body (geometry/rolling_ball_opening.h,
// small slopes), and read back on the grid's cells. The margin's surface is
// taken as the body's: no ball is centred beyond it.
#include "contact/half_space_contact.h"
#include <cstddef>
#include <functional>
#include <vector>

namespace rollcheck::contact
{
/// The rounded surface over a grid and its margin; (i, j) are the grid's cells.
struct BallRoundedSurface
{
  std::vector<double> values;     ///< over the grid and its margin
  std::size_t margin = 0, ny = 0; ///< of the opened grid: the margin in cells and its width across
  double operator()(std::size_t i, std::size_t j) const { return values[(i + margin) * ny + j + margin]; }
};

/// m: the cells beyond a grid whose surface the rounding needs.
std::size_t rounding_margin(double edge_radius_m, double cell_m);

/// `height` (m, at x and y of the grid's frame) rounded by a ball of
/// `edge_radius_m`, on `grid`'s square cells. ComputationError naming the
/// point where `height` is not finite (a point outside the body's outline).
BallRoundedSurface ball_rounded_surface(const std::function<double(double, double)>& height, const HalfSpaceGrid& grid,
                                        double edge_radius_m);

/// The largest slope |grad g| of the rounded surface over the grid's loaded
/// cells (pressure > 0) away from its border, by central differences: what
/// half-space theory needs small.
double largest_loaded_slope(const BallRoundedSurface& surface, const HalfSpaceGrid& grid,
                            const std::vector<double>& pressure_pa);
} // namespace rollcheck::contact
