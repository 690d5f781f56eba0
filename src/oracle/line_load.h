#pragma once
// The load rule of a line contact: how a ruling of length L carrying the
// normal force N with centre of pressure c (fraction of the ruling from its
// start) spreads it along the ruling. The no-tension linear (Winkler) rule of
// a rigid footing:
//     1/3 <= c <= 2/3:  p(s) = N / L ((4 - 6c) + (12c - 6) s), s in [0, 1]
//     c < 1/3:          p(s) = 2N / (3c L) (1 - s / (3c)) for s < 3c, else 0
//     c > 2/3:          the mirror image from the other end,
// whose resultant is N at c and which is nowhere negative: the middle-third
// rule of an eccentrically loaded rigid footing on a foundation that takes no
// tension (J. E. Bowles, "Foundation Analysis and Design", McGraw-Hill). N and
// c come from the rolling motion
// (rolling_dynamics.h). It lives in the oracle layer, the lowest that uses it:
// the Hertz contact width of real rolling (contact_density.h) needs it, as do
// the contact loci and the loop scores above.

namespace rollcheck::oracle
{
/// Line load p(s) (N/m) at fraction s of a ruling of length L carrying normal
/// force N with centre of pressure c; 0 where the ruling is unloaded, and for
/// N <= 0 or L <= 0.
double line_load(double normal_force_n, double centre_of_pressure, double length_m, double s);
} // namespace rollcheck::oracle
