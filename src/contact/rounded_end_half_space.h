#pragma once
// A rounded rim end by half-space theory on a graded grid: the end of a line
// contact of half-width b (line Hertz's, across a sheet of radius R) where
// the rim's edge, rounded to r_e >> b, turns away from the counter-face.
// At the contact's scale the body is then a half-space and the end is
// Hertz's problem with the gap (x along the ruling, the fillet starting at
// x = 0, y across it)
//   h(x, y) = y^2 / (2 R) + max(0, x)^2 / (2 r_e),
// the ruling [-L, 0] pressed onto the rigid plane (or a half-space of E*)
// under the line load q = pi b p0 / 2 and mirrored at x = -L (the far side's
// symmetry plane: a line contact has no plane-strain limit in half-space
// theory, so how far it is held is part of the model). In units of b and
// p0 the pressure depends on rho = R / r_e and L / b alone. The fillet's
// boundary layer, where the line contact's square-root edge meets the
// fillet's parabola, is s = 2 r_e b / (pi R) (docs/methods/rims.md); the
// peak lies a few s past the fillet's start and grows as a rounded punch's,
// p0 (R / r_e)^(1/3) at large R / r_e.
//
// The grid (contact/graded_half_space_contact.h): cells `finest` s long
// from -2 s to `core` s about the fillet's start, growing by 1.15 towards
// -L (at most L / 20) and to 2 b beyond; across, cells `across` b wide to
// 1.25 b, then growing to 1.75 b (wider where the contact reaches it);
// mirrored at y = 0 and x = -L.
#include "contact/graded_half_space_contact.h"
#include <cstddef>
#include <limits>

namespace rollcheck::contact
{
struct RoundedEndGridSettings
{
  double finest_over_layer = 0.125;      ///< cells about the fillet's start, in s
  double across_over_half_width = 0.0625; ///< cells across the contact, in b
  double core_over_layer = 12;           ///< finest cells from -2 s to this many s past the fillet's start
  /// The grid's half-width across, in b: the fine cells to 0.5 b less, then
  /// growing. Where the contact reaches it (it widens near the fillet's
  /// start at large R / r_e and long holds) rounded_end_half_space widens it.
  double extent_over_half_width = 1.75;
};

struct RoundedEndHalfSpaceSettings
{
  double radius_ratio = 0;                ///< R / r_e
  double held_length_over_half_width = 0; ///< L / b
  RoundedEndGridSettings grid;
  unsigned threads = 0; ///< the influence's threads (0: every core)
  /// A grid widened across whose dense matrices would take more bytes
  /// (graded_half_space_bytes) is not solved: ComputationError.
  double max_bytes = std::numeric_limits<double>::infinity();
};

struct RoundedEndHalfSpace
{
  std::size_t cells = 0;
  int active_set_passes = 0;
  double layer_over_half_width = 0; ///< s / b
  double far_over_p0 = 0;           ///< centre-line pressure at x = -L / 2 over line Hertz's p0
  double peak_over_p0 = 0;          ///< the centre line's largest pressure over p0
  double peak_over_far = 0;         ///< the end's factor: peak over the far side
  double peak_x_over_layer = 0;     ///< where the peak lies past the fillet's start, in s
  double extent_over_half_width = 0; ///< the grid's half-width across that held the contact, in b
};

/// s / b = 2 r_e / (pi R) = 2 / (pi rho): the fillet's boundary layer over b.
double boundary_layer_over_half_width(double radius_ratio);

/// The grid of the end (units of b: b = 1).
GradedHalfSpaceGrid rounded_end_grid(const RoundedEndHalfSpaceSettings& settings);

/// The end solved (E* and b arbitrary: the result is nondimensional). Where
/// the contact reaches the grid's side it is solved again on a grid 1.5
/// times as wide across, up to three times.
/// Throws InputError for rho or L / b not positive and finite, L below
/// 10 b or within 4 s of the fillet's start, and ComputationError when the
/// contact still reaches the grid's border.
RoundedEndHalfSpace rounded_end_half_space(const RoundedEndHalfSpaceSettings& settings);
} // namespace rollcheck::contact
