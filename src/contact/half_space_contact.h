#pragma once
// Frictionless contact of two elastic half-spaces (one of them may be rigid)
// across an initial gap given on a uniform grid of rectangular cells: the
// boundary-element method of half-space theory (K. L. Johnson, Contact
// Mechanics, CUP 1985, sec. 3.4 and 3.9). The pressure is constant on each
// cell; a uniform pressure p on the cell |x| <= a, |y| <= c deflects the two
// surfaces apart at (x, y) by (Love 1929; Johnson eq. 3.25)
//   u = p / (pi E*) [f(x+a, y+c) - f(x+a, y-c) - f(x-a, y+c) + f(x-a, y-c)],
//   f(s, t) = s asinh(t / s) + t asinh(s / t)   (f = 0 where s or t is 0),
// the integral of 1 / r over the cell; 1 / E* = (1 - nu1^2) / E1 + (1 -
// nu2^2) / E2 (contact/hertz.h effective_modulus). The grid's deflection is
// that kernel convolved with the pressure, by FFT on a grid padded to twice
// each side so that the circular convolution equals the linear one (DC-FFT:
// S. Liu, Q. Wang, G. Liu, Wear 243 (2000) 101-111). Both are real: half
// spectra along y (the other half is their conjugate), and the padding's
// rows are neither transformed nor transformed back. The contact conditions
//   p >= 0,  g = h + u - delta >= 0,  p g = 0,  sum p A = F
// (h the initial gap, delta the rigid approach) are solved by the constrained
// conjugate-gradient method of I. A. Polonsky and L. M. Keer, Wear 231 (1999)
// 206-219, which holds the force at every iteration.
//
// Half-space theory needs the surfaces' slopes small across the contact (as
// Hertz's theory does); the grid must hold the whole contact with unloaded
// cells at its border (the solver refuses a loaded border cell).
#include "core/error.h"
#include <complex>
#include <cstddef>
#include <span>
#include <vector>

namespace rollcheck::contact
{
/// Cells (i, j), i = 0..nx-1 along x and j = 0..ny-1 along y, centred at
/// (x0 + i dx, y0 + j dy); values of a field are stored at i * ny + j.
struct HalfSpaceGrid
{
  std::size_t nx = 0;
  std::size_t ny = 0;
  double cell_x_m = 0;
  double cell_y_m = 0;
  double first_x_m = 0; ///< x of the centre of cells (0, j)
  double first_y_m = 0; ///< y of the centre of cells (i, 0)

  double x(std::size_t i) const { return first_x_m + static_cast<double>(i) * cell_x_m; }
  double y(std::size_t j) const { return first_y_m + static_cast<double>(j) * cell_y_m; }
  std::size_t size() const { return nx * ny; }
  double cell_area_m2() const { return cell_x_m * cell_y_m; }
};

/// f(s, t) = s asinh(t / |s|) + t asinh(s / |t|): the integral of 1 / r over
/// the rectangle [0, s] x [0, t] (m), odd in s and in t; Love's rectangle is
/// its sum over the four corners.
double love_corner_integral(double s_m, double t_m);

/// Deflection (m per Pa of pressure) at (x, y) from the centre of a cell of
/// half-sides a (along x) and c (along y) under uniform unit pressure.
double cell_deflection(double half_x_m, double half_y_m, double x_m, double y_m, double effective_modulus_pa);

/// The grid's influence operator: deflection = K pressure, by FFT.
class HalfSpaceDeflection
{
public:
  HalfSpaceDeflection(const HalfSpaceGrid& grid, double effective_modulus_pa);
  /// u (m) at every cell from the cells' pressures (Pa).
  std::vector<double> operator()(std::span<const double> pressure_pa) const;
  const HalfSpaceGrid& grid() const { return grid_; }

private:
  HalfSpaceGrid grid_;
  std::size_t padded_x_ = 0;
  std::size_t padded_y_ = 0;
  std::vector<std::complex<double>> kernel_spectrum_;
};

struct HalfSpaceContactSettings
{
  double tolerance = 1e-9;     ///< A sum |p_new - p_old| / F at which the iteration stops
  int max_iterations = 5000;
  /// The contact runs on past the grid's last x (loaded there by the caller,
  /// in the gap): the cells at i = nx - 1 may carry load. Every other border
  /// cell must not.
  bool contact_continues_past_last_x = false;
};

struct HalfSpaceContact
{
  std::vector<double> pressure_pa;  ///< per cell (i * ny + j)
  std::vector<double> deflection_m; ///< u per cell
  double approach_m = 0;            ///< delta: h + u = delta where p > 0
  int iterations = 0;
  double change = 0;                ///< the last iteration's A sum |p_new - p_old| / F
  double largest_gap_violation_m = 0; ///< max over unloaded cells of (delta - h - u), <= 0 when solved
};

/// The contact reached a border cell of the grid: `across` when at j = 0
/// or ny - 1 (a wider grid across holds it), else at an end along x.
struct ContactBeyondGrid : ComputationError
{
  ContactBeyondGrid(const std::string& what, bool reached_across) : ComputationError(what), across(reached_across) {}
  bool across = false;
};

/// Solves the contact for total force `force_n` across the initial gap
/// `gap_m` (per cell, m). `initial_pressure_pa` (optional, per cell) starts
/// the iteration, e.g. from a nearby solve. Throws InputError on a gap or
/// force that is not finite or a negative force, ComputationError when the
/// iteration does not converge, ContactBeyondGrid when the contact reaches
/// the grid's border.
HalfSpaceContact solve_half_space_contact(const HalfSpaceDeflection& deflection, std::span<const double> gap_m,
                                          double force_n, const HalfSpaceContactSettings& settings = {},
                                          std::span<const double> initial_pressure_pa = {});
} // namespace rollcheck::contact
