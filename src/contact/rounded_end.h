#pragma once
// A rounded end of a line contact along a ruling, in 3D by half-space
// theory: the end of a loaded ruling (a rim of interior angle 150-180 deg)
// finished with edge radius r_e, pressed onto a rigid plane or a steel
// half-space. The method of `rollcheck flat-rim`, independent of how the
// end and its load were found.
//  - the surface: the body's surface near the end (RoundedEndProblem)
//    rounded by a ball of r_e rolled inside it (contact/ball_rounded_surface.h,
//    small slopes), on a grid of cells of b / cells_per_half_width, b line
//    Hertz's half-width at the end's q with R = max(R(0), r_e)
//    (contact/rounded_end_problem.h);
//  - the body and the counter-face as half-spaces (contact/half_space_contact.h:
//    K. L. Johnson, Contact Mechanics, CUP 1985, sec. 3.9; Polonsky and Keer,
//    Wear 231 (1999) 206-219): exact for the steel block, and for the body
//    where its rim is nearly flat and the surface's slopes across the contact
//    are small (reported: largest_slope);
//  - the window [-before, +after] b along the ruling from the end is solved
//    (12 b and 100 b), the rest of the loaded ruling beyond it prescribed as
//    line Hertz pressure, the window matched to it and, for a body's end,
//    the body balanced (contact/rounded_end_window.h);
//    where the window (or its doubled check) covers so much of the loaded
//    ruling that the rule beyond cannot balance the body with it (a short
//    ruling, or a load close to the end), the window shortens by a quarter
//    at a time, at most three times (to 42 % of `after`); where the contact
//    outgrows the window across (the balanced load beyond it rising above
//    the given load's), the window widens by half at a time, at most twice.
//    The window used is reported; none of this changes an end that solved at
//    the settings;
//  - or (`whole_ruling`, a body's end) the whole loaded ruling in one grid,
//    F's centre at the centre of mass's foot by the tilt along the ruling
//    (contact/rounded_end_whole_ruling.h); the window is checked against it.
// Levels halve the cells (core/refinement_series.h); the peak is converged
// when its relative change between the last two levels,
//   c = p_n / p_{n-1} - 1,
// is below `tolerance` and (not for the whole ruling) so is its change when
// the first level's window is doubled along the ruling (the half-space's
// reach along a line contact is long: an end's extra line load decays over
// tens of b, and for a long contact held to a uniform load the end's peak
// keeps growing with the held length, as line contacts in half-space theory
// have no plane-strain limit).
#include "contact/rounded_end_level.h"
#include "contact/rounded_end_problem.h"
#include <functional>
#include <string>
#include <vector>

namespace rollcheck::contact
{
struct RoundedEndContact
{
  double end_line_load_n_per_m = 0;    ///< q at the end
  double effective_modulus_pa = 0;
  double reference_radius_m = 0;        ///< max(R(0), r_e)
  double half_width_m = 0;              ///< b: line Hertz at the end's q, R = max(R(0), r_e)
  double line_hertz_peak_pa = 0;        ///< p0 there
  double largest_slope = 0;             ///< of the rounded surface over the loaded cells (half-space theory needs it small)
  double end_lift_m = 0;               ///< the rounded surface's height above the ground at the end
  std::vector<RoundedEndLevel> levels;
  double last_change = 0;               ///< of the peak, last level against the one before
  double longer_window_peak_pa = 0;     ///< the first level's peak with `after` doubled
  double window_change = 0;             ///< that against the first level's
  bool converged = false;               ///< both changes below the tolerance
  double wall_s = 0;                    ///< every level and the longer window
  double after_over_half_width = 0;     ///< the window's `after` used (the settings', or shortened; whole ruling: the grid's reach)
  double across_scale = 1;              ///< the window's width across over the settings' (widened: > 1)
  bool whole_ruling = false;            ///< solved over the whole loaded ruling (no longer window)
};

/// The levels (and the longer window) of `end`. ComputationError when a
/// solve fails: the contact reaching the window's border beyond the end, or
/// across once the window has widened twice (ContactBeyondGrid), a window
/// shortened three times that still cannot balance the body
/// (WindowCannotBalance), a matching or balance that does not settle.
/// `progress`, if set, is told each solve as it starts (the longer window,
/// each level), in words.
using RoundedEndProgress = std::function<void(const std::string&)>;
RoundedEndContact solve_rounded_end(const RoundedEndSettings& settings, const RoundedEndProblem& end,
                                    const RoundedEndProgress& progress = {});

/// Whether a body's end solved at the settings' window wants its whole
/// ruling instead: the balance shortened the window and the doubled window
/// still moves the peak by the tolerance (a short ruling, the end's reach
/// comparable with it).
bool needs_whole_ruling(const RoundedEndSettings& settings, const RoundedEndContact& window_result);
} // namespace rollcheck::contact
