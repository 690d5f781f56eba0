#pragma once
// The rim end's edge crossing the ruling obliquely (fem/mesh/rim_end_geometry.h
// RimEndGeometry::crossing_angle_rad): the angle c in the contact plane
// between the ruling (x) and the rim's edge, 90 deg for today's square
// crossing. The edge runs along t = (cos c, sin c, 0) through the origin; the
// other face is the plane through it whose angle with the sheet, measured
// normal to the edge, is the dihedral angle D, and whose trace in the
// ruling's vertical plane y = 0 is the section angle S. With phi = 90 deg - c
// (the angle between the ruling and the rim's normal, contact/rim_dihedral_angle.h)
//     tan S = cos(phi) tan D = sin(c) tan D,
// both in (0, 180) deg on the same side of 90 deg. The other face's outward
// normal is (sin D sin c, -sin D cos c, cos D): the square end's
// (sin S, 0, cos S) turned about y by D - 90 deg, then about z by c - 90 deg.
// At c = 90 deg (to 1e-12 rad) each function returns the square end's value exactly
// (bit-identical to the model without the crossing).

namespace rollcheck::fem
{
/// Whether the edge crosses the ruling at other than 90 deg (to 1e-12 rad).
bool crosses_obliquely(double crossing_angle_rad);

/// D from S and c: atan2(sin S, cos S sin c); S itself at c = 90 deg.
double oblique_dihedral_angle(double section_angle_rad, double crossing_angle_rad);

/// x of the sharp edge at (y, z) (z the sheet's height there):
///     x = y cot c - z cot D / sin c,
/// -z cot S at c = 90 deg.
double oblique_edge_x(double section_angle_rad, double crossing_angle_rad, double y, double z);

/// (x', y'): the point's distance beyond the edge along its normal in the
/// contact plane, x' = x sin c - y cos c, and its distance |y| from the
/// ruling's centre line; (x, y) at c = 90 deg.
void oblique_edge_frame(double crossing_angle_rad, double x, double y, double& normal_m, double& across_m);
} // namespace rollcheck::fem
