#pragma once
// One level (one cell size) of a rounded end's half-space solve
// (contact/rounded_end.h) and what it reads from its grid's pressure p:
//   the peak max p and where it is,
//   each column's peak and load per unit length   q_i = sum_j p_ij dy,
//   the force and moment about x' = 0 of the columns in [a, b]
//     F = sum p_ij dA,   M = sum p_ij x'_i dA,
//   where the contact starts (the smallest loaded x'),
// and the grid's half-width across: the widest line Hertz contact of the
// ruling's load from a station on, 1.6 b(q(x'), R(x')), with room for a
// balance raising it and the end's extra load near it.
#include "core/seconds_since.h"
#include "contact/ball_rounded_surface.h"
#include "contact/half_space_contact.h"
#include "contact/rounded_end_problem.h"
#include <Eigen/Core>
#include <chrono>
#include <cstddef>
#include <vector>

namespace rollcheck::contact
{
struct RoundedEndLevel
{
  double cell_m = 0;
  std::size_t cells = 0;          ///< in the window
  int iterations = 0;             ///< conjugate-gradient iterations over every tilt
  int solves = 0;                 ///< contact solves to match the ruling beyond the window
  double peak_pressure_pa = 0;
  double peak_along_m = 0;        ///< x' of the peak from the end (negative: beyond it)
  double peak_across_m = 0;
  double contact_start_m = 0;     ///< the loaded cells' smallest x'
  double window_load_change = 0;  ///< the window's load over the ruling's on it, - 1 (what the end does not take)
  /// The linear rule beyond the window once the body balances (a body's
  /// end): q = balanced_end_line_load + balanced_slope x' up to
  /// balanced_loaded_length; the ruling's held load otherwise.
  double balanced_end_line_load_n_per_m = 0;
  double balanced_slope_n_per_m2 = 0;
  double balanced_loaded_length_m = 0;
  double far_peak_pa = 0;         ///< the largest pressure across the ruling at the window's far station (whole ruling: halfway along the contact)
  double far_line_hertz_pa = 0;   ///< line Hertz's p0 at that station's q (the rule's; whole ruling: the column's) and R
  double wall_s = 0;
  std::vector<double> station_m;          ///< x' of each column of cells
  std::vector<double> station_peak_pa;    ///< the largest pressure across each column
  std::vector<double> station_load_n_per_m; ///< the column's load per unit length
};

/// What every level of one end shares.
struct LevelScale
{
  double effective_modulus_pa = 0;
  double half_width_m = 0; ///< b
  double across_scale = 1; ///< the grid's width across over the settings' (widened: > 1)
};

/// A level and what its rounded surface says of half-space theory's reach.
struct SolvedLevel
{
  RoundedEndLevel level;
  double largest_slope = 0; ///< of the rounded surface over the loaded cells
  double end_lift_m = 0;    ///< the rounded surface's height above the ground at the end (x' = 0, y = 0)
};

/// (F, M) of the grid's columns with x' in [from, to].
Eigen::Vector2d load_over(const std::vector<double>& pressure_pa, const HalfSpaceGrid& grid, double from, double to);

/// The level's peak, where it is, its columns and where its contact starts,
/// from the grid's pressure.
void read_level(RoundedEndLevel& level, const std::vector<double>& pressure_pa, const HalfSpaceGrid& grid);

/// The cells a grid needs across on either side of the ruling for the
/// ruling's load from x' = `from` on: the widest contact, at least the
/// settings' `across` b, times the scale's `across_scale`.
std::size_t half_across_cells(const RoundedEndSettings& settings, const RoundedEndProblem& end,
                              const LevelScale& scale, double from, double cell);

/// ceil(length / cell): the cells that cover a length.
std::size_t cells_over(double length_m, double cell_m);
} // namespace rollcheck::contact
