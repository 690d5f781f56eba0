#pragma once
// The height of the lower surface of the convex hull of two circles above a
// ground plane that touches it, over a point of the ground. A boundary point
// of the hull of two circles lies on a segment from one circle to the other
// or on one of their discs (a face of the hull beyond some rims of the
// preprint's body; never near a ruling of the oloid, whose circle planes
// each cut the other circle), and every segment and disc lies in the hull,
// so the height over (x, y) is the least of
//   min over t of the height at (x, y) of the segments from A(t) to the
//   points B(s) whose ground projections lie on the line from A(t)'s
//   projection through (x, y), beyond (x, y),
// and the discs' heights there.
// For each t those s solve k0 + kc cos s + ks sin s = 0 in closed form; the
// minimum over t is taken over samples of [first_t, last_t] and refined by
// golden-section search about the best sample. scripts/studies/oloid_vertex.py
// computes the same surface.
#include <Eigen/Core>

namespace rollcheck::geometry
{
/// centre + radius (cos t first_axis + sin t second_axis), axes orthonormal.
struct SpaceCircle
{
  Eigen::Vector3d centre;
  Eigen::Vector3d first_axis;
  Eigen::Vector3d second_axis;
  double radius_m = 0;

  Eigen::Vector3d at(double t) const;
};

/// The ground plane through `origin` with unit normal `down` (into the
/// ground); points on it by `along` and `across`, orthonormal with `down`.
struct GroundFrame
{
  Eigen::Vector3d origin;
  Eigen::Vector3d along;
  Eigen::Vector3d across;
  Eigen::Vector3d down;
};

/// The range of circle A's parameter whose segments are searched.
struct SegmentSearch
{
  double first_t = 0;
  double last_t = 0;
  int samples = 64;
};

/// z (m) of the hull's lower surface above the ground at (along_m, across_m)
/// from the frame's origin; +infinity where no segment from A's searched
/// range lies over the point.
double two_circle_hull_height(const SpaceCircle& a, const SpaceCircle& b, const GroundFrame& ground,
                              const SegmentSearch& search, double along_m, double across_m);
} // namespace rollcheck::geometry
