#pragma once
// A rounded rim end whose rim is nearly flat (interior angle 150-180 deg),
// in 3D by half-space theory: the end of the rolling loop where `rim`'s
// FEM end model is weakest (a fillet arc shorter than its boundary layer,
// the end table's last node standing for 178.5-180 deg).
//
// The oloid at a vertex orientation (the default; any two-circle body's loop
// end of a given angle with `body`): at c = 1/4 (and 3/4) it
// stands on the ruling from P, rim circle A's point at -60 deg, to B's far
// point; the ruling is A's tangent at P (the rim's interior angle is
// 180 deg), the sheet's radius across the ruling falls to 0 at P
// (R = 2 x' / sqrt 3) and the contact locus's no-tension rule puts its
// largest line load there, q(P) = 8 F / (3 L) (scripts/studies/oloid_vertex.py). A
// part finished with edge radius r_e is the hull rounded by a ball of r_e
// rolled inside it; the FEM end table takes such an end as line Hertz at
// R = r_e times a straight rim's factor, an estimate from above. Here it is
// solved as it is; so is any loaded end of a two-circle body's loop (a
// LoopEnd, study/rims/flattest_loop_ends.h: the settings' body's by
// `end_angle_rad`, rim --body's flat-rim table by the loop's own angles). Or
// (`interior_angle_rad` > 0) a straight rim across a flattened sheet of
// radius R under a uniform line load q, `rim`'s one end, to check this
// reduction against the FEM end model.
//  - the surface: the hull's lower surface near the end (a body's from
//    its two circles, geometry/two_circle_hull_height.h; the straight rim's
//    y^2 / 2R + max(0, -x' tan(180 deg - a)), rim's flat sheet), rounded by the ball
//    (geometry/rolling_ball_opening.h, small slopes), on a grid of cells of
//    b / cells_per_half_width, b line Hertz's half-width at the end's q with
//    R = max(R_end, r_e) (R_end = 0 at the oloid's apex);
//  - the body and the counter-face as half-spaces (contact/half_space_contact.h):
//    exact for the steel block, and for the body where its rim is nearly
//    flat and the surface's slopes across the contact are small (reported);
//  - the window [-before, +after] b along the ruling from the end is solved
//    (12 b and 100 b);
//    beyond it, along the rest of the loaded ruling, the line load as line
//    Hertz pressure at the sheet's R(x'), prescribed: its deflection is in
//    the window's gap. The window shares the counter-face's approach and
//    tilt along the ruling with the ruling beyond it: both are set (Broyden)
//    so that the window carries the ruling's load and moment over its
//    matching zone, [0.5, 0.9] of `after`, where the end no longer shows.
//    For a body's end the ruling beyond then takes the no-tension linear
//    rule again with the window's load and moment, so that the body
//    balances (F through the centre of mass's foot; Broyden on the rule's q
//    at the end and its slope): the load the finished end does not take
//    moves along the ruling. No rotation about the ruling.
//    Where the window (or its doubled check) covers so much of the loaded
//    ruling that the rule beyond cannot balance the body with it (a short
//    ruling, or a load close to the end), the window shortens by a quarter
//    at a time, at most three times (to 42 % of `after`); where the contact
//    outgrows the window across (the balanced load beyond it rising above
//    the locus's), the window widens by half at a time, at most twice. A
//    balance step whose rule beyond the window ends inside it or puts more
//    than F on it is halved back (at most ten times; then the window
//    shortens). The window used is reported; none of this changes an end
//    that solved at the settings.
//  - or (`whole_ruling`, a body's end) the whole loaded ruling in one grid,
//    from `before` beyond the end to 1.3 times the locus's loaded length
//    (within the ruling, r_e short of its far rim): F on the grid, the tilt
//    along the ruling set (bracketed, then regula falsi) so that F's centre
//    lies at the centre of mass's foot. No rule beyond, no window to
//    double: the reduction above is checked against it (docs/flat-rim.md);
//    the contact must end before the grid's far side.
// Levels halve the cells; the peak is converged when it changes by less
// than `tolerance` at the last level and (not for the whole ruling) when the
// first level's window is doubled along the ruling (the half-space's reach along a line contact is
// long: an end's extra line load decays over tens of b, and for a long
// contact held to a uniform load the end's peak keeps growing with the
// held length, as line contacts in half-space theory have no plane-strain
// limit).
#include "geometry/body.h"
#include "study/rims/flattest_loop_ends.h"
#include <nlohmann/json_fwd.hpp>
#include <numbers>
#include <vector>

namespace rollcheck::study::rims
{
/// Below this interior angle the rim's other face is too steep for half-space theory.
constexpr double smallest_flat_rim_angle_rad = 150 * std::numbers::pi / 180;

/// The true oloid of r1 = 10 mm, the body of the rim scenes' rounded loops.
inline geometry::BodySpec rim_scene_oloid()
{
  geometry::BodySpec oloid;
  oloid.radius_m = 0.01;
  return oloid;
}

struct FlatRimSettings
{
  /// A two-circle body (by default the rim scenes' oloid, r1 = 10 mm).
  geometry::BodySpec body = rim_scene_oloid();
  double normal_load_n = 800;     ///< F through the centre of mass (rim --body's)
  /// The body's loop orientation whose loaded end has this interior angle
  /// (rad): pi is the loop's flattest end (the oloid's vertex, c = 1/4),
  /// below it the orientation on the loop's side `loop_side` from there.
  double end_angle_rad = std::numbers::pi;
  int loop_side = 0;              ///< 0: walking the loop forwards, 1: backwards (the oloid's mirror image)
  /// > 0: a straight rim of this interior angle (rad) across a flattened sheet
  /// instead of the body's loop end, with:
  double interior_angle_rad = 0;
  double sheet_radius_m = 1e-3;   ///< R of that sheet
  double load_n_per_m = 1.2e5;    ///< its uniform line load q
  double edge_radius_m = 4e-4;    ///< r_e of the finish (rim --body's)
  double youngs_modulus_pa = 200e9;
  double poisson_ratio = 0.3;
  bool steel_counter_face = false; ///< a half-space of the body's material; else the rigid plane
  double cells_per_half_width = 4; ///< b / cell at the first level
  int levels = 2;
  /// Levels beyond `levels`, added one at a time while the peak's change
  /// between the last two is at least `tolerance` (a cell that does not yet
  /// resolve the end); the window's change is not a level's to mend.
  int extra_levels = 0;
  double before_over_half_width = 12; ///< the window beyond the end, in b
  double after_over_half_width = 100; ///< the window along the ruling from the end, in b
  double across_over_half_width = 4;  ///< the window's half-width across the ruling, in b
  double tolerance = 0.03;            ///< of the peak between the last two levels
  /// A body's end: solve its whole loaded ruling in one grid instead of the
  /// window and the rule beyond it (F at the centre of mass's foot by the
  /// tilt alone; no window to double). The fuller model where the end's
  /// reach is comparable with a short ruling; the contact must end on the
  /// ruling, before its far rim.
  bool whole_ruling = false;
};

struct FlatRimLevel
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

struct FlatRimContact
{
  double ruling_length_m = 0;           ///< the body's
  double centre_of_pressure = 0;        ///< the body's c, as a fraction of the ruling from the end
  double interior_angle_rad = 0;        ///< of the rim at the end
  double end_radius_m = 0;              ///< the hull's sheet radius across the ruling at the end
  double end_line_load_n_per_m = 0;    ///< q at the end (the oloid's q(P))
  double effective_modulus_pa = 0;
  double reference_radius_m = 0;        ///< max(R_end, r_e)
  double half_width_m = 0;              ///< b: line Hertz at the end's q, R = max(R_end, r_e)
  double line_hertz_peak_pa = 0;        ///< p0 there: what rim --body takes before its end factor
  double largest_slope = 0;             ///< of the rounded surface over the loaded cells (half-space theory needs it small)
  double end_lift_m = 0;               ///< the rounded surface's height above the ground at the end
  std::vector<FlatRimLevel> levels;
  double last_change = 0;               ///< of the peak, last level against the one before
  double longer_window_peak_pa = 0;     ///< the first level's peak with `after` doubled
  double window_change = 0;             ///< that against the first level's
  bool converged = false;               ///< both changes below the tolerance
  double wall_s = 0;                    ///< every level and the longer window
  double after_over_half_width = 0;     ///< the window's `after` used (the settings', or shortened; whole ruling: the grid's reach)
  double across_scale = 1;              ///< the window's width across over the settings' (widened: > 1)
  bool whole_ruling = false;            ///< solved over the whole loaded ruling (no longer window)
};

/// Whether a body's end solved at the settings' window wants its whole
/// ruling instead: the balance shortened the window and the doubled window
/// still moves the peak by the tolerance (a short ruling, the end's reach
/// comparable with it: the U optimum's 160-166 deg ends on steel).
bool needs_whole_ruling(const FlatRimSettings& settings, const FlatRimContact& window_result);

/// The settings' scene: the straight rim (interior_angle_rad > 0) or the
/// body's loop end at end_angle_rad. Throws InputError for a non-positive
/// radius, load, edge radius or modulus, an angle outside [150, 180] deg or
/// a body other than the oloids and rollers (the cylinder's ends are square),
/// ComputationError when a solve fails (the contact reaching the window's
/// border beyond P, or across once the window has widened twice, names the
/// setting to widen; a window shortened three times that still cannot
/// balance the body says so).
FlatRimContact flat_rim_contact(const FlatRimSettings& settings);
/// A loaded end of any two-circle body's loop (study/rims/flattest_loop_ends.h),
/// its q from F (the settings' normal_load_n) and c by the locus's rule; the
/// settings' oloid and straight-rim fields are not used.
FlatRimContact flat_rim_contact(const FlatRimSettings& settings, const LoopEnd& end);
/// The hull's lower surface near a loop's end, as flat-rim solves it: its
/// height (m) above the ground at x' along the ruling from the end (negative:
/// beyond it) and y across (geometry/two_circle_hull_height.h).
double end_hull_height(const LoopEnd& end, double along_m, double across_m);
/// A two-circle body at its loop's end of this interior angle (pi: the
/// loop's flattest, the oloid's vertex), on the loop's side `loop_side` (0
/// forwards, 1 backwards) from the flattest. The centre of mass is the
/// rolling loop's (oracle::mass_mesh), except the oloid's: midway between
/// its circles' centres by symmetry, exactly, so that its vertex has
/// c = 1/4 exactly.
LoopEnd body_loop_end(const geometry::BodySpec& body, double interior_angle_rad, int loop_side = 0);

nlohmann::json to_json(const FlatRimContact& result);
} // namespace rollcheck::study::rims
