#include "geometry/two_circle_roller.h"
#include "geometry/convex_hull.h"
#include "core/error.h"
#include "geometry/mesh_checks.h"
#include <Eigen/Geometry>
#include <cmath>
#include <fmt/format.h>
#include <numbers>

namespace rollcheck::geometry
{
namespace
{
void validate(const RollerGenome& g, double r1, int n_points)
{
  auto finite_positive = [](double x) { return std::isfinite(x) && x > 0; };
  if (!finite_positive(r1))
    throw InputError(fmt::format("roller: radius r1 must be positive and finite, got {} m", r1));
  if (!finite_positive(g.ratio))
    throw InputError(fmt::format("roller: radius ratio rho must be positive and finite, got {}", g.ratio));
  if (!std::isfinite(g.offset) || g.offset < 0)
    throw InputError(fmt::format("roller: offset d must be non-negative and finite, got {}", g.offset));
  if (!std::isfinite(g.theta_deg))
    throw InputError(fmt::format("roller: theta must be finite, got {} deg", g.theta_deg));
  if (g.n_circles < 2)
    throw InputError(fmt::format("roller: needs at least 2 circles, got {}", g.n_circles));
  if (n_points < 3)
    throw InputError(fmt::format("roller: needs at least 3 points per circle, got {}", n_points));
}

/// Circle of radius r in the xz-plane about the origin, sampled at t_k = 2 pi k / n.
Vertices circle_in_xz(double r, int n)
{
  Vertices c(n, 3);
  for (int k = 0; k < n; ++k)
  {
    const double t = 2 * std::numbers::pi * k / n;
    c.row(k) << r * std::cos(t), 0.0, r * std::sin(t);
  }
  return c;
}
} // namespace

Vertices roller_points(const RollerGenome& g, RollerFamily family, double r1, int n_points)
{
  validate(g, r1, n_points);
  const double theta = g.theta_deg * std::numbers::pi / 180;
  const double r2 = g.ratio * r1;
  Vertices points(static_cast<Eigen::Index>(g.n_circles) * n_points, 3);
  if (g.n_circles == 2)
  {
    const Eigen::Vector3d turn_axis = family == RollerFamily::paper ? Eigen::Vector3d::UnitZ()
                                                                     : Eigen::Vector3d::UnitX();
    const Eigen::Matrix3d turn = Eigen::AngleAxisd(theta, turn_axis).toRotationMatrix();
    points.topRows(n_points) = circle_in_xz(r1, n_points);
    Vertices c2 = circle_in_xz(r2, n_points) * turn.transpose();
    c2.col(0).array() += g.offset * r1;
    points.bottomRows(n_points) = c2;
    return points;
  }
  // The reference's n-circle rollers: circle i tilted by theta about x, turned
  // to azimuth 2 pi i / n about z and moved out radially by d r1.
  const Eigen::Matrix3d tilt = Eigen::AngleAxisd(theta, Eigen::Vector3d::UnitX()).toRotationMatrix();
  for (int i = 0; i < g.n_circles; ++i)
  {
    const double azimuth = 2 * std::numbers::pi * i / g.n_circles;
    const Eigen::Matrix3d turn = Eigen::AngleAxisd(azimuth, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    Vertices ci = circle_in_xz(i == 0 ? r1 : r2, n_points) * (turn * tilt).transpose();
    ci.col(0).array() += g.offset * r1 * std::cos(azimuth);
    ci.col(1).array() += g.offset * r1 * std::sin(azimuth);
    points.middleRows(static_cast<Eigen::Index>(i) * n_points, n_points) = ci;
  }
  return points;
}

SurfaceMesh two_circle_roller(const RollerGenome& g, RollerFamily family, double r1, int n_points)
{
  const std::string name = fmt::format("{} roller (theta={} deg, d={}, rho={}, n={})",
                                       family == RollerFamily::paper ? "paper-family" : "centre-line-family",
                                       g.theta_deg, g.offset, g.ratio, g.n_circles);
  SurfaceMesh mesh = convex_hull(roller_points(g, family, r1, n_points), name);
  require_closed_convex(mesh, name);
  return mesh;
}
} // namespace rollcheck::geometry
