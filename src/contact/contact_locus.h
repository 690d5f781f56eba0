#pragma once
// The contact locus of one sampled orientation of a body that is the hull of
// circles (the two-circle rollers, the oloids, the cylinder): what the
// preprint's oracle counted and what the exact body touches, with the load
// the paper presses it with.
//
// - oracle faces: the faces whose centroid lies within the preprint's
//   threshold eps of the ground (oracle/heights.h), the set its SDS sums over;
// - support set (oracle/support_set.h): a segment (a ruling, line contact), a
//   point (the body stands on a rim) or a disc (it lies on a circle's face);
// - load: the normal force F pressed through the centre of mass, vertically,
//   as on a body at rest. On a ruling its centre of pressure is the centre of
//   mass projected onto the ruling, c = ((G - s_1) . b) / L, and the
//   no-tension linear rule of a rigid footing (oracle/contact_density.h
//   line_load) spreads it: over the whole ruling if 1/3 <= c <= 2/3, else
//   triangularly over the 3c (or 3 (1 - c)) nearest the loaded end. With c
//   outside (0, 1) the body is not in equilibrium on the ruling (it tips).
// - creases: every ruling ends on the two circles, which are the bodies'
//   edges (the oloid's rims, the cylinder's rims): where the line load at an
//   end is not zero, the contact reaches a crease. Between two elastic
//   bodies (the preprint's steel on steel) the end of an uncrowned roller
//   carries a singular edge pressure (T. A. Harris, M. N. Kotzalas, "Rolling
//   Bearing Analysis", 5th ed., 2007, ch. 6), like the edge of a flat punch
//   (K. L. Johnson, "Contact Mechanics", CUP 1985, ch. 2); against a rigid
//   frictionless plane a right-angled end is not singular (the 3D slab of
//   fem/scenes/slab_contact.h: the pressure falls towards it). Either way slices
//   near a crease are not plane strain, so the FEM takes its peaks away from
//   it. A point support on a rim and a disc support are creases by
//   themselves: the contact then holds the edge itself.
#include "geometry/surface_mesh.h"
#include "oracle/contact_density.h"
#include "oracle/rolling_body.h"
#include "oracle/rolling_dynamics.h"
#include "oracle/support_set.h"
#include <Eigen/Core>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace rollcheck::contact
{
struct ContactLocus
{
  std::size_t sample = 0;           ///< index into the oracle's samples
  double time_s = 0;                ///< of the sample
  Eigen::Matrix3d rotation;         ///< body to world
  oracle::CircleSupportSet support;
  std::optional<oracle::Ruling> ruling; ///< the contact segment (support kind segment)
  double centre_of_pressure = 0;    ///< static c along the ruling (0 at s_1, 1 at s_2)
  double loaded_from = 0;           ///< fraction of the ruling where the load starts
  double loaded_to = 0;             ///< and ends (no-tension rule)
  bool in_equilibrium = false;      ///< ruling with 0 < c < 1
  /// Where the loaded contact meets an edge of the body, in words; empty when
  /// it meets none.
  std::vector<std::string> creases;
  std::vector<int> oracle_faces;    ///< faces within the preprint's threshold
};

struct LocusSettings
{
  double contact_threshold_m = 0.04;     ///< eps (the preprint's)
  bool ground_at_lowest_centroid = true; ///< the reference's ground (PaperCompat)
  /// Circles within this fraction of the body size of the lowest height count
  /// as touching: loose enough for integrated rolling rulings (whose two ends
  /// agree to about 1e-10 of the size), far below any visible tilt.
  double support_tolerance = 1e-7;
};

/// The locus of `rotation` (body to world) for the hull of `circles` with
/// centre of mass `centre_of_mass_m` (body frame), the preprint's faces on
/// `body`. `oracle_faces`, if given, replaces the threshold search (the rigid
/// oracle's own counts). InputError for fewer than two circles.
ContactLocus contact_locus(std::span<const oracle::Circle> circles, const Eigen::Vector3d& centre_of_mass_m,
                           const oracle::RollingBody& body, const Eigen::Matrix3d& rotation,
                           const LocusSettings& options, const std::vector<int>* oracle_faces = nullptr);

/// Faces of `cones` that hold the points of the locus's ruling at the given
/// fractions (body frame); requires a ruling.
std::vector<int> faces_along_ruling(const oracle::FaceCones& cones, const ContactLocus& locus,
                                    std::span<const double> fractions);
} // namespace rollcheck::contact
