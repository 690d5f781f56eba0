#pragma once
// What the stages of one whole-body check share (study/whole_body/whole_body_check.h,
// run_whole_body_check): the settings and the orientation, what follows from
// them once (E*, the stations, the whole body's sizes), and the whole body's
// mesh and solve at given sizes (the reference, and the coarse body's load
// rule). Internal to the check; not part of the wing's umbrella header.
//
// Sizes: the whole body's section is sized from the locus's line Hertz b,
//   b = sqrt(4 q R / (pi E*)),
// at the stations and the loaded ends whichever the load rule (one
// reference for every rule: its station readings move by 0.13 % at most on
// a finer strip, docs/methods/whole-body.md): contact elements b_min /
// contact_elements, the strip b_max strip_over_half_width, end layers
// body_end_layer times the smallest of the locus's b at the loaded ends.
#include "fem/scenes/whole_body_contact.h"
#include "study/whole_body/whole_body_check.h"
#include <array>
#include <cstdint>
#include <functional>
#include <mpi.h>
#include <optional>
#include <vector>

namespace rollcheck::study::whole_body
{
/// A line load along the ruling: q (N/m) at the fraction f of its length.
using LineLoad = std::function<double(double)>;

/// Line Hertz's half-width b = sqrt(4 q R / (pi E*)).
double line_half_width(double q, double R, double E_star);

/// The whole body's sizes and the locus's b they come from.
struct BodySizing
{
  fem::WholeBodySizes sizes;
  double smallest_b = 0, largest_b = 0; ///< over the stations and the loaded ends
  /// The smallest of the locus's b at the loaded ends (smallest_b if no end
  /// is loaded): the end layers, d_m and the near-edge reach.
  double smallest_end_b = 0;
};

/// Every stage's inputs. Holds references to the settings and orientation
/// it was made from, which must outlive it.
struct CheckContext
{
  CheckContext(MPI_Comm comm, const WholeBodyCheckSettings& settings, const WholeBodyOrientation& orientation);

  MPI_Comm comm;
  const WholeBodyCheckSettings& settings;
  const WholeBodyOrientation& orientation;
  double effective_modulus_pa;           ///< E* of the rigid plane
  bool log;                              ///< rank 0 logs progress
  std::vector<double> fractions;         ///< the stations, fractions of L (loop_scores::slice_fractions)
  std::array<double, 2> end_fractions;   ///< the loaded part's ends, fractions of L
  BodySizing sizing;
  /// The body's sections ray cast against its hull (fem/mesh/whole_body_mesh.h),
  /// built once for a body that is mapped (the oloid); none for the
  /// extruded cylinder.
  std::optional<fem::MappedBodyPose> pose;

  double length_m() const { return orientation.ruling.length_m; }
  double centre_of_pressure() const { return orientation.centre_of_pressure; } ///< c
  double radius_at(double f) const;      ///< R, linear along the ruling
  double locus_load_at(double f) const;  ///< the locus's q (oracle::line_load)
  /// Line Hertz's b under q at the radius R(f).
  double half_width_at(double q, double f) const { return line_half_width(q, radius_at(f), effective_modulus_pa); }
};

/// The body's pose for fem::build_mapped_body_mesh: x along the ruling from
/// its start, z = -u up from the plane, y = z x x; its sections ray cast
/// against the hull of settings.body.points n per circle (the mesh the
/// centre of mass comes from), within r (pi / n)^2 / 2 of the exact body
/// (0.3 um at n = 400, r = 10 mm: 3e-5 of r for the elastic body; the
/// contact's sheet is exact, in the initial gap).
fem::MappedBodyPose mapped_pose(const CheckContext& context);

/// One solve of the whole body and its mesh's counts.
struct BodySolve
{
  fem::WholeBodyFem fem;
  std::size_t node_planes = 0;
  std::int64_t section_nodes = 0;
  double gmsh_s = 0;
};

/// The whole body at `sizes` (extruded cylinder or mapped body) under F
/// through its centre of mass, its load control started from line contact
/// under the line load `load_at_centre` at the centre of mass's foot: the
/// line-contact estimate of the approach of a section's top at height R
/// (fem/load_control.h), the body shifted down by the height of its surface
/// at the contact's edge, b^2 / (2 R) (the slab's start).
BodySolve solve_body(const CheckContext& context, const fem::WholeBodySizes& sizes, double load_at_centre);

/// The first approach, its load exponent and the body's first shift down
/// under the line load q at the centre of mass's foot (solve_body's start).
struct RigidStart
{
  double approach_m, exponent, shift_m;
};
RigidStart rigid_start(const CheckContext& context, double load_at_centre);
} // namespace rollcheck::study::whole_body
