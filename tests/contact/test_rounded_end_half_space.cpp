// The graded half-space contact (contact/graded_half_space_contact.h)
// against Hertz's sphere and its own unmirrored grid, and the rounded end
// on it (contact/rounded_end_half_space.h) against an independent
// computation: the numpy prototype scripts/studies/rounded_end_half_space.py
// (its table in docs/notes/rim-ends-tables.md, "A rounded end by half-space
// theory"), whose grids it builds cell for cell.
#include "contact/graded_half_space_contact.h"
#include "contact/rounded_end_half_space.h"
#include "core/error.h"
#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <numbers>

using namespace rollcheck;

namespace
{
/// Edges from `from` to `to` (both included), the first cell `first` long
/// at `from`, each next `growth` times longer up to `largest`.
std::vector<double> growing_edges(double from, double to, double first, double growth, double largest)
{
  std::vector<double> edges{from};
  for (double size = first; edges.back() < to - 1e-12; size = std::min(size * growth, largest))
    edges.push_back(std::min(edges.back() + size, to));
  return edges;
}

/// x edges over [-2a, 2a] finest at the centre, y edges over [0, 2a] finest at 0.
contact::GradedHalfSpaceGrid sphere_grid(double a)
{
  contact::GradedHalfSpaceGrid grid;
  const std::vector<double> half = growing_edges(a / 64, 2 * a, a / 64, 1.1, a / 16);
  for (auto x = half.rbegin(); x != half.rend(); ++x)
    grid.x_edges_m.push_back(-*x);
  grid.x_edges_m.insert(grid.x_edges_m.end(), half.begin(), half.end());
  grid.y_edges_m = growing_edges(0, 2 * a, a / 32, 1.05, a / 16);
  grid.mirror_y = true;
  return grid;
}
} // namespace

TEST(GradedHalfSpaceContact, HertzSphereOnAGradedGrid)
{
  // R = 10 mm, E* = 1.1e11 Pa, F = 100 N; half the sphere (y >= 0) and its image.
  const double radius = 0.01, modulus = 1.1e11, force = 100;
  const double a = std::cbrt(3 * force * radius / (4 * modulus));
  const double p0 = 3 * force / (2 * std::numbers::pi * a * a);
  const contact::GradedHalfSpaceGrid grid = sphere_grid(a);
  const std::size_t n = grid.size(), ny = grid.ny();
  std::vector<double> gap(n);
  std::vector<char> loaded(n);
  for (std::size_t c = 0; c < n; ++c)
  {
    const double r2 = grid.x(c / ny) * grid.x(c / ny) + grid.y(c % ny) * grid.y(c % ny);
    gap[c] = r2 / (2 * radius);
    loaded[c] = r2 < a * a;
  }
  const std::vector<double> influence = contact::graded_half_space_influence(grid, modulus);
  const contact::GradedContactSolution s
      = contact::graded_half_space_contact(grid, influence, gap, force / 2, std::move(loaded));
  double area = 0;
  for (std::size_t c = 0; c < n; ++c)
    if (s.pressure_pa[c] > 0)
      area += grid.area_m2(c / ny, c % ny);
  EXPECT_NEAR(*std::ranges::max_element(s.pressure_pa) / p0, 1, 0.005);
  EXPECT_NEAR(std::sqrt(2 * area / std::numbers::pi) / a, 1, 0.01);
  // Hertz's approach a^2 / R.
  EXPECT_NEAR(s.approach_m / (a * a / radius), 1, 0.01);
}

TEST(GradedHalfSpaceContact, MirrorImagesAreTheWholeGrids)
{
  // A graded grid over x >= 0, y >= 0 mirrored about x = 0 and y = 0 against
  // the whole grid over all four quadrants: the same deflection under a
  // symmetric pressure, to rounding.
  const std::vector<double> half_x = growing_edges(0, 3e-4, 1e-5, 1.2, 1e-4);
  const std::vector<double> half_y = growing_edges(0, 2e-4, 2e-5, 1.3, 1e-4);
  contact::GradedHalfSpaceGrid quarter{half_x, half_y, 0.0, true};
  contact::GradedHalfSpaceGrid whole;
  for (const auto& [half, full] : {std::pair{&half_x, &whole.x_edges_m}, std::pair{&half_y, &whole.y_edges_m}})
  {
    for (auto e = half->rbegin(); e != half->rend(); ++e)
      full->push_back(-*e);
    full->insert(full->end(), half->begin() + 1, half->end());
  }
  auto pressure = [](double x, double y) { return 1e9 / (1 + 1e7 * x * x + 3e7 * y * y); };
  const std::vector<double> kq = contact::graded_half_space_influence(quarter, 2e11, 1);
  const std::vector<double> kw = contact::graded_half_space_influence(whole, 2e11, 2);
  const std::size_t nq = quarter.size(), nw = whole.size();
  const std::size_t qx = quarter.nx(), qy = quarter.ny(), wy = whole.ny();
  std::vector<double> pw(nw);
  for (std::size_t c = 0; c < nw; ++c)
    pw[c] = pressure(whole.x(c / wy), whole.y(c % wy));
  for (std::size_t c = 0; c < nq; ++c)
  {
    const std::size_t i = c / qy, j = c % qy;
    double uq = 0, uw = 0;
    for (std::size_t d = 0; d < nq; ++d)
      uq += kq[c * nq + d] * pressure(quarter.x(d / qy), quarter.y(d % qy));
    const std::size_t w = (qx + i) * wy + (qy + j); // the same cell in the whole grid
    for (std::size_t d = 0; d < nw; ++d)
      uw += kw[w * nw + d] * pw[d];
    EXPECT_NEAR(uq / uw, 1, 1e-12) << "cell " << i << ", " << j;
  }
}

TEST(GradedHalfSpaceContact, RefusesAMirrorInsideTheGridAndUnorderedEdges)
{
  contact::GradedHalfSpaceGrid grid{{0, 1e-3, 2e-3}, {0, 1e-3}, 1e-3, false};
  EXPECT_THROW(contact::graded_half_space_influence(grid, 1e11), InputError);
  grid.mirror_x_m = -1e-3;
  grid.x_edges_m = {0, 2e-3, 1e-3};
  EXPECT_THROW(contact::graded_half_space_influence(grid, 1e11), InputError);
}

TEST(RoundedEndHalfSpace, MeetsTheNumpyPrototypeCellForCell)
{
  // `python3 scripts/studies/rounded_end_half_space.py --rho 4 35.7 --length 40`:
  // 4575 and 5325 cells, peak over far side 2.1432 and 3.9809, far side
  // 0.9596 and 0.9651 p0, the peak at 0.94 and 2.19 s.
  struct Row
  {
    double rho;
    std::size_t cells;
    double peak_over_far, far_over_p0, peak_x_over_layer;
  };
  for (const Row row : {Row{4, 4575, 2.1432, 0.9596, 0.94}, Row{35.7, 5325, 3.9809, 0.9651, 2.19}})
  {
    contact::RoundedEndHalfSpaceSettings settings;
    settings.radius_ratio = row.rho;
    settings.held_length_over_half_width = 40;
    const contact::RoundedEndHalfSpace r = contact::rounded_end_half_space(settings);
    EXPECT_EQ(r.cells, row.cells);
    EXPECT_NEAR(r.peak_over_far, row.peak_over_far, 5e-5) << "rho " << row.rho;
    EXPECT_NEAR(r.far_over_p0, row.far_over_p0, 5e-5) << "rho " << row.rho;
    EXPECT_NEAR(r.peak_x_over_layer, row.peak_x_over_layer, 0.005) << "rho " << row.rho;
  }
}

TEST(RoundedEndHalfSpace, RefusesAShortHoldAndANonPositiveRatio)
{
  contact::RoundedEndHalfSpaceSettings settings;
  settings.radius_ratio = 4;
  settings.held_length_over_half_width = 5;
  EXPECT_THROW(contact::rounded_end_half_space(settings), InputError);
  settings.held_length_over_half_width = 40;
  settings.radius_ratio = 0;
  EXPECT_THROW(contact::rounded_end_half_space(settings), InputError);
}
