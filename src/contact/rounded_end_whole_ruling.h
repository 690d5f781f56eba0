#pragma once
// One level of a body's rounded end solved over its whole loaded ruling in
// one grid (contact/rounded_end.h): from `before` beyond the end to 1.3 times
// the ruling's loaded length, stopping r_e short of its far rim (whose
// rounding it would need beyond) and short of where an oblique far rim
// crosses the grid's end (the grid and the rounding's margin about it lie
// within the body's outline on the ground). The ruling's force F on the grid
// across the gap
//   gap = g(x', y) + t x'
// (g the rounded surface, contact/ball_rounded_surface.h), the tilt t along
// the ruling set so that F's centre lies at the centre of mass's foot,
//   sum p x' A / sum p A = M / F   (M, F: the ruling's load's moment and force):
// more tilt moves the centre towards the end. From an estimate (the load
// falling to none over its loaded length l, on an approach of a few q / E*:
// t = 4 q(0) / (E* l)), doubled or halved until the foot is bracketed, then
// regula falsi with the Illinois halving (M. Dowell and P. Jarratt, BIT 11
// (1971) 168-174). No rule beyond, no window to double.
#include "contact/rounded_end_level.h"
#include "contact/rounded_end_problem.h"

namespace rollcheck::contact
{
/// The level on cells of `cell`. ComputationError where the body's outline
/// does not cover the grid across, where the contact reaches the grid's
/// border across (ContactBeyondGrid) or where F's centre does not settle at
/// the foot (the contact may reach the ruling's far rim).
SolvedLevel solve_whole_ruling_level(const RoundedEndSettings& settings, const RoundedEndProblem& end,
                                     const LevelScale& scale, double cell);
} // namespace rollcheck::contact
