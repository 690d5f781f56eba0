#pragma once
// The rims at the two ends of a contact ruling, as the 3D slab needs them
// (fem/scenes/slab_contact.h end overhang). At an end s on circle c the body has an
// edge along the circle's tangent t. Turning the ground's normal u about t,
// away from the patch in contact, s stays a support point of the hull up to
// a last normal u': the other face at the edge. Its trace in the vertical
// plane of the ruling, cos(g) (-b) + sin(g) (-u) with b the ruling axis
// pointing into the contact at that end, has tan g = -(b . u') / (u . u');
// the overhang is 90 deg - g: 0 for a square rim (the cylinder's, where u' is
// the axis), positive for an obtuse edge, whose end pressure is singular
// against a rigid plane (docs/methods/fem-sds.md#creases). The edge's own plane, the one
// perpendicular to t, is where the wedge angle strictly belongs; the slab
// carries only this trace (its end faces contain the horizontal normal to the
// ruling).
#include "oracle/rolling_dynamics.h"
#include "oracle/support_set.h"
#include <array>
#include <span>

namespace rollcheck::contact
{
/// Overhangs (rad) at the ruling's start (on circles[start_circle]) and end
/// (on circles[end_circle]); body frame, u = ruling.direction.
std::array<double, 2> rim_overhang(std::span<const oracle::Circle> circles, int start_circle, int end_circle,
                                   const oracle::Ruling& ruling);

/// The other face's outward normal u' at the end `point` of a ruling on
/// circles[on] (see above).
Eigen::Vector3d other_face_normal(std::span<const oracle::Circle> circles, int on, const Eigen::Vector3d& point,
                                  const Eigen::Vector3d& u);
} // namespace rollcheck::contact
