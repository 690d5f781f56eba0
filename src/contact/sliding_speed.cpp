#include "contact/sliding_speed.h"
#include <cmath>

namespace rollcheck::contact
{
double horizontal_speed(const Eigen::Vector3d& w, const Eigen::Vector3d& r)
{
  const double vx = w[1] * r[2] - w[2] * r[1];
  const double vy = w[2] * r[0] - w[0] * r[2];
  return std::sqrt(vx * vx + vy * vy);
}
} // namespace rollcheck::contact
