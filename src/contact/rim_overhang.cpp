#include "contact/rim_overhang.h"
#include "core/error.h"
#include <Eigen/Geometry>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

namespace rollcheck::contact
{
namespace
{
/// The turns psi in (0, pi) at which circle c's support in the direction
/// d(psi) = cos(psi) u + sin(psi) w reaches `point`'s: h_c(d) = point . d with
/// h_c(d) = C . d + r sqrt(1 - (m . d)^2). Writing L = (point - C) . d and
/// M = m . d, both linear in (cos, sin), the root needs L >= 0 and
/// L^2 + r^2 M^2 - r^2 (cos^2 + sin^2) = 0: a quadratic form in (cos, sin),
/// so a quadratic in tan(psi). NaN marks a root that is not there.
std::array<double, 2> support_reaches_point(const oracle::Circle& c, const Eigen::Vector3d& point,
                                            const Eigen::Vector3d& u, const Eigen::Vector3d& w)
{
  const Eigen::Vector3d q = point - c.centre_m;
  const double alpha = q.dot(u), beta = q.dot(w), gamma = c.normal.dot(u), delta = c.normal.dot(w);
  const double r2 = c.radius_m * c.radius_m;
  // A cos^2 + 2 B cos sin + D sin^2 = 0
  const double a = alpha * alpha + r2 * gamma * gamma - r2;
  const double b = alpha * beta + r2 * gamma * delta;
  const double d = beta * beta + r2 * delta * delta - r2;
  const double scale = alpha * alpha + beta * beta + r2;
  // tan(psi) of each root (infinite: psi = pi / 2), NaN where there is none.
  std::array<double, 2> tangents{std::nan(""), std::nan("")};
  const double discriminant = b * b - a * d;
  if (std::abs(d) <= 1e-14 * scale)
  {
    tangents[0] = std::numeric_limits<double>::infinity(); // cos = 0
    if (std::abs(b) > 1e-14 * scale)
      tangents[1] = -a / (2 * b);
  }
  else if (discriminant >= 0)
  {
    // The stable pair of roots of d t^2 + 2 b t + a = 0.
    const double root = std::sqrt(discriminant), k = -(b + std::copysign(root, b));
    tangents[0] = k / d;
    if (k != 0)
      tangents[1] = a / k;
  }
  std::array<double, 2> turns{std::nan(""), std::nan("")};
  for (std::size_t i = 0; i < 2; ++i)
  {
    const double t = tangents[i];
    if (std::isnan(t))
      continue;
    const double psi = std::isinf(t) ? std::numbers::pi / 2 : (t > 0 ? std::atan(t) : std::numbers::pi + std::atan(t));
    // Squaring admitted the turns where the circle's support is -L.
    if (alpha * std::cos(psi) + beta * std::sin(psi) >= -1e-12 * std::sqrt(scale))
      turns[i] = psi;
  }
  return turns;
}
} // namespace

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
  const Eigen::Vector3d w = sense * turn;
  auto direction = [&](double psi) { return Eigen::Vector3d(std::cos(psi) * u + std::sin(psi) * w); };
  if (excess(sense, probe) >= 0 || direction(probe).dot(radial) <= 0)
    return direction(probe).normalized();
  // The turn ends at the first psi where another circle reaches `point`'s
  // height again, or where the direction leaves the circle's outward side
  // (d . radial = 0; the circle's flat face, whose normal is +-c.normal, then
  // is the other face). Both in closed form.
  double end = std::atan2(u.dot(radial), -w.dot(radial));
  for (std::size_t k = 0; k < circles.size(); ++k)
    if (static_cast<int>(k) != on)
      for (double psi : support_reaches_point(circles[k], point, u, w))
        if (psi > probe) // false for NaN
          end = std::min(end, psi);
  if (!(end > probe && end <= std::numbers::pi))
    throw ComputationError("rim overhang: no other face found within half a turn");
  return direction(end).normalized();
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
