#include "geometry/rolling_ball_opening.h"
#include "core/error.h"
#include <algorithm>
#include <array>
#include <cmath>
#include <fmt/format.h>
#include <limits>

namespace rollcheck::geometry
{
namespace
{
/// One pass along a line of n values `stride` apart: out[a] = best over u of
/// (in[u] -+ (u - a)^2 h^2 / (2 r)), the max with `subtract` (erosion), the
/// min without (dilation).
void parabola_pass(const double* in, double* out, std::size_t n, std::size_t stride, double cell_m, double radius_m,
                   bool subtract)
{
  const double curvature = cell_m * cell_m / (2 * radius_m);
  const double sign = subtract ? -1.0 : 1.0;
  // Minimised: sign (in[u] + sign curvature d^2), d = u - a; a max for the erosion.
  const auto objective = [&](std::size_t u, std::size_t a) {
    const double d = static_cast<double>(u) - static_cast<double>(a);
    return sign * in[u * stride] + curvature * d * d;
  };
  for (std::size_t a = 0; a < n; ++a)
  {
    std::size_t best = 0;
    double value = objective(0, a);
    for (std::size_t u = 1; u < n; ++u)
      if (const double f = objective(u, a); f < value)
      {
        best = u;
        value = f;
      }
    // The optimum lies between samples. Where the objective is smooth about
    // the best sample (equal second differences), it is the vertex of the
    // parabola through the best sample and its neighbours (error O(h^3)).
    // Where it has a kink beside the best sample (the dilation meets the
    // erosion's crease between samples; a slope jump far above the sides'
    // curvature), it is where the parabolas through three samples on either
    // side meet, or a side's own vertex (error O(h^3) instead of O(h)).
    const auto bend_at = [&](std::size_t u) {
      return objective(u - 1, a) - 2 * objective(u, a) + objective(u + 1, a);
    };
    if (best > 1 && best + 2 < n)
    {
      const double bend = bend_at(best);
      const double left = objective(best - 1, a), right = objective(best + 1, a);
      if (bend > 0 && std::abs(bend_at(best - 1) - bend) < 0.25 * bend && std::abs(bend_at(best + 1) - bend) < 0.25 * bend)
        value -= (right - left) * (right - left) / (8 * bend);
    }
    for (const std::size_t kink : {best - 1, best}) // a kink between samples `kink` and `kink + 1`
    {
      if (best < 1 || kink < 2 || kink + 3 >= n)
        continue;
      // t in cells from sample `kink`: left side on t = -2, -1, 0, right on 1, 2, 3.
      const double l0 = objective(kink, a), l_slope = (objective(kink, a) - objective(kink - 2, a)) / 2;
      const double l_bend = bend_at(kink - 1);
      const double r0 = objective(kink + 2, a), r_slope = (objective(kink + 3, a) - objective(kink + 1, a)) / 2;
      const double r_bend = bend_at(kink + 2);
      const auto left_side = [&](double t) { return l0 + (l_slope + l_bend) * t + l_bend / 2 * t * t; };
      const auto right_side = [&](double t) {
        const double d = t - 2;
        return r0 + r_slope * d + r_bend / 2 * d * d;
      };
      const double jump = (r_slope - 1.5 * r_bend) - (l_slope + 1.5 * l_bend); // the sides' slopes at t = 1/2
      if (!(jump > 8 * std::max({std::abs(l_bend), std::abs(r_bend), 1e-300})))
        continue;
      // left_side - right_side = A t^2 + B t + C on [0, 1].
      const double A = (l_bend - r_bend) / 2, B = (l_slope + l_bend) - (r_slope - 2 * r_bend);
      const double C = l0 - (r0 - 2 * r_slope + 2 * r_bend);
      // NaN marks no root: it fails the interval test below.
      std::array<double, 2> roots{std::nan(""), std::nan("")};
      if (std::abs(A) < 1e-14 * (std::abs(B) + std::abs(C)))
        roots[0] = -C / B;
      else if (const double disc = B * B - 4 * A * C; disc >= 0)
        roots = {(-B - std::sqrt(disc)) / (2 * A), (-B + std::sqrt(disc)) / (2 * A)};
      for (const double t : roots)
        if (t >= 0 && t <= 1)
        {
          value = std::min(value, left_side(t));
          // A side's own minimum on its side of the kink.
          if (l_bend > 0)
            if (const double v = -(l_slope + l_bend) / l_bend; v > -1 && v < t)
              value = std::min(value, left_side(v));
          if (r_bend > 0)
            if (const double v = 2 - r_slope / r_bend; v > t && v < 2)
              value = std::min(value, right_side(v));
        }
    }
    out[a * stride] = sign * value;
  }
}

std::vector<double> separable_pass(std::span<const double> field, std::size_t nx, std::size_t ny, double cell_x_m,
                                   double cell_y_m, double radius_m, bool subtract)
{
  std::vector<double> along_y(field.size()), result(field.size());
  for (std::size_t i = 0; i < nx; ++i)
    parabola_pass(field.data() + i * ny, along_y.data() + i * ny, ny, 1, cell_y_m, radius_m, subtract);
  for (std::size_t j = 0; j < ny; ++j)
    parabola_pass(along_y.data() + j, result.data() + j, nx, ny, cell_x_m, radius_m, subtract);
  return result;
}
} // namespace

std::vector<double> rolling_ball_opening(std::span<const double> height_m, std::size_t nx, std::size_t ny,
                                         double cell_x_m, double cell_y_m, double radius_m)
{
  if (height_m.size() != nx * ny || nx == 0 || ny == 0)
    throw InputError(fmt::format("rolling-ball opening: {} heights for a grid of {} x {}", height_m.size(), nx, ny));
  if (!(radius_m > 0) || !std::isfinite(radius_m) || !(cell_x_m > 0) || !(cell_y_m > 0))
    throw InputError(fmt::format("rolling-ball opening: the ball's radius ({} m) and the cells ({} x {} m) must be "
                                 "positive",
                                 radius_m, cell_x_m, cell_y_m));
  if (std::ranges::any_of(height_m, [](double z) { return !std::isfinite(z); }))
    throw InputError("rolling-ball opening: a height is not finite");
  const std::vector<double> eroded = separable_pass(height_m, nx, ny, cell_x_m, cell_y_m, radius_m, true);
  return separable_pass(eroded, nx, ny, cell_x_m, cell_y_m, radius_m, false);
}
} // namespace rollcheck::geometry
