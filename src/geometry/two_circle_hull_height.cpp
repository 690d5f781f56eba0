#include "geometry/two_circle_hull_height.h"
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>

namespace rollcheck::geometry
{
Eigen::Vector3d SpaceCircle::at(double t) const
{
  return centre + radius_m * (std::cos(t) * first_axis + std::sin(t) * second_axis);
}

namespace
{
/// The lowest height over `point` of the segments from a.at(t) to b.
double segments_height(const SpaceCircle& a, const SpaceCircle& b, const GroundFrame& ground, double t,
                       const Eigen::Vector2d& point)
{
  const auto plane = [&](const Eigen::Vector3d& v) {
    return Eigen::Vector2d((v - ground.origin).dot(ground.along), (v - ground.origin).dot(ground.across));
  };
  const auto height = [&](const Eigen::Vector3d& v) { return (ground.origin - v).dot(ground.down); };
  const Eigen::Vector3d from = a.at(t);
  const Eigen::Vector2d start = plane(from);
  const Eigen::Vector2d towards = point - start;
  const double reach = towards.norm();
  if (reach < 1e-15)
    return height(from);
  const Eigen::Vector2d normal(-towards.y() / reach, towards.x() / reach);
  // B's projection, centre + r (cos s e1' + sin s e2'), meets the line through
  // `start` along `towards` where k0 + kc cos s + ks sin s = 0.
  const Eigen::Vector2d centre = plane(b.centre);
  const Eigen::Vector2d e1(b.first_axis.dot(ground.along), b.first_axis.dot(ground.across));
  const Eigen::Vector2d e2(b.second_axis.dot(ground.along), b.second_axis.dot(ground.across));
  const double k0 = normal.dot(centre - start), kc = b.radius_m * normal.dot(e1), ks = b.radius_m * normal.dot(e2);
  const double amplitude = std::hypot(kc, ks);
  if (amplitude < std::abs(k0))
    return std::numeric_limits<double>::infinity();
  const double phase = std::atan2(ks, kc), spread = std::acos(std::clamp(-k0 / amplitude, -1.0, 1.0));
  double lowest = std::numeric_limits<double>::infinity();
  for (const double s : {phase + spread, phase - spread})
  {
    const Eigen::Vector3d to = b.at(s);
    const double beyond = (plane(to) - start).dot(towards) / reach;
    if (beyond >= reach)
      lowest = std::min(lowest, height(from) + reach / beyond * (height(to) - height(from)));
  }
  return lowest;
}

/// The height over `point` of circle c's disc (+infinity where the vertical
/// line misses it).
double disc_height(const SpaceCircle& c, const GroundFrame& ground, const Eigen::Vector2d& point)
{
  const Eigen::Vector3d normal = c.first_axis.cross(c.second_axis);
  const double tilt = normal.dot(ground.down);
  if (std::abs(tilt) < 1e-12)
    return std::numeric_limits<double>::infinity();
  const Eigen::Vector3d foot = ground.origin + point.x() * ground.along + point.y() * ground.across;
  const double z = normal.dot(foot - c.centre) / tilt;
  return (foot - z * ground.down - c.centre).norm() <= c.radius_m ? z : std::numeric_limits<double>::infinity();
}
} // namespace

double two_circle_hull_height(const SpaceCircle& a, const SpaceCircle& b, const GroundFrame& ground,
                              const SegmentSearch& search, double along_m, double across_m)
{
  const Eigen::Vector2d point(along_m, across_m);
  const auto at = [&](double t) { return segments_height(a, b, ground, t, point); };
  const int samples = std::max(search.samples, 3);
  const double step = (search.last_t - search.first_t) / (samples - 1);
  int best = 0;
  double lowest = std::numeric_limits<double>::infinity();
  for (int k = 0; k < samples; ++k)
    if (const double z = at(search.first_t + k * step); z < lowest)
    {
      lowest = z;
      best = k;
    }
  // A disc, where it is a face of the hull, lies lower than every segment;
  // elsewhere it lies inside the hull, above its lower surface.
  const double discs = std::min(disc_height(a, ground, point), disc_height(b, ground, point));
  if (!std::isfinite(lowest))
    return discs;
  // Golden-section search between the best sample's neighbours.
  const double ratio = (std::sqrt(5.0) - 1) / 2;
  double lo = search.first_t + std::max(best - 1, 0) * step, hi = search.first_t + std::min(best + 1, samples - 1) * step;
  double m1 = hi - ratio * (hi - lo), m2 = lo + ratio * (hi - lo);
  double f1 = at(m1), f2 = at(m2);
  for (int iteration = 0; iteration < 60 && hi - lo > 1e-14; ++iteration)
  {
    if (f1 < f2)
    {
      hi = m2;
      m2 = m1;
      f2 = f1;
      m1 = hi - ratio * (hi - lo);
      f1 = at(m1);
    }
    else
    {
      lo = m1;
      m1 = m2;
      f1 = f2;
      m2 = lo + ratio * (hi - lo);
      f2 = at(m2);
    }
  }
  return std::min({lowest, f1, f2, discs});
}
} // namespace rollcheck::geometry
