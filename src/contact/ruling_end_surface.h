#pragma once
// The lower surface of a two-circle body's hull near one end of the ruling
// it stands on, over the ground: the frame has the end as its origin, x'
// along the ruling into the body and y across it, z up from the ground into
// the body (geometry/two_circle_hull_height.h: the least height over (x',
// y) of the segments between the circles and of their discs). The circle
// the end lies on is A, parametrised with t = 0 at the end; the other is B,
// with t = 0 at the ruling's other end.
//
// The surface within a few edge radii of the end lies on segments from A
// within 0.3 rad of it (3 mm at r1 = 10 mm; 0.15 rad missed the hull beyond
// the FEM-SDS optimum's 160 deg end), sampled as densely as before; where
// no segment from that arc lies over a point, every t of A is searched, so
// that +infinity means the point lies outside the body's outline on the
// ground.
#include "geometry/two_circle_hull_height.h"
#include "oracle/rolling_dynamics.h"
#include "oracle/support_set.h"
#include <array>
#include <numbers>

namespace rollcheck::contact
{
class RulingEndSurface
{
public:
  /// The hull of `circles` (the ruling starts on circles[0]) near the
  /// ruling's start (`end` 0) or end (1).
  RulingEndSurface(const std::array<oracle::Circle, 2>& circles, const oracle::Ruling& ruling, int end);
  /// z (m) above the ground at x' = along_m from the end (negative: beyond
  /// it) and y = across_m; +infinity outside the body's outline.
  double height(double along_m, double across_m) const;

private:
  geometry::SpaceCircle a_; ///< the circle the end lies on, t = 0 at the end
  geometry::SpaceCircle b_;
  geometry::GroundFrame ground_;
  geometry::SegmentSearch near_end_{-0.3, 0.3, 96};
  geometry::SegmentSearch whole_circle_{-std::numbers::pi, std::numbers::pi, 720};
};
} // namespace rollcheck::contact
