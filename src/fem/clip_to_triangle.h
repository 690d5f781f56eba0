#pragma once
// The part of a convex polygon inside a triangle, in the plane: the pieces
// over which the mortar pairs (fem/node_pairs.h) integrate an upper facet's
// projection against the lower facets beneath it.
//
// Sutherland-Hodgman clipping (I. E. Sutherland, G. W. Hodgman, Reentrant
// polygon clipping, Commun. ACM 17, 1974, 32): the polygon is clipped by the
// half-plane of each of the triangle's edges in turn; a vertex is kept where
// it lies inside (on the left of the counter-clockwise edge, or on it), and
// where an edge of the polygon crosses the clipping line the crossing point
//   p + t (q - p),  t = s_p / (s_p - s_q),  s = cross(a, b, .)
// is added. Exact up to rounding for a convex subject; the result is convex,
// its vertices in the subject's order, empty where the two do not overlap.
#include <array>
#include <vector>

namespace rollcheck::fem
{
using Point2 = std::array<double, 2>;

/// Twice the signed area of the triangle (o, a, b): positive when
/// counter-clockwise.
double cross(const Point2& o, const Point2& a, const Point2& b);

/// The barycentric coordinates of q in the (non-degenerate) triangle t.
std::array<double, 3> barycentric(const std::array<Point2, 3>& t, const Point2& q);

/// The part of the convex polygon `subject` inside the triangle `clip`
/// (either orientation).
std::vector<Point2> clip_to_triangle(std::vector<Point2> subject, std::array<Point2, 3> clip);
} // namespace rollcheck::fem
