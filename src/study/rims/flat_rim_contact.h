#pragma once
// A rounded rim end whose rim is nearly flat (interior angle 150-180 deg),
// in 3D by half-space theory (contact/rounded_end.h): the end of the rolling
// loop where `rim`'s FEM end model is weakest (a fillet arc shorter than its
// boundary layer, the end table's last node standing for 178.5-180 deg).
// This file joins the loop to that method: the body, its loop's loaded end,
// and the end's load from the loop's contact locus.
//
// The oloid at a vertex orientation (the default; any two-circle body's loop
// end of a given angle with `body`): at c = 1/4 (and 3/4) it stands on the
// ruling from P, rim circle A's point at -60 deg, to B's far point; the
// ruling is A's tangent at P (the rim's interior angle is 180 deg), the
// sheet's radius across the ruling falls to 0 at P (R = 2 x' / sqrt 3) and
// the contact locus's no-tension rule puts its largest line load there,
// q(P) = 8 F / (3 L) (scripts/studies/oloid_vertex.py). A part finished with
// edge radius r_e is the hull rounded by a ball of r_e rolled inside it; the
// FEM end table takes such an end as line Hertz at R = r_e times a straight
// rim's factor, an estimate from above. Here it is solved as it is; so is
// any loaded end of a two-circle body's loop (a LoopEnd,
// study/rims/flattest_loop_ends.h: the settings' body's by `end_angle_rad`,
// rim --body's flat-rim table by the loop's own angles):
//  - the surface: the hull's lower surface near the end, from the body's two
//    circles (contact/ruling_end_surface.h);
//  - the sheet's radius across the ruling linear along it, R(x') = R_0 + (R_1
//    - R_0) x' / L (exact for a developable sheet);
//  - the load: the contact locus's no-tension linear rule from the end
//    (oracle/line_load.h) carrying F with its centre at the centre of mass's
//    foot, c L from the end; beyond the window it is re-solved so that the
//    body balances (no rotation about the ruling).
// Or (`interior_angle_rad` > 0) a straight rim across a flattened sheet of
// radius R under a uniform line load q, `rim`'s one end
// (contact/straight_rim_end.h), to check this reduction against the FEM end
// model.
#include "contact/rounded_end.h"
#include "geometry/body.h"
#include "study/rims/flattest_loop_ends.h"
#include <nlohmann/json_fwd.hpp>
#include <numbers>
#include <string>

namespace rollcheck::study::rims
{
/// Below this interior angle the rim's other face is too steep for half-space theory.
constexpr double smallest_flat_rim_angle_rad = 150 * std::numbers::pi / 180;

/// The true oloid of r1 = 10 mm, the body of the rim scenes' rounded loops.
inline geometry::BodySpec rim_scene_oloid()
{
  geometry::BodySpec oloid;
  oloid.radius_m = 0.01;
  return oloid;
}

/// The method's settings (the finish, the material, the grids) and the scene's.
struct FlatRimSettings : contact::RoundedEndSettings
{
  /// A two-circle body (by default the rim scenes' oloid, r1 = 10 mm).
  geometry::BodySpec body = rim_scene_oloid();
  double normal_load_n = 800;     ///< F through the centre of mass (rim --body's)
  /// The body's loop orientation whose loaded end has this interior angle
  /// (rad): pi is the loop's flattest end (the oloid's vertex, c = 1/4),
  /// below it the orientation on the loop's side `loop_side` from there.
  double end_angle_rad = std::numbers::pi;
  int loop_side = 0;              ///< 0: walking the loop forwards, 1: backwards (the oloid's mirror image)
  /// > 0: a straight rim of this interior angle (rad) across a flattened sheet
  /// instead of the body's loop end, with:
  double interior_angle_rad = 0;
  double sheet_radius_m = 1e-3;   ///< R of that sheet
  double load_n_per_m = 1.2e5;    ///< its uniform line load q
};

using FlatRimLevel = contact::RoundedEndLevel;

/// The method's result and the end it was solved at.
struct FlatRimContact : contact::RoundedEndContact
{
  double ruling_length_m = 0;           ///< the body's
  double centre_of_pressure = 0;        ///< the body's c, as a fraction of the ruling from the end
  double interior_angle_rad = 0;        ///< of the rim at the end (its section in the ruling's vertical plane)
  double end_radius_m = 0;              ///< the hull's sheet radius across the ruling at the end
  double dihedral_angle_rad = 0;        ///< of the rim at the end, normal to its edge (contact/rim_dihedral_angle.h)
};

/// Whether a body's end solved at the settings' window wants its whole
/// ruling instead (the U optimum's 160-166 deg ends on steel).
using contact::needs_whole_ruling;

/// The settings' scene: the straight rim (interior_angle_rad > 0) or the
/// body's loop end at end_angle_rad. Throws InputError for a non-positive
/// radius, load, edge radius or modulus, an angle outside [150, 180] deg or
/// a body other than the oloids and rollers (the cylinder's ends are square),
/// ComputationError when a solve fails (contact::solve_rounded_end).
FlatRimContact flat_rim_contact(const FlatRimSettings& settings, const contact::RoundedEndProgress& progress = {});
/// A loaded end of any two-circle body's loop (study/rims/flattest_loop_ends.h),
/// its q from F (the settings' normal_load_n) and c by the locus's rule; the
/// settings' oloid and straight-rim fields are not used.
FlatRimContact flat_rim_contact(const FlatRimSettings& settings, const LoopEnd& end,
                                const contact::RoundedEndProgress& progress = {});
/// The hull's lower surface near a loop's end, as flat-rim solves it: its
/// height (m) above the ground at x' along the ruling from the end (negative:
/// beyond it) and y across (contact/ruling_end_surface.h).
double end_hull_height(const LoopEnd& end, double along_m, double across_m);

nlohmann::json to_json(const FlatRimContact& result);
/// The text report of a solve at `settings`: the scene, the levels' table
/// and the verdicts.
std::string report(const FlatRimSettings& settings, const FlatRimContact& result);
} // namespace rollcheck::study::rims
