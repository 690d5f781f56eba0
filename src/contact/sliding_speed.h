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

namespace rollcheck::contact
{
/// Horizontal speed of omega x r (m/s), with numpy's cross-product rounding.
double horizontal_speed(const Eigen::Vector3d& omega, const Eigen::Vector3d& r);
} // namespace rollcheck::contact
