#pragma once
// The rim crossing the ruling obliquely (docs/methods/rims.md#an-oblique-end):
// the loop's most oblique rim end, solved with its edge at the real crossing
// angle (fem/scenes/rim_end_contact.h RimEndSettings::crossing_angle_rad:
// the section angle in the ruling's vertical plane, both sides of the
// ruling) and by the perpendicular reduction the rim loop uses (the edge
// square to the ruling at the dihedral angle normal to the rim,
// study/rims/rim_loop.h), at the same edge mesh levels and the same q and R.
//
// The comparison: at each level each model's end-to-interior ratio, the
// oblique model's over the reduction's less 1 (`ratio_difference`), and its
// change from level to level (the difference's mesh convergence). A sharp
// edge's ratio is its nodal pressure over the far side's (singular: it grows
// with the mesh as h_e^(lambda - 1)), compared with each model's fitted edge
// exponent against the wedge equation at the dihedral angle
// (contact/wedge_exponent.h, Williams 1952), both models' `wedge_exponent`.
// A rounded edge (end.edge_radius_m > 0, the same r_e in both models) has a
// finite ratio, its end peak over the far side's, which converges: each
// model is solved as the rim loop solves its ends (study/rims/rim_loop.h:
// the boundary layer resolved at the last level, the block at least
// `depth_over_edge_radius` r_e deep, at least one extra level) and judged
// by its own tolerance (RimEndSettings::tolerance); where both converged,
// the difference between their last levels is the verdict, within the bound
// `difference_bound`: its size plus each ratio's change over its last level
// (each below the tolerance).
//
// The most oblique end: over `samples` rulings of the body's contact loop
// (oracle/rolling_dynamics.h trace_contact_loop) every end, loaded or not,
// away from the vertex, where the ruling runs along the rim (|t . b| > 0.97,
// as tests/contact/test_rim_dihedral_angle.cpp); the one whose sharp edge's
// exponent on the rigid plane rises most from the section angle to the
// dihedral angle. Its crossing angle c (ruling to rim, in the contact plane)
// is 90 deg less phi, phi the angle between the ruling and the rim's normal
// t x u (contact/rim_dihedral_angle.h: tan S = sin(c) tan D).
#include "fem/scenes/rim_end_contact.h"
#include "geometry/body.h"
#include <cstddef>
#include <functional>
#include <mpi.h>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace rollcheck::study::rims
{
/// A rim end of the contact loop.
struct LoopRimEnd
{
  double section_angle_rad = 0;  ///< in the ruling's vertical plane (90 deg + the rim's lean)
  double dihedral_angle_rad = 0; ///< normal to the rim
  double crossing_angle_rad = 0; ///< c, in (0, 90] deg
  double exponent_shift = 0;     ///< the sharp edge's exponent on the rigid plane, dihedral less section
  std::size_t sample = 0;        ///< the ruling's index along the loop
  int end = 0;                   ///< 0: the ruling's start, 1: its end
  double sheet_radius_m = 0;     ///< the hull's R across the ruling at the end
  double ruling_length_m = 0;
  /// The static load rule's centre of pressure on the ruling (the centre of
  /// mass's foot, 0 at its start, 1 at its end), as the rim loop's
  /// (contact/contact_locus.h): the line load at the end is
  /// oracle::line_load(F, centre_of_pressure, ruling_length_m, end).
  double centre_of_pressure = 0;
};

/// The most oblique end of a two-circle body's loop (the oloid, a roller;
/// InputError for other bodies), over `samples` rulings.
LoopRimEnd most_oblique_end(const geometry::BodySpec& body, std::size_t samples);

struct ObliqueEndSettings
{
  geometry::BodySpec body;   ///< whose loop's most oblique end is solved
  std::size_t samples = 2048; ///< rulings of its loop searched
  /// Both models' q, R, material, edge, mesh and levels (its angles are the end's).
  fem::RimEndSettings end;
  /// If set, F (N): q and R are the end's own in the loop instead of
  /// end's, as the rim loop takes them (study/rims/rim_loop.h): F through the
  /// centre of mass (the static rule) and the hull's R, at least r_e.
  std::optional<double> loop_load_n;
  /// A rounded edge's block at least this many r_e deep (RimLoopSettings's).
  double depth_over_edge_radius = 10.5;
  /// If set, called on every rank as each model's level starts, with the
  /// model ("oblique" or "perpendicular"), the level (0 the first) and h_e
  /// (the end's own on_level is not called).
  std::function<void(const char* model, int level, double edge_element_m)> on_model_level;
};

/// One edge level of both models.
struct ObliqueEndLevel
{
  double edge_element_m = 0;
  /// End over interior: a sharp edge's nodal pressure, a rounded edge's end
  /// peak, over the far side's (fem::end_to_interior).
  double oblique_ratio = 0, perpendicular_ratio = 0;
  double ratio_difference = 0;                       ///< oblique / perpendicular - 1
};

struct ObliqueEndStudy
{
  LoopRimEnd end;
  fem::RimEndStudy oblique, perpendicular;
  std::vector<ObliqueEndLevel> levels;
  bool rounded = false;
  std::optional<double> loop_load_n; ///< F, where q and R are the end's own in the loop
  /// Rounded: each model's end_to_interior at its own last level, oblique
  /// over perpendicular less 1 (a model may take one level more than the
  /// other: RimEndSettings::extra_levels).
  std::optional<double> difference;
  /// Both models converged: |difference| plus each ratio's change over its
  /// last level (end_change); none otherwise.
  std::optional<double> difference_bound;
  double wall_s = 0;
};

/// Collective on `comm`: every rank gets the study. InputError for bad
/// settings (the steel block is not modelled obliquely).
ObliqueEndStudy oblique_end_study(MPI_Comm comm, const ObliqueEndSettings& settings);

nlohmann::json to_json(const ObliqueEndStudy& study);

/// The comparison as a Markdown table under a line naming the end.
std::string report(const ObliqueEndStudy& study);
} // namespace rollcheck::study::rims
