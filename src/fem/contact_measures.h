#pragma once
// Contact size, peak pressure and subsurface maxima from nodal data.
//
// Contact size and peak pressure: a least-squares fit of the Hertz form
// p^2 = p0^2 (1 - s^2 / c^2) (s the distance from the axis or symmetry plane,
// c = a or b) to the nodes carrying at least half the largest nodal pressure
// (s < 0.87 c). Its two parameters come from the interior of the contact:
// not from the edge, which the penalty smears over about one element, nor
// from the single node at the pole, whose pressure scatters with the shape of
// its element patch (3D) or sits on the axis (axisymmetric). How well the
// form fits is measured separately (HertzResult::profile_rms_error). The
// outermost zero of the nodal gap is reported beside it (contact_edge).
//
// Subsurface maxima on the axis (x = 0 in 2D, the z axis in 3D): the depth
// band is where the axis nodes come within 3 % of the largest one; every node
// of that band within a small distance s of the axis enters a least-squares
// fit f = sum_j c_j t^j + d s^2 (t the depth, cubic from eight nodes on,
// quadratic below), whose maximum on the axis is the result. The maxima are
// flat, so a three-point parabola would let the nodal scatter of the
// recovered stress (about 1e-3 p0 in 2D, 2e-3 p0 in 3D) move the depth by
// several per cent; the cubic absorbs the skew of the profile (on exact
// Hertz data the depth comes out within 0.1 %), the nodes next to the axis
// average the scatter, and the s^2 term their offset from it.
#include <vector>

namespace rollcheck::fem
{
struct SurfaceNode
{
  double s;        ///< distance from the axis (point) or symmetry plane (line), m
  double pressure; ///< Pa
  double gap;      ///< z + u_z, m; negative where the node penetrates the plane
};

struct ProfileFit
{
  double peak_pressure_pa; ///< sqrt(A) of p^2 = A - B s^2
  double contact_size_m;   ///< sqrt(A / B)
  int nodes_used;
};

/// Fits the nodes with pressure >= peak / 2. Returns nodes_used < 2 (and zero
/// sizes) when fewer than two distinct radii qualify.
ProfileFit fit_hertz_profile(const std::vector<SurfaceNode>& nodes, double peak_pressure_pa);

/// Outermost zero of the gap along s (linear between the nodes around it);
/// 0 if no node penetrates.
double contact_edge(std::vector<SurfaceNode> nodes);

struct AxisNode
{
  double depth; ///< m below the plane
  double s;     ///< distance from the axis, m
  double value;
};
struct DepthMaximum
{
  double value;
  double depth_m;
};
/// `nodes` near the axis; those with s <= axis_tolerance are on it.
DepthMaximum maximum_along_axis(std::vector<AxisNode> nodes, double axis_tolerance);
} // namespace rollcheck::fem
