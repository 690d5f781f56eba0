#pragma once
// The line load one contact ruling of a rolling line contact carries under a
// load rule, and the point of it at which a peak pressure is taken. For a
// sample of the rolling motion whose ruling runs from s_1 to s_2 (length L,
// fraction f from s_1), F the prescribed load:
//  - static through the centre of mass G: N = F, centre of pressure
//    c = ((G - s_1) . (s_2 - s_1)) / L^2;
//  - dynamic: N = F N_motion / (m g), c the motion's own centre of pressure
//    (Newton-Euler, oracle/rolling_dynamics.h);
//  - uniform: q = F / L along the whole ruling.
// Static and dynamic spread N by the no-tension linear rule of a rigid
// footing (oracle/line_load.h; J. E. Bowles, "Foundation Analysis and
// Design"), which loads the part
//     [from, to] = [max(0, 1 - 3 (1 - c)), min(1, 3 c)]
// of the ruling. With c outside (0, 1) or N <= 0 the body stands on a rim
// point and the ruling carries nothing (N = 0; the rim's singular stress is
// study/rims').
//
// Held point: the stress near a loaded end of the ruling is the rim's own
// problem, so a peak pressure within `end_margin` (a fraction of the ruling)
// of a loaded end is taken at its value that far inside it:
//     held(f) = clamp(f, from + end_margin, to - end_margin),
// the middle of [from, to] where that interval is empty.
//
// Contract: RulingLoad::line_load is 0 outside [from, to] and for N = 0.
#include "core/named_values.h"
#include "oracle/rolling_dynamics.h"
#include <Eigen/Core>

namespace rollcheck::contact
{
enum class LoadRule
{
  static_through_centre_of_mass,
  dynamic,
  uniform
};
/// The rules' names ("static", "dynamic", "uniform"), read with
/// core/named_values.h's name_of and parse_named.
const NamedValues<LoadRule>& load_rule_names();

/// The body's mass properties the static and dynamic rules need.
struct RollingBodyMass
{
  Eigen::Vector3d centre_of_mass_m = Eigen::Vector3d::Zero(); ///< body frame
  double mass_kg = 1;
  double gravity_m_s2 = 9.81;
};

/// The load of one ruling: total N, centre of pressure c, the loaded part.
struct RulingLoad
{
  double normal_n = 0;     ///< N; 0: the ruling carries nothing
  double centre = 0.5;     ///< c, a fraction of the ruling from its start
  bool uniform = false;    ///< q = N / L, not the no-tension linear rule
  double from = 0, to = 1; ///< the loaded part of the ruling (fractions)

  /// q(f) (N/m) at fraction `f` of a ruling of length `length_m`.
  double line_load(double length_m, double f) const;
};

/// The rule's resultant on `sample`'s ruling before the no-tension rule: N
/// and c as above for any c (outside (0, 1) the body stands on a rim point,
/// whose load the rims' study needs), `uniform` for the uniform rule (c =
/// 1/2); from and to stay [0, 1].
RulingLoad ruling_resultant(const oracle::RollingSample& sample, LoadRule rule, double normal_load_n,
                            const RollingBodyMass& body);

/// The load of `sample`'s ruling under `rule`, F = `normal_load_n`: the
/// resultant spread by the no-tension rule, N = 0 where c is outside (0, 1).
RulingLoad ruling_load(const oracle::RollingSample& sample, LoadRule rule, double normal_load_n,
                       const RollingBodyMass& body);

/// held(f) above: where the peak pressure at fraction `f` of a ruling loaded
/// over [loaded_from, loaded_to] is taken.
double held_fraction(double f, double loaded_from, double loaded_to, double end_margin);
} // namespace rollcheck::contact
