#include "contact/graded_half_space_contact.h"
#include "contact/half_space_contact.h"
#include "core/error.h"
#include "oracle/parallel_for.h"
#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <numbers>

extern "C" void dgesv_(const int* n, const int* nrhs, double* a, const int* lda, int* ipiv, double* b, const int* ldb,
                       int* info);

namespace rollcheck::contact
{
namespace
{
void check_edges(const std::vector<double>& edges, const char* axis)
{
  if (edges.size() < 2)
    throw InputError(fmt::format("graded half-space contact: the grid needs at least one cell along {}", axis));
  for (std::size_t k = 0; k + 1 < edges.size(); ++k)
    if (!(edges[k + 1] > edges[k]) || !std::isfinite(edges[k + 1]))
      throw InputError(fmt::format("graded half-space contact: the {} edges must increase, got {} then {} m", axis,
                                   edges[k], edges[k + 1]));
}

/// Adds sign times the deflection of every cell under unit pressure, seen
/// from offsets a_k = x - X_k to the x edges and b_l = y - Y_l to the y edges
/// (an image's offsets reversed give sign -1), to `row`.
void add_cells(std::span<const double> a, std::span<const double> b, double sign, std::vector<double>& corners,
               std::span<double> row)
{
  const std::size_t nx = a.size() - 1, ny = b.size() - 1;
  for (std::size_t k = 0; k <= nx; ++k)
    for (std::size_t l = 0; l <= ny; ++l)
      corners[k * (ny + 1) + l] = love_corner_integral(a[k], b[l]);
  for (std::size_t k = 0; k < nx; ++k)
    for (std::size_t l = 0; l < ny; ++l)
    {
      const double* c = corners.data() + k * (ny + 1) + l;
      row[k * ny + l] += sign * (c[0] - c[1] - c[ny + 1] + c[ny + 2]);
    }
}
} // namespace

double graded_half_space_bytes(std::size_t cells)
{
  const double n = static_cast<double>(cells);
  return 8 * (2 * n * n + 4 * n);
}

std::vector<double> graded_half_space_influence(const GradedHalfSpaceGrid& grid, double effective_modulus_pa,
                                                unsigned threads)
{
  check_edges(grid.x_edges_m, "x");
  check_edges(grid.y_edges_m, "y");
  if (grid.mirror_y && grid.y_edges_m.front() != 0)
    throw InputError(fmt::format("graded half-space contact: mirrored about y = 0, the grid must start there, not at "
                                 "{} m", grid.y_edges_m.front()));
  if (grid.mirror_x_m && *grid.mirror_x_m > grid.x_edges_m.front() && *grid.mirror_x_m < grid.x_edges_m.back())
    throw InputError(fmt::format("graded half-space contact: the mirror plane x = {} m lies inside the grid",
                                 *grid.mirror_x_m));
  if (!(effective_modulus_pa > 0) || !std::isfinite(effective_modulus_pa))
    throw InputError(fmt::format("graded half-space contact: E* must be positive, got {} Pa", effective_modulus_pa));
  const std::size_t nx = grid.nx(), ny = grid.ny(), n = grid.size();
  std::vector<double> influence(n * n, 0.0);
  const double scale = 1 / (std::numbers::pi * effective_modulus_pa);
  oracle::parallel_for(nx, threads, [&](std::size_t i) {
    // Offsets to the edges from column i's centres, direct and through each image.
    std::vector<double> a(nx + 1), a_image(nx + 1), b(ny + 1), b_image(ny + 1), corners((nx + 1) * (ny + 1));
    const double x = grid.x(i);
    for (std::size_t k = 0; k <= nx; ++k)
    {
      a[k] = x - grid.x_edges_m[k];
      // The image of the edge X about m is 2 m - X; the image cells' order is reversed.
      a_image[k] = grid.mirror_x_m ? x - (2 * *grid.mirror_x_m - grid.x_edges_m[k]) : 0;
    }
    for (std::size_t j = 0; j < ny; ++j)
    {
      const double y = grid.y(j);
      for (std::size_t l = 0; l <= ny; ++l)
      {
        b[l] = y - grid.y_edges_m[l];
        b_image[l] = y + grid.y_edges_m[l];
      }
      std::span<double> row(influence.data() + (i * ny + j) * n, n);
      add_cells(a, b, 1, corners, row);
      if (grid.mirror_y)
        add_cells(a, b_image, -1, corners, row);
      if (grid.mirror_x_m)
      {
        add_cells(a_image, b, -1, corners, row);
        if (grid.mirror_y)
          add_cells(a_image, b_image, 1, corners, row);
      }
      for (double& v : row)
        v *= scale;
    }
  });
  return influence;
}

GradedContactSolution graded_half_space_contact(const GradedHalfSpaceGrid& grid, std::span<const double> influence,
                                                std::span<const double> gap_m, double force_n,
                                                std::vector<char> loaded)
{
  const std::size_t n = grid.size(), ny = grid.ny();
  if (influence.size() != n * n || gap_m.size() != n || loaded.size() != n)
    throw InputError(fmt::format("graded half-space contact: {} cells, but an influence of {} values, {} gaps and {} "
                                 "loaded flags",
                                 n, influence.size(), gap_m.size(), loaded.size()));
  if (!(force_n > 0) || !std::isfinite(force_n))
    throw InputError(fmt::format("graded half-space contact: the force must be positive, got {} N", force_n));
  std::vector<double> area(n);
  for (std::size_t c = 0; c < n; ++c)
    area[c] = grid.area_m2(c / ny, c % ny);
  GradedContactSolution solution;
  std::vector<double> system, rhs;
  std::vector<int> pivots;
  for (int pass = 1; pass <= 100; ++pass)
  {
    std::vector<std::size_t> cells;
    for (std::size_t c = 0; c < n; ++c)
      if (loaded[c])
        cells.push_back(c);
    if (cells.empty())
      throw ComputationError("graded half-space contact: no cell is loaded");
    // Column-major [K_LL, -1; A_L^T, 0] [p; delta] = [-h_L; F].
    const std::size_t m = cells.size(), size = m + 1;
    system.assign(size * size, 0.0);
    rhs.assign(size, 0.0);
    for (std::size_t c = 0; c < m; ++c)
    {
      double* column = system.data() + c * size;
      for (std::size_t r = 0; r < m; ++r)
        column[r] = influence[cells[r] * n + cells[c]];
      column[m] = area[cells[c]];
    }
    for (std::size_t r = 0; r < m; ++r)
    {
      system[m * size + r] = -1;
      rhs[r] = -gap_m[cells[r]];
    }
    rhs[m] = force_n;
    pivots.assign(size, 0);
    const int order = static_cast<int>(size), one = 1;
    int info = 0;
    dgesv_(&order, &one, system.data(), &order, pivots.data(), rhs.data(), &order, &info);
    if (info != 0)
      throw ComputationError(fmt::format("graded half-space contact: the loaded cells' system is singular (LAPACK "
                                         "dgesv info {}) at pass {}",
                                         info, pass));
    solution.pressure_pa.assign(n, 0.0);
    for (std::size_t r = 0; r < m; ++r)
      solution.pressure_pa[cells[r]] = rhs[r];
    solution.approach_m = rhs[m];
    solution.active_set_passes = pass;
    bool settled = true;
    const double penetration = -1e-12 * std::abs(solution.approach_m);
    for (std::size_t c = 0; c < n; ++c)
    {
      if (loaded[c])
      {
        if (solution.pressure_pa[c] < 0)
          loaded[c] = 0, settled = false;
        continue;
      }
      const double* row = influence.data() + c * n;
      double clearance = gap_m[c] - solution.approach_m;
      for (const std::size_t j : cells)
        clearance += row[j] * solution.pressure_pa[j];
      if (clearance < penetration)
        loaded[c] = 1, settled = false;
    }
    if (settled)
      return solution;
  }
  throw ComputationError("graded half-space contact: the loaded set did not settle in 100 passes");
}
} // namespace rollcheck::contact
