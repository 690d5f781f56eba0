// The half-space boundary-element contact (contact/half_space_contact.h)
// against Boussinesq's point load and Hertz's sphere (contact/hertz.h).
#include "contact/half_space_contact.h"
#include "contact/hertz.h"
#include "core/error.h"
#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <numbers>

using namespace rollcheck;

namespace
{
constexpr double effective_modulus = 1.1e11; // steel on steel, E / (2 (1 - nu^2))

contact::HalfSpaceGrid square_grid(std::size_t cells, double half_side)
{
  const double cell = 2 * half_side / static_cast<double>(cells);
  return {cells, cells, cell, cell, -half_side + cell / 2, -half_side + cell / 2};
}

/// f(r) at every cell's centre, r its distance from the grid's centre.
template <class Radial>
std::vector<double> radial_field(const contact::HalfSpaceGrid& grid, Radial f)
{
  std::vector<double> values(grid.size());
  for (std::size_t i = 0; i < grid.nx; ++i)
    for (std::size_t j = 0; j < grid.ny; ++j)
      values[i * grid.ny + j] = f(std::hypot(grid.x(i), grid.y(j)));
  return values;
}
} // namespace

TEST(HalfSpaceContact, CellDeflectionIsBoussinesqFarAwayAndLoveAtTheCentre)
{
  // Far away a cell is a point force p A: u = p A / (pi E* r).
  const double a = 1e-6, c = 2e-6, r = 1e-4;
  EXPECT_NEAR(contact::cell_deflection(a, c, r, 0.3 * r, effective_modulus)
                  / (4 * a * c / (std::numbers::pi * effective_modulus * std::hypot(r, 0.3 * r))),
              1.0, 1e-4);
  // At the centre of a square of side 2a (Johnson eq. 3.25 there):
  // u = (4 a / (pi E*)) ln(1 + sqrt 2) x 2.
  EXPECT_NEAR(contact::cell_deflection(a, a, 0, 0, effective_modulus),
              8 * a * std::log(1 + std::sqrt(2.0)) / (std::numbers::pi * effective_modulus), 1e-20);
}

TEST(HalfSpaceContact, FftDeflectionIsTheDirectSumOfEveryCellsDeflection)
{
  // The padded real FFT convolution against the sum over cells, term by
  // term, on grids padded to an odd and an even size along x (y's is a
  // multiple of 4: 13 x 7 pads to 27 x 16, 8 x 37 to 16 x 80), under an
  // uneven pressure that is zero on some cells.
  for (const auto& [nx, ny] : {std::pair<std::size_t, std::size_t>{13, 7}, {8, 37}, {1, 1}})
  {
    const contact::HalfSpaceGrid grid{nx, ny, 2e-6, 3e-6, -1e-5, 4e-6};
    std::vector<double> pressure(grid.size());
    for (std::size_t k = 0; k < pressure.size(); ++k)
      pressure[k] = k % 5 == 3 ? 0.0 : 1e8 * (1.0 + std::sin(0.7 * static_cast<double>(k)));
    const std::vector<double> u = contact::HalfSpaceDeflection(grid, effective_modulus)(pressure);
    ASSERT_EQ(u.size(), grid.size());
    double worst = 0, largest = 0;
    for (std::size_t i = 0; i < nx; ++i)
      for (std::size_t j = 0; j < ny; ++j)
      {
        double direct = 0;
        for (std::size_t k = 0; k < nx; ++k)
          for (std::size_t l = 0; l < ny; ++l)
            direct += pressure[k * ny + l]
                      * contact::cell_deflection(grid.cell_x_m / 2, grid.cell_y_m / 2, grid.x(i) - grid.x(k),
                                                 grid.y(j) - grid.y(l), effective_modulus);
        worst = std::max(worst, std::abs(u[i * ny + j] - direct));
        largest = std::max(largest, std::abs(direct));
      }
    EXPECT_LT(worst, 1e-12 * largest) << nx << " x " << ny;
  }
}

TEST(HalfSpaceContact, HertzPressureDeflectsTheSurfaceByTheSpheresProfile)
{
  // Hertz's pressure p0 sqrt(1 - r^2 / a^2) deflects the surface by
  // delta - r^2 / (2 R) inside the contact (Johnson eq. 3.41): the FFT
  // convolution checked without the contact solver.
  const double radius = 0.01, force = 100;
  const contact::PointHertz hertz = contact::point_contact(force, radius, effective_modulus, 0.3);
  const double a = hertz.contact_radius_m;
  const contact::HalfSpaceGrid grid = square_grid(128, 1.5 * a);
  const std::vector<double> pressure = radial_field(
      grid, [&](double r) { return contact::pressure_profile(hertz.peak_pressure_pa, a, r); });
  const contact::HalfSpaceDeflection deflection(grid, effective_modulus);
  const std::vector<double> u = deflection(pressure);
  double worst = 0;
  for (std::size_t i = 0; i < grid.nx; ++i)
    for (std::size_t j = 0; j < grid.ny; ++j)
    {
      const double r = std::hypot(grid.x(i), grid.y(j));
      if (r < 0.8 * a)
        worst = std::max(worst, std::abs(u[i * grid.ny + j] - (hertz.approach_m - r * r / (2 * radius))));
    }
  // Piecewise-constant cells of a / 43: within 0.05 % of the approach.
  EXPECT_LT(worst / hertz.approach_m, 5e-4);
}

TEST(HalfSpaceContact, SphereOnAPlaneIsHertz)
{
  const double radius = 0.01, force = 100;
  const contact::PointHertz hertz = contact::point_contact(force, radius, effective_modulus, 0.3);
  const double a = hertz.contact_radius_m;
  // Cells of a / 32, the sphere's gap r^2 / (2 R) at their centres.
  const contact::HalfSpaceGrid grid = square_grid(96, 1.5 * a);
  const auto sphere = [&](double r) { return r * r / (2 * radius); };
  const std::vector<double> gap = radial_field(grid, sphere);
  const contact::HalfSpaceDeflection deflection(grid, effective_modulus);
  const contact::HalfSpaceContact solved = contact::solve_half_space_contact(deflection, gap, force);
  const double peak = *std::ranges::max_element(solved.pressure_pa);
  EXPECT_NEAR(peak / hertz.peak_pressure_pa, 1.0, 0.002);
  EXPECT_NEAR(solved.approach_m / hertz.approach_m, 1.0, 0.002);
  // Contact area pi a^2 within the cells along its rim (2 pi a h).
  const double loaded = static_cast<double>(std::ranges::count_if(solved.pressure_pa, [](double p) { return p > 0; }))
                        * grid.cell_area_m2();
  EXPECT_NEAR(loaded / (std::numbers::pi * a * a), 1.0, 2 * grid.cell_x_m / a);
  EXPECT_LE(solved.largest_gap_violation_m, 1e-6 * hertz.approach_m);
  // Halving the cells moves the peak by less than 1 %.
  const contact::HalfSpaceGrid coarse = square_grid(48, 1.5 * a);
  const contact::HalfSpaceContact coarse_solved = contact::solve_half_space_contact(
      contact::HalfSpaceDeflection(coarse, effective_modulus), radial_field(coarse, sphere), force);
  EXPECT_NEAR(*std::ranges::max_element(coarse_solved.pressure_pa) / peak, 1.0, 0.01);
}

TEST(HalfSpaceContact, RefusesAContactReachingTheBorderAndBadInput)
{
  const contact::HalfSpaceGrid grid = square_grid(16, 1e-4);
  const contact::HalfSpaceDeflection deflection(grid, effective_modulus);
  // A flat punch as wide as the grid: every cell loaded.
  const std::vector<double> flat(grid.size(), 0.0);
  EXPECT_THROW(contact::solve_half_space_contact(deflection, flat, 100), ComputationError);
  std::vector<double> bad(grid.size(), 0.0);
  bad[5] = std::nan("");
  EXPECT_THROW(contact::solve_half_space_contact(deflection, bad, 100), InputError);
  EXPECT_THROW(contact::solve_half_space_contact(deflection, flat, -1), InputError);
  EXPECT_THROW(contact::HalfSpaceDeflection(grid, -1), InputError);
}
