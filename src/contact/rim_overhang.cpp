#include "contact/rim_overhang.h"
#include "core/error.h"
#include <Eigen/Geometry>
#include <cmath>
#include <fmt/format.h>
#include <limits>
#include <numbers>

namespace rollcheck::contact
{
Eigen::Vector3d other_face_normal(std::span<const oracle::Circle> circles, int on, const Eigen::Vector3d& point,
                                  const Eigen::Vector3d& u)
{
  const oracle::Circle& c = circles[static_cast<std::size_t>(on)];
  Eigen::Vector3d radial = point - c.centre_m;
  radial -= radial.dot(c.normal) * c.normal;
  if (!(radial.norm() > 0))
    throw ComputationError("rim overhang: the ruling end is the centre of its circle");
  radial.normalize();
  const Eigen::Vector3d tangent = c.normal.cross(radial);
  const Eigen::Vector3d turn = tangent.cross(u).normalized();
  const double size = radial.dot(point - c.centre_m);
  // How far the other circles reach beyond `point` in the turned direction
  // (negative while `point` is the hull's support point).
  auto excess = [&](double sense, double psi) {
    const Eigen::Vector3d d = std::cos(psi) * u + sense * std::sin(psi) * turn;
    double worst = -std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < circles.size(); ++k)
      if (static_cast<int>(k) != on)
        worst = std::max(worst, oracle::circle_support(circles[k], d) - point.dot(d));
    return worst / size;
  };
  // Away from the patch in contact: the sense in which the others drop.
  const double probe = 1e-3;
  const double sense = excess(1.0, probe) < excess(-1.0, probe) ? 1.0 : -1.0;
  auto direction = [&](double psi) { return Eigen::Vector3d(std::cos(psi) * u + sense * std::sin(psi) * turn); };
  // The turn ends where another circle reaches `point`'s height again, or
  // where the direction leaves the circle's outward side (the circle's flat
  // face, whose normal is +-c.normal, then is the other face).
  auto done = [&](double psi) { return excess(sense, psi) >= 0 || direction(psi).dot(radial) <= 0; };
  double lo = probe, hi = probe;
  const double step = 1e-2;
  while (!done(hi))
  {
    lo = hi;
    hi += step;
    if (hi > std::numbers::pi)
      throw ComputationError("rim overhang: no other face found within half a turn");
  }
  for (int i = 0; i < 60; ++i)
  {
    const double mid = 0.5 * (lo + hi);
    (done(mid) ? hi : lo) = mid;
  }
  return direction(lo).normalized();
}

std::array<double, 2> rim_overhang(std::span<const oracle::Circle> circles, int start_circle, int end_circle,
                                   const oracle::Ruling& ruling)
{
  const Eigen::Vector3d& u = ruling.direction;
  std::array<double, 2> overhang{};
  const std::array<std::pair<int, Eigen::Vector3d>, 2> ends{{{start_circle, ruling.start_m}, {end_circle, ruling.end_m}}};
  for (int e = 0; e < 2; ++e)
  {
    const Eigen::Vector3d into_contact = e == 0 ? ruling.axis : Eigen::Vector3d(-ruling.axis);
    const Eigen::Vector3d other = other_face_normal(circles, ends[e].first, ends[e].second, u);
    const double lean = std::atan2(-into_contact.dot(other), u.dot(other));
    overhang[static_cast<std::size_t>(e)] = std::numbers::pi / 2 - lean;
  }
  return overhang;
}
} // namespace rollcheck::contact
