#pragma once
// A line load along a contact ruling from one of its ends (x' = 0), linear
// where it is positive:
//   q(x') = q_0 + k x'   on [0, l],   0 elsewhere,
// with the load and its first moment about the end over [0, x]
//   Q(x) = q_0 x + k x^2 / 2,   M(x) = q_0 x^2 / 2 + k x^3 / 3   (x clamped to [0, l]).
// The no-tension linear rule (the contact locus's, oracle/line_load.h: a
// rigid footing's middle-third rule, J. E. Bowles, "Foundation Analysis and
// Design") carrying F with its centre at e (as a fraction of [from, L]):
//   e < 1/3:           q(from) = 2 F / (3 e l),  k = -q(from) / (3 e l)   (loaded over 3 e l)
//   1/3 <= e <= 2/3:   q(from) = F / l (4 - 6 e), q(L) = F / l (6 e - 2)
// with l = L - from; a centre in the far third would load the ruling only
// from its far end, which this rule from `from` does not describe.

#include <optional>

namespace rollcheck::contact
{
struct RulingLineLoad
{
  double at_end_n_per_m = 0; ///< q_0
  double slope_n_per_m2 = 0; ///< k
  double length_m = 0;       ///< l: the loaded length from the end

  /// q(x') (N/m).
  double at(double x) const;
  /// Q(x): the load (N) over [0, x].
  double load_to(double x) const;
  /// M(x): that load's first moment (N m) about the end.
  double moment_to(double x) const;

  /// q = at_end + slope x' where positive, on [0, ruling_length] (the no-tension linear rule).
  static RulingLineLoad no_tension(double at_end, double slope, double ruling_length);
  /// The no-tension linear rule on [from, ruling_length] carrying `force` (N)
  /// with its centre at x' = `centre`; none when the centre lies outside the
  /// first two thirds of [from, ruling_length].
  static std::optional<RulingLineLoad> carrying(double force, double centre, double from, double ruling_length);
};
} // namespace rollcheck::contact
