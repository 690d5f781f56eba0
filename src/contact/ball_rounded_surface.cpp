#include "contact/ball_rounded_surface.h"
#include "core/error.h"
#include "geometry/rolling_ball_opening.h"
#include <algorithm>
#include <cmath>
#include <fmt/format.h>

namespace rollcheck::contact
{
std::size_t rounding_margin(double edge_radius_m, double cell_m)
{
  return static_cast<std::size_t>(std::ceil(0.6 * edge_radius_m / cell_m));
}

BallRoundedSurface ball_rounded_surface(const std::function<double(double, double)>& height, const HalfSpaceGrid& grid,
                                        double edge_radius_m)
{
  const double cell = grid.cell_x_m;
  BallRoundedSurface r;
  r.margin = rounding_margin(edge_radius_m, cell);
  const std::size_t nx = grid.nx + 2 * r.margin;
  r.ny = grid.ny + 2 * r.margin;
  std::vector<double> hull(nx * r.ny);
  const double shift = static_cast<double>(r.margin);
  for (std::size_t i = 0; i < nx; ++i)
    for (std::size_t j = 0; j < r.ny; ++j)
    {
      const double along = grid.first_x_m + (static_cast<double>(i) - shift) * cell;
      const double across = grid.first_y_m + (static_cast<double>(j) - shift) * cell;
      const double z = height(along, across);
      if (!std::isfinite(z))
        throw ComputationError(fmt::format("flat rim: the hull's surface was not found over the window (search "
                                           "range) at x' = {:.4g} m along the ruling, y = {:.4g} m across",
                                           along, across));
      hull[i * r.ny + j] = z;
    }
  r.values = geometry::rolling_ball_opening(hull, nx, r.ny, cell, cell, edge_radius_m);
  return r;
}

double largest_loaded_slope(const BallRoundedSurface& surface, const HalfSpaceGrid& grid,
                            const std::vector<double>& pressure_pa)
{
  const std::size_t nx = grid.nx, ny = grid.ny;
  const double cell = grid.cell_x_m; // square cells
  double largest = 0;
  for (std::size_t i = 1; i + 1 < nx; ++i)
    for (std::size_t j = 1; j + 1 < ny; ++j)
      if (pressure_pa[i * ny + j] > 0)
        largest = std::max(largest, std::hypot(surface(i + 1, j) - surface(i - 1, j),
                                               surface(i, j + 1) - surface(i, j - 1))
                                        / (2 * cell));
  return largest;
}
} // namespace rollcheck::contact
