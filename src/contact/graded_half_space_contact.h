#pragma once
// Frictionless contact of an elastic half-space with a rigid body (or of two
// half-spaces, through E*) on a tensor grid of rectangular cells of any
// sizes: where a contact has a scale far below its extent (a rounded rim
// end's fillet boundary layer, s ~ 1e-3 b, beside a line contact held over
// hundreds of b) a uniform grid (contact/half_space_contact.h) cannot afford
// the small cells everywhere. The pressure is constant on each cell; a cell
// [x1, x2] x [y1, y2] under unit pressure deflects the surface at (x, y) by
// (Love 1929; K. L. Johnson, Contact Mechanics, CUP 1985, eq. 3.25)
//   u = [f(x-x1, y-y1) - f(x-x1, y-y2) - f(x-x2, y-y1) + f(x-x2, y-y2)] / (pi E*)
// with f = love_corner_integral. A symmetry plane x = m or y = 0 is a mirror
// image of every cell (the pressure field symmetric about it). Evaluated at
// the cells' centres, the influence is a dense n x n matrix: the grid's
// corners are shared, so each row costs one f per corner and image.
//
// The contact conditions
//   p >= 0,  g = h + K p - delta >= 0,  p g = 0,  sum p A = F
// (h the initial gap, delta the rigid approach) are solved by an active set
// (Kalker's, as in Johnson sec. 5.9): the equations on the loaded cells
// solved exactly (dense LU, LAPACK), cells pulled (p < 0) dropped and cells
// penetrated (g < 0) added, until neither.
//
// Memory: 8 n^2 bytes for the influence and up to as much again for the
// loaded cells' system; graded_half_space_bytes says how much before any is
// allocated.
#include <cstddef>
#include <optional>
#include <span>
#include <vector>

namespace rollcheck::contact
{
/// Cells (i, j) of the tensor grid of x_edges_m (nx + 1, increasing) and
/// y_edges_m (ny + 1, increasing); values stored at i * ny + j.
struct GradedHalfSpaceGrid
{
  std::vector<double> x_edges_m;
  std::vector<double> y_edges_m;
  /// The field is mirrored about the plane x = mirror_x_m (outside the grid).
  std::optional<double> mirror_x_m;
  /// The field is mirrored about y = 0 (the grid's y_edges_m start at 0).
  bool mirror_y = false;

  std::size_t nx() const { return x_edges_m.size() - 1; }
  std::size_t ny() const { return y_edges_m.size() - 1; }
  std::size_t size() const { return nx() * ny(); }
  double x(std::size_t i) const { return 0.5 * (x_edges_m[i] + x_edges_m[i + 1]); }
  double y(std::size_t j) const { return 0.5 * (y_edges_m[j] + y_edges_m[j + 1]); }
  double area_m2(std::size_t i, std::size_t j) const
  {
    return (x_edges_m[i + 1] - x_edges_m[i]) * (y_edges_m[j + 1] - y_edges_m[j]);
  }
};

/// Bytes the influence and the loaded cells' system take at most for a grid of `cells`.
double graded_half_space_bytes(std::size_t cells);

/// The dense influence (row-major, n x n): deflection (m) at cell i's centre
/// per Pa on cell j and its mirror images, E* the effective modulus.
/// `threads` as oracle::parallel_for's (0: every core).
std::vector<double> graded_half_space_influence(const GradedHalfSpaceGrid& grid, double effective_modulus_pa,
                                                unsigned threads = 0);

struct GradedContactSolution
{
  std::vector<double> pressure_pa;
  double approach_m = 0;
  int active_set_passes = 0;
};

/// The contact under `force_n` on the grid's cells (the mirror images carry
/// as much again each), from the initially loaded cells `loaded` (nonzero:
/// loaded). Throws ComputationError when the set does not settle in 100
/// passes or the loaded cells' system is singular.
GradedContactSolution graded_half_space_contact(const GradedHalfSpaceGrid& grid, std::span<const double> influence,
                                                std::span<const double> gap_m, double force_n,
                                                std::vector<char> loaded);
} // namespace rollcheck::contact
