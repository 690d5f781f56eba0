#pragma once
// The end of a long line contact at a straight rim across a flattened sheet
// (rollcheck rim's end model, fem/scenes: a block whose top, x' > 0, meets
// the rim's other face, leaning by 180 deg - a, along a straight edge
// across the ruling), as a rounded end's problem (contact/rounded_end.h):
//   h(x', y) = y^2 / (2 R) + max(0, -x' tan(180 deg - a)),   R(x') = R,
// the sheet's profile across the ruling in the gap, under a uniform line
// load q held to
//   l = max(400, 3 after) b
// beyond the end (b: line Hertz's half-width at q and max(R, r_e)); the
// held load's far end deflects the window smoothly, and the window's tilt
// takes it. The load beyond the window is held, not balanced.
#include "contact/rounded_end_problem.h"

namespace rollcheck::contact
{
/// A straight rim of interior angle `interior_angle_rad` (pi/2, pi] across a
/// sheet of radius `sheet_radius_m` under `load_n_per_m`, for `settings`'
/// window and finish.
RoundedEndProblem straight_rim_end(const RoundedEndSettings& settings, double interior_angle_rad,
                                   double sheet_radius_m, double load_n_per_m);
} // namespace rollcheck::contact
