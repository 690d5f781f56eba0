#pragma once
// The orientations of a two-circle body's rolling loop whose loaded ruling
// end has a given interior angle, next to the loop's flattest loaded end
// (the oloid's: 180 deg at its vertex orientations, c = 1/4 and 3/4, where
// the ruling is the rim circle's tangent and the sheet's radius across it
// falls to 0). flat-rim solves such ends in 3D (study/rims/flat_rim_contact.h).
//
// The loop is the contact curve h_1(u) = h_2(u) (oracle::trace_contact_loop);
// at each u the ruling (oracle::ruling_at), the centre of pressure c = (c_m -
// s_1) . b / L, the no-tension rule's loaded ends (the start for c < 2/3, the
// end for c > 1/3: oracle::line_load) and their interior angles, 90 deg +
// the rim's lean (contact/rim_overhang.h). The flattest loaded end is the
// loop's largest angle, refined by golden-section search between the loop's
// points about the best; from it the loop is walked both ways until the same
// end's angle falls below each target, and the crossing is bisected (on the
// chord between two points of the loop, projected onto it by ruling_at).
// body_loop_end finds a body's end of one angle from its spec (its circles
// and centre of mass).
#include "geometry/body.h"
#include "oracle/rolling_dynamics.h"
#include <Eigen/Core>
#include <array>
#include <functional>
#include <span>
#include <vector>

namespace rollcheck::study::rims
{
/// One loaded end of one orientation of a two-circle body's loop.
struct LoopEnd
{
  std::array<oracle::Circle, 2> circles;   ///< the body's; the ruling starts on [0]
  Eigen::Vector3d centre_of_mass_m = Eigen::Vector3d::Zero();
  oracle::Ruling ruling;
  int end = 0;                    ///< 0: the ruling's start (on circles[0]); 1: its end
  double centre_of_pressure = 0;  ///< c, as a fraction of the ruling from its start
  double interior_angle_rad = 0;  ///< of the rim at this end
  /// c measured from this end; the sheet's radius across the ruling here and at the other end.
  double centre_of_pressure_from_end() const { return end == 0 ? centre_of_pressure : 1 - centre_of_pressure; }
  double radius_m() const { return end == 0 ? ruling.start_radius_m : ruling.end_radius_m; }
  double other_radius_m() const { return end == 0 ? ruling.end_radius_m : ruling.start_radius_m; }
  const Eigen::Vector3d& point_m() const { return end == 0 ? ruling.start_m : ruling.end_m; }
  /// The rim's angle normal to its edge (contact/rim_dihedral_angle.h);
  /// interior_angle_rad is its section in the ruling's vertical plane.
  double dihedral_angle_rad() const;
};

/// The loop's flattest loaded end and, for each of `angles_rad` below its
/// angle, the loop's orientation on either side of it whose same end has that
/// angle ([k][0] walking the loop forwards, [k][1] backwards). InputError
/// for circles that are not two; ComputationError when the loop loads no
/// end or an angle is not reached on a side.
struct FlattestLoopEnds
{
  LoopEnd flattest;
  std::vector<std::array<LoopEnd, 2>> at_angle;
};
FlattestLoopEnds flattest_loop_ends(std::span<const oracle::Circle> circles, const Eigen::Vector3d& centre_of_mass_m,
                                    std::span<const double> angles_rad, int loop_points = 4000);
/// The same with the angles chosen from the flattest end's (a table up to
/// it): `angles_below` gets that angle (rad) and returns the angles wanted.
FlattestLoopEnds flattest_loop_ends_below(std::span<const oracle::Circle> circles,
                                          const Eigen::Vector3d& centre_of_mass_m,
                                          const std::function<std::vector<double>(double)>& angles_below,
                                          int loop_points = 4000);
/// A two-circle body at its loop's end of this interior angle (pi: the
/// loop's flattest, the oloid's vertex), on the loop's side `loop_side` (0
/// forwards, 1 backwards) from the flattest. The centre of mass is the
/// rolling loop's (oracle::mass_mesh), except the oloid's: midway between
/// its circles' centres by symmetry, exactly, so that its vertex has
/// c = 1/4 exactly. InputError for a side other than 0 or 1 and for the
/// cylinder (its ruling ends are square).
LoopEnd body_loop_end(const geometry::BodySpec& body, double interior_angle_rad, int loop_side = 0);
} // namespace rollcheck::study::rims
