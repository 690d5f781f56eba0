#include "contact/rounded_end_level.h"
#include <algorithm>
#include <cmath>

namespace rollcheck::contact
{
Eigen::Vector2d load_over(const std::vector<double>& pressure, const HalfSpaceGrid& grid, double from, double to)
{
  Eigen::Vector2d sum = Eigen::Vector2d::Zero();
  const double area = grid.cell_area_m2();
  for (std::size_t i = 0; i < grid.nx; ++i)
    if (const double x = grid.x(i); x >= from && x <= to)
      for (std::size_t j = 0; j < grid.ny; ++j)
        sum += pressure[i * grid.ny + j] * area * Eigen::Vector2d(1.0, x);
  return sum;
}

void read_level(RoundedEndLevel& level, const std::vector<double>& pressure, const HalfSpaceGrid& grid)
{
  const std::size_t nx = grid.nx, ny = grid.ny;
  const auto peak = std::ranges::max_element(pressure);
  const auto k_peak = static_cast<std::size_t>(peak - pressure.begin());
  level.peak_pressure_pa = *peak;
  level.peak_along_m = grid.x(k_peak / ny);
  level.peak_across_m = grid.y(k_peak % ny);
  level.contact_start_m = grid.x(nx - 1);
  for (std::size_t i = 0; i < nx; ++i)
  {
    double column_peak = 0, column_load = 0;
    for (std::size_t j = 0; j < ny; ++j)
    {
      const double p = pressure[i * ny + j];
      column_peak = std::max(column_peak, p);
      column_load += p * grid.cell_y_m;
      if (p > 0)
        level.contact_start_m = std::min(level.contact_start_m, grid.x(i));
    }
    level.station_m.push_back(grid.x(i));
    level.station_peak_pa.push_back(column_peak);
    level.station_load_n_per_m.push_back(column_load);
  }
}

std::size_t cells_over(double length, double cell) { return static_cast<std::size_t>(std::ceil(length / cell)); }

std::size_t half_across_cells(const RoundedEndSettings& s, const RoundedEndProblem& end, const LevelScale& scale,
                              double from, double cell)
{
  double widest = s.across_over_half_width * scale.half_width_m;
  for (double x = from; x < end.load.length_m; x += cell)
    widest = std::max(widest, 1.6 * line_contact(end.load.at(x), end.sheet_radius(x), scale.effective_modulus_pa,
                                                 s.poisson_ratio).half_width_m);
  return cells_over(scale.across_scale * widest, cell);
}
} // namespace rollcheck::contact
