#pragma once
// One level of a rounded end solved on a window of the ruling
// [-before, after] (contact/rounded_end.h), the rest of the loaded ruling
// beyond the window prescribed as line Hertz pressure at the sheet's R(x')
// (contact/line_hertz_beyond.h), its deflection in the window's gap:
//   gap = g(x', y) + u_beyond(x', y) + t x',   sum p A = s Q(after)
// with g the rounded surface (contact/ball_rounded_surface.h) and Q the
// ruling's load over [0, x'] (contact/ruling_line_load.h). The window
// shares the counter-face's approach and tilt t with the ruling beyond it:
// the window's force over the ruling's on it, s, and t are set (Broyden's
// method from a finite-difference Jacobian, C. G. Broyden, Math. Comp. 19
// (1965) 577-593) so that the window carries the ruling's load and its
// moment arm over the matching zone [0.5, 0.9] of `after`, where the end no
// longer shows. For a body's end (balance_body) the ruling beyond then takes
// the no-tension linear rule again with F less the window's load and its
// moment, so that the body balances (F through the centre of mass's foot;
// Broyden on the rule's q at the end and its slope, from half steps), the
// load the finished end does not take moving along the ruling. A balance
// step whose rule beyond the window ends inside it or puts more than F on
// it is halved back (at most ten times).
#include "contact/rounded_end_level.h"
#include "contact/rounded_end_problem.h"
#include "core/error.h"

namespace rollcheck::contact
{
/// The ruling beyond the window cannot balance the body with it: the window
/// covers too much of the loaded ruling (a shorter window may).
struct WindowCannotBalance : ComputationError
{
  using ComputationError::ComputationError;
};

/// The level on cells of `cell`. ContactBeyondGrid where the contact reaches
/// the window's border (across: a wider window holds it),
/// WindowCannotBalance, ComputationError when the matching does not settle.
SolvedLevel solve_window_level(const RoundedEndSettings& settings, const RoundedEndProblem& end,
                               const LevelScale& scale, double cell);
} // namespace rollcheck::contact
