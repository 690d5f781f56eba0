#pragma once
// The interior dihedral angle of a rim at a ruling's end: the angle between
// the face in contact (the ground's plane, outward normal u) and the other
// face at the edge (outward normal u', contact/rim_overhang.h
// other_face_normal), measured in the plane normal to the rim's edge (the
// circle's tangent t, which both faces contain):
//     dihedral = pi - arccos(u . u').
// That plane is where a wedge's stress singularity belongs (M. L. Williams,
// J. Appl. Mech. 19, 526-528, 1952: the apex field of a straight edge is a
// field of the plane normal to it), so the exponents of
// contact/wedge_exponent.h and contact/edge_on_elastic_block_exponent.h take
// this angle. The section angle of rim_overhang (90 deg + the overhang), the
// trace in the vertical plane of the ruling, is not it where the rim crosses
// the ruling obliquely: with phi the angle in the contact plane between the
// ruling and the rim's normal n = t x u,
//     tan(pi - section) = cos(phi) tan(pi - dihedral),
// so an obtuse section angle lies above its dihedral (148.5 deg is 129 deg at
// phi = 60 deg), the two agree for a rim square to the ruling (phi = 0), and
// both exceed 90 deg together (the rigid plane's singular set is the same).
#include "oracle/rolling_dynamics.h"
#include "oracle/support_set.h"
#include <array>
#include <span>

namespace rollcheck::contact
{
/// Interior dihedral angles (rad, in (0, pi]) at the ruling's start (on
/// circles[start_circle]) and end (on circles[end_circle]); body frame, u =
/// ruling.direction. ComputationError as other_face_normal.
std::array<double, 2> rim_dihedral_angle(std::span<const oracle::Circle> circles, int start_circle, int end_circle,
                                         const oracle::Ruling& ruling);
} // namespace rollcheck::contact
