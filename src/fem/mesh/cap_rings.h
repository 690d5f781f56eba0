#pragma once
// The rings of the structured mesh of the 3D Hertz scene's contact cap
// (fem/mesh/hertz_mesh.h): the radii s_0 = 0 < s_1 < ... < s_n = s_cap,
// s the distance from the axis through the first point of contact, at which
// the cap's surface nodes lie, and the segments of each ring.
//
// Inside the contact the rings are equally spaced, s_k = k h for
// k = 0..K, h = c / (K + 1/2), K = max(1, ceil(c / h_0 - 1/2)) (h <= h_0):
// the contact's edge radius c lies exactly midway between the rings K and
// K + 1, no node within h / 2 of it, where the Hertz pressure
// p0 sqrt(1 - s^2 / c^2) has an unbounded slope (a node a small fraction of
// a spacing inside or outside the discrete edge, 0.1-0.6 % off c, reads
// several per cent of p0); and a node's neighbour rings lie h inside and
// outside it, so that its patch puts as much area on either side (the
// lumped recovery F_i / A_i reads the pressure at the patch's centroid).
// Beyond the edge the gaps grow from h by g per unit of distance from
// c + h / 2 up to h_far, scaled by one factor to end at s_cap exactly (the
// last gap dropped first if it overshoots by more than half of it).
//
// Ring j > 0 has m_j = min(M, 2^round(log2((pi / 2) s_j / h))) segments of
// equal angle over the quarter circle, M = 2^round(log2((pi / 2) c / h_t))
// for a segment length h_t along the edge's rings: the segments within a
// factor sqrt(2) of h below M (near-equilateral triangles), doubling from
// one ring to the next where they change (each inner segment facing two
// outer ones, its two triangles and the one between them mirror images),
// M on every ring from the edge outwards. Ring 0 is the pole (m_0 = 0).
//
// Node angles: ring j's nodes lie at t = k pi / (2 m_j), k = 0..m_j; in a
// run of rings of as many segments, every second one counted from the run's
// first is staggered, its nodes at t = (k + 1/2) pi / (2 m_j), k = 0..m_j - 1,
// and at the symmetry planes t = 0 and pi / 2. Between rings, triangles join
// the nodes in the order of their segments' midpoint angles: a hexagonal
// lattice, each node's patch mirror-symmetric across its ring and across
// its radius (as is the half patch of a node in a symmetry plane with its
// mirror image), every node but the planes' of six triangles.
#include <vector>

namespace rollcheck::fem
{
struct CapRingDesign
{
  double edge_radius_m;  ///< c, midway between two rings
  double spacing_m;      ///< h_0, the largest spacing of the rings inside the contact
  double far_spacing_m;  ///< h_far, the largest gap beyond it
  double edge_segment_m; ///< h_t, the segment length along the edge's rings
  double cap_radius_m;   ///< s_cap, the last ring
  double growth;         ///< g, m/m
};

struct CapRings
{
  std::vector<double> radius_m; ///< s_0 = 0 < ... < s_n = s_cap; empty: no structured cap
  std::vector<int> segments;    ///< m_j per ring (m_0 = 0)
  std::vector<std::vector<double>> angles_rad; ///< ring j's node angles t, from 0 to pi / 2 ({0} at the pole)
};

/// The rings of `design`. InputError unless every size is positive and
/// finite, h_0 <= h_far and c + h_0 < s_cap.
CapRings cap_rings(const CapRingDesign& design);
} // namespace rollcheck::fem
