#pragma once
// Sliding speed of a contacting face: the horizontal part of omega x r,
//   v = sqrt((omega x r)_x^2 + (omega x r)_y^2).
// What r is depends on the paper-compat switch
// sliding_velocity_about_body_origin: in the reference code, the face centroid
// with x, y measured from the body origin and z from the lowest centroid (so a
// spinning body slides even at its contact point); corrected, the face centroid
// relative to the support point, the velocity relative to the ground of a body
// rolling without slip there.
#include <Eigen/Core>
#include <cmath>

namespace rollcheck::contact
{
/// Horizontal speed of omega x r (m/s), with numpy's cross-product rounding.
inline double horizontal_speed(const Eigen::Vector3d& w, const Eigen::Vector3d& r)
{
  const double vx = w[1] * r[2] - w[2] * r[1];
  const double vy = w[2] * r[0] - w[0] * r[2];
  return std::sqrt(vx * vx + vy * vy);
}
} // namespace rollcheck::contact
