#include "study/rims/flattest_loop_ends.h"
#include "contact/rim_dihedral_angle.h"
#include "contact/rim_overhang.h"
#include "core/error.h"
#include "oracle/contact_density.h"
#include "oracle/rolling_study.h"
#include "oracle/support_set.h"
#include <cmath>
#include <fmt/format.h>
#include <numbers>
#include <limits>

namespace rollcheck::study::rims
{
namespace
{
/// The loop's orientation on the chord from `from` to `to` at t, projected
/// onto the contact curve, with its loaded `end`'s angle (none: not loaded).
struct Probe
{
  std::span<const oracle::Circle> circles;
  oracle::TwoCircleBody body;
  Eigen::Vector3d centre_of_mass;

  LoopEnd at(const Eigen::Vector3d& direction, int end) const
  {
    LoopEnd e;
    e.circles = {circles[0], circles[1]};
    e.centre_of_mass_m = centre_of_mass;
    e.ruling = oracle::ruling_at(body, direction);
    e.end = end;
    e.centre_of_pressure = (centre_of_mass - e.ruling.start_m).dot(e.ruling.axis) / e.ruling.length_m;
    const bool loaded = oracle::line_load(1.0, e.centre_of_pressure, e.ruling.length_m, end) > 0;
    e.interior_angle_rad = loaded ? std::numbers::pi / 2 + contact::rim_overhang(circles, 0, 1, e.ruling)[end]
                                  : -std::numeric_limits<double>::infinity();
    return e;
  }
};

Eigen::Vector3d chord(const Eigen::Vector3d& from, const Eigen::Vector3d& to, double t)
{
  return ((1 - t) * from + t * to).normalized();
}
} // namespace

FlattestLoopEnds flattest_loop_ends(std::span<const oracle::Circle> circles, const Eigen::Vector3d& centre_of_mass_m,
                                    std::span<const double> angles_rad, int loop_points)
{
  const std::vector<double> angles(angles_rad.begin(), angles_rad.end());
  return flattest_loop_ends_below(circles, centre_of_mass_m, [&angles](double) { return angles; }, loop_points);
}

FlattestLoopEnds flattest_loop_ends_below(std::span<const oracle::Circle> circles,
                                          const Eigen::Vector3d& centre_of_mass_m,
                                          const std::function<std::vector<double>(double)>& angles_below,
                                          int loop_points)
{
  if (circles.size() != 2)
    throw InputError(fmt::format("flattest loop ends: a hull of two circles is needed, got {} circles", circles.size()));
  const Probe probe{circles, oracle::two_circle_body(circles), centre_of_mass_m};
  const oracle::ContactLoop loop = oracle::trace_contact_loop(
      probe.body, oracle::contact_curve_point(probe.body, -Eigen::Vector3d::UnitZ()), loop_points);
  const auto n = static_cast<long>(loop.directions.size());
  const auto direction = [&](long k) { return loop.directions[static_cast<std::size_t>(((k % n) + n) % n)]; };

  long best_k = 0;
  int best_end = 0;
  double best_angle = -std::numeric_limits<double>::infinity();
  for (long k = 0; k < n; ++k)
    for (const int end : {0, 1})
      if (const double a = probe.at(direction(k), end).interior_angle_rad; a > best_angle)
      {
        best_angle = a;
        best_k = k;
        best_end = end;
      }
  if (!std::isfinite(best_angle))
    throw ComputationError("flattest loop ends: no orientation of the loop loads a rim end");

  // Golden-section search for the largest angle on the chords through the
  // loop's points before and after the best.
  const Eigen::Vector3d before = direction(best_k - 1), after = direction(best_k + 1);
  const auto along = [&](double t) {
    return t < 0 ? chord(direction(best_k), before, -t) : chord(direction(best_k), after, t);
  };
  const double golden = (std::sqrt(5.0) - 1) / 2;
  double lo = -1, hi = 1;
  double x1 = hi - golden * (hi - lo), x2 = lo + golden * (hi - lo);
  double f1 = probe.at(along(x1), best_end).interior_angle_rad, f2 = probe.at(along(x2), best_end).interior_angle_rad;
  while (hi - lo > 1e-6)
    if (f1 < f2)
    {
      lo = x1;
      x1 = x2;
      f1 = f2;
      x2 = lo + golden * (hi - lo);
      f2 = probe.at(along(x2), best_end).interior_angle_rad;
    }
    else
    {
      hi = x2;
      x2 = x1;
      f2 = f1;
      x1 = hi - golden * (hi - lo);
      f1 = probe.at(along(x1), best_end).interior_angle_rad;
    }
  FlattestLoopEnds result;
  result.flattest = probe.at(along(0.5 * (lo + hi)), best_end);
  if (result.flattest.interior_angle_rad < best_angle)
    result.flattest = probe.at(direction(best_k), best_end);

  for (const double target : angles_below(result.flattest.interior_angle_rad))
  {
    // The walk starts from the loop's best point, which must lie above the target.
    if (!(target < best_angle))
      throw InputError(fmt::format("flattest loop ends: {:.6g} deg is not below the loop's flattest loaded end "
                                   "({:.6g} deg; {:.6g} deg at its nearest point of {})",
                                   target * 180 / std::numbers::pi,
                                   result.flattest.interior_angle_rad * 180 / std::numbers::pi,
                                   best_angle * 180 / std::numbers::pi, n));
    std::array<LoopEnd, 2> sides;
    for (const int side : {0, 1})
    {
      const long step = side == 0 ? 1 : -1;
      long k = best_k;
      while (probe.at(direction(k + step), best_end).interior_angle_rad >= target)
        if (std::abs((k += step) - best_k) >= n)
          throw ComputationError("flattest loop ends: the loop never leaves the target angle");
      // The crossing lies on the chord from k (at or above the target) to the next point.
      const Eigen::Vector3d from = direction(k), to = direction(k + step);
      double t_lo = 0, t_hi = 1;
      while (t_hi - t_lo > 1e-9)
      {
        const double mid = 0.5 * (t_lo + t_hi);
        (probe.at(chord(from, to, mid), best_end).interior_angle_rad >= target ? t_lo : t_hi) = mid;
      }
      sides[static_cast<std::size_t>(side)] = probe.at(chord(from, to, 0.5 * (t_lo + t_hi)), best_end);
    }
    result.at_angle.push_back(sides);
  }
  return result;
}

double LoopEnd::dihedral_angle_rad() const
{
  return contact::rim_dihedral_angle(circles, 0, 1, ruling)[static_cast<std::size_t>(end)];
}

LoopEnd body_loop_end(const geometry::BodySpec& body, double interior_angle_rad, int loop_side)
{
  if (loop_side != 0 && loop_side != 1)
    throw InputError(fmt::format("flat-rim: the loop's side must be 0 (forwards) or 1 (backwards), got {}", loop_side));
  const std::vector<oracle::Circle> circles = oracle::line_contact_circles(body);
  if (body.body == "cylinder")
    throw InputError("flat-rim: body 'cylinder': its ruling ends are square (90 deg), no rim end of 150-180 deg; a "
                     "square end is `rollcheck rim --interior-angle 90`");
  const Eigen::Vector3d centre_of_mass
      = body.body == "oloid"
            ? Eigen::Vector3d(0.5 * (circles[0].centre_m + circles[1].centre_m))
            : oracle::rolling_centre_of_mass(body);
  if (interior_angle_rad >= std::numbers::pi)
    return flattest_loop_ends(circles, centre_of_mass, {}).flattest;
  const double angles[1] = {interior_angle_rad};
  return flattest_loop_ends(circles, centre_of_mass, angles).at_angle[0][loop_side];
}
} // namespace rollcheck::study::rims
