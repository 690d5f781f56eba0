#include "contact/ruling_end_surface.h"
#include <Eigen/Geometry>
#include <cmath>

namespace rollcheck::contact
{
namespace
{
/// The circle with t = 0 at `through`, a point of it.
geometry::SpaceCircle space_circle(const oracle::Circle& c, const Eigen::Vector3d& through)
{
  const Eigen::Vector3d radial = (through - c.centre_m).normalized();
  return {c.centre_m, radial, c.normal.cross(radial), c.radius_m};
}
} // namespace

RulingEndSurface::RulingEndSurface(const std::array<oracle::Circle, 2>& circles, const oracle::Ruling& ruling, int end)
    : a_(space_circle(circles[static_cast<std::size_t>(end)], end == 0 ? ruling.start_m : ruling.end_m)),
      b_(space_circle(circles[static_cast<std::size_t>(1 - end)], end == 0 ? ruling.end_m : ruling.start_m))
{
  ground_.origin = end == 0 ? ruling.start_m : ruling.end_m;
  ground_.down = ruling.direction; // the support direction: out of the body, into the ground
  ground_.along = end == 0 ? ruling.axis : Eigen::Vector3d(-ruling.axis);
  ground_.across = ground_.down.cross(ground_.along);
}

double RulingEndSurface::height(double along_m, double across_m) const
{
  const double z = geometry::two_circle_hull_height(a_, b_, ground_, near_end_, along_m, across_m);
  return std::isfinite(z) ? z : geometry::two_circle_hull_height(a_, b_, ground_, whole_circle_, along_m, across_m);
}
} // namespace rollcheck::contact
