#include "contact/line_hertz_beyond.h"
#include "contact/hertz.h"

namespace rollcheck::contact
{
std::vector<double> LineHertzBeyond::deflection(const RulingLineLoad& load) const
{
  std::vector<double> prescribed(grid.size(), 0.0);
  const std::size_t ny = grid.ny;
  for (std::size_t i = first_column; i < grid.nx; ++i)
  {
    const double x = grid.x(i), q = load.at(x);
    if (q <= 0)
      continue;
    const LineHertz hertz = line_contact(q, sheet_radius(x), effective_modulus_pa, poisson_ratio);
    double column = 0;
    for (std::size_t j = 0; j < ny; ++j)
      column += prescribed[i * ny + j] = pressure_profile(hertz.peak_pressure_pa, hertz.half_width_m, grid.y(j));
    // Each column carries q exactly, whatever its cells resolve of b.
    if (column > 0)
      for (std::size_t j = 0; j < ny; ++j)
        prescribed[i * ny + j] *= q / (column * grid.cell_y_m);
  }
  return influence(prescribed);
}
} // namespace rollcheck::contact
