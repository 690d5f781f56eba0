#pragma once
// The rings of the structured mesh of the 3D Hertz scene's contact cap
// (fem/mesh/hertz_mesh.h): the radii s_0 = 0 < s_1 < ... < s_n = s_cap,
// s the distance from the axis through the first point of contact, at which
// the cap's surface nodes lie, and the segments of each ring.
//
// The contact's edge radius c lies exactly midway between two rings h_e
// apart, so that no node lies within h_e / 2 of the edge: where the Hertz
// pressure p0 sqrt(1 - s^2 / c^2) has an unbounded slope, a node a small
// fraction of a spacing inside or outside the discrete edge (0.1-0.6 % off
// c) reads several per cent of p0 (docs/methods/hertz-fem.md, pointwise
// accuracy in 3D).
//
// Spacing: the gap starting at radius s is
//   h(s) = min(h_far, h_e + g |s - c|, h_p + g max(0, s - r_p)),
// h_e at the edge, h_p within r_p of the pole, growing by g per unit of
// distance from either up to h_far. Each side of the edge (from c - h_e / 2
// down to 0, from c + h_e / 2 up to s_cap) takes the gaps h(s) stepped from
// the edge, the last one dropped if it overshoots by more than half, all
// scaled by one factor so that the rings end exactly at 0 and at s_cap.
// Ring j > 0 has m_j = max(1, min(M, round((pi / 2) s_j / h_j))) segments
// of equal angle over the quarter circle, h_j the mean of its two gaps (the
// last ring's one gap), M = round((pi / 2) c / h_t) the edge ring's for a
// segment length h_t: near-equilateral triangles between rings near the
// pole, and from where the rings reach M segments outwards (about the edge,
// and beyond it) all rings alike, so that every node of such a ring has
// the same patch of triangles turned about the axis (the pressure varies
// across the rings, not along them). Ring 0 is the pole (m_0 = 0).
#include <vector>

namespace rollcheck::fem
{
struct CapRingDesign
{
  double edge_radius_m;   ///< c, midway between two rings
  double edge_spacing_m;  ///< h_e, the gap across the edge
  double pole_spacing_m;  ///< h_p, within pole_radius_m of the axis
  double pole_radius_m;   ///< r_p
  double far_spacing_m;   ///< h_far, the largest gap
  double edge_segment_m;  ///< h_t, the segment length along the edge's rings
  double cap_radius_m;    ///< s_cap, the last ring
  double growth;          ///< g, m/m
};

struct CapRings
{
  std::vector<double> radius_m; ///< s_0 = 0 < ... < s_n = s_cap; empty: no structured cap
  std::vector<int> segments;    ///< m_j per ring (m_0 = 0)
};

/// The rings of `design`. InputError unless every size is positive and
/// finite, h_e <= h_far, h_p <= h_far and c + h_e / 2 < s_cap.
CapRings cap_rings(const CapRingDesign& design);
} // namespace rollcheck::fem
