#pragma once
// The lower surface z = h(x, y) of a body (the body above it) rounded by a
// ball of radius r rolled inside the body: the surface of the union of every
// ball of radius r within it, so that no radius of curvature is below r (the
// way a part's edges are finished). In the small-slope approximation of
// half-space contact the ball's bottom is the paraboloid |u - a|^2 / (2 r),
// and the rounded surface is the morphological opening of h by that
// quadratic structuring function (R. van den Boomgaard, "The morphological
// equivalent of the Gauss convolution", Nieuw Archief voor Wiskunde 10,
// 1992; R. van den Boomgaard and A. Smeulders, IEEE PAMI 16, 1994):
//   erosion  e(a) = max over u of [h(u) - |u - a|^2 / (2 r)]   (the ball's lowest centre height - r)
//   opening  g(u) = min over a of [e(a) + |u - a|^2 / (2 r)]   (the lowest ball over u)
// Both split into passes along x and along y, since |u - a|^2 does. g >= h,
// g = h wherever h's curvature radii are all >= r; a crease z = k |y| is
// replaced by k^2 r / 2 + y^2 / (2 r) for |y| <= k r. The grid is taken as
// the whole body's surface: a ball is never centred beyond it.
#include <cstddef>
#include <span>
#include <vector>

namespace rollcheck::geometry
{
/// Values at i * ny + j over x = x0 + i dx, y = y0 + j dy (m); `radius_m` > 0.
std::vector<double> rolling_ball_opening(std::span<const double> height_m, std::size_t nx, std::size_t ny,
                                         double cell_x_m, double cell_y_m, double radius_m);
} // namespace rollcheck::geometry
