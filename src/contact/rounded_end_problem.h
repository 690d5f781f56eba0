#pragma once
// The input of a rounded end's half-space solve (contact/rounded_end.h): one
// end of a line contact along a ruling (x' along it from the end, y across,
// z up into the body), the surface the body presents there before its
// finish, the sheet's radius of curvature across the ruling R(x'), the line
// load q(x') the contact carries along it (contact/ruling_line_load.h), and
// the settings of the grids: cells of b / cells_per_half_width at the first
// level, b line Hertz's half-width at the end's q with
//   R_ref = max(R(0), r_e)
// (contact/hertz.h line_contact; the finished part has no radius below
// r_e), E* = effective_modulus(E, nu, steel counter-face).
#include "contact/hertz.h"
#include "contact/ruling_line_load.h"
#include <functional>

namespace rollcheck::contact
{
struct RoundedEndSettings
{
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

struct RoundedEndProblem
{
  /// The body's surface above the ground before its finish, at (x', y);
  /// +infinity outside the body's outline on the ground.
  std::function<double(double, double)> hull_height;
  /// R(x') across the ruling.
  std::function<double(double)> sheet_radius;
  RulingLineLoad load;        ///< q(x') along the ruling
  double ruling_length_m = 0; ///< where the ruling (and any load on it) ends
  /// Re-solve the ruling's load beyond the window so that the body balances
  /// (a body's end: F and its centre held); else the load beyond is held (an
  /// end of a long contact).
  bool balance_body = false;
};

/// E* of the settings' body on its counter-face.
double effective_modulus(const RoundedEndSettings& settings);
/// R_ref = max(R(0), r_e).
double reference_radius(const RoundedEndSettings& settings, const RoundedEndProblem& end);
/// Line Hertz at the end's q and R_ref: b and p0 of the grids' scale.
LineHertz end_line_hertz(const RoundedEndSettings& settings, const RoundedEndProblem& end);
} // namespace rollcheck::contact
