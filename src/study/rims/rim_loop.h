#pragma once
// The rims over a body's rolling loop (docs/methods/rims.md): the 3D end
// model (fem/scenes/rim_end_contact.h) at every loaded ruling end of the
// orientations fem-sds solves directly, and FEM-SDS and FEM-FDS over every
// sample of the loop with the ends' pressures in them (study/loop_scores/loop_sds.h).
//
// A ruling end is loaded where the contact's load reaches a rim; its section
// angle in the ruling's vertical plane is 90 deg + the rim's lean
// (contact/rim_overhang.h), its dihedral angle normal to the rim
// (contact/rim_dihedral_angle.h) the wedge's: the rim crosses the ruling
// obliquely, and the edge's singularity and the end model (its edge square
// to the ruling) take the dihedral angle. At each such end
// of the K orientations the end model runs at the end's own line load q and
// radius R across the ruling: a sharp edge is singular (the wedge's exponent
// below 0: a > 90 deg on the rigid plane, a > 77.45 deg on a steel block) or
// has a converged end/interior ratio; a rounded edge has a converged ratio
// when its boundary layer is resolved (fem/scenes/rim_end_contact.h).
//
// Over the whole loop the end's pressure is taken as the end/interior ratio
// times the FEM pressure at the end (study/rims/end_ratios.h). The ratio
// comes from a table (study/rims/end_table.h): end models at evenly spaced
// dihedral angles across the loop's range, and for a rounded edge at
// geometrically spaced R across the range of the loop's ends (its columns),
// all at the directly modelled ends' median q, interpolated linearly in the
// angle and in log R. A rounded end's ratio depends on r_e /
// R (its boundary layer s / b = 2 r_e / (pi R)) far more than on q
// (measured: docs/results/rim-ends.md#a-rounded-ends-ratio-against-r-and-q). A
// sharp edge's ratio has no such length: one column, at the median q and R.
// The table is a reduction and is checked twice: against the direct end
// models at their own q and R (`table_vs_direct`), and by the end-aware
// scores from every other node of the table, in both directions (the change
// when its nodes halve). A sharp edge's singular ends make the end-aware
// scores singular: reported as such, with the number of loaded ends that are.
//
// A rounded edge's flattest ends (section angle from flat_rim_from_rad,
// 160 deg, on; where half-space theory is refused at some nodes, from
// flat_rim_table_start's) take the flat-rim table instead
// (study/rims/flat_rim_table.h): the loop's own
// ends at angles 2.5 deg apart up to its flattest (study/rims/flattest_loop_ends.h),
// solved in 3D by half-space theory on the hull's own surface with the
// ruling's own load and the body's balance (study/rims/flat_rim_contact.h); an
// end's pressure is the table's peak at its angle (interpolated: the
// ends near the flattest are one family per side, whose c, q and R follow
// the angle) times the slices' factor. The straight rim of the FEM end
// model is the weaker reduction there: it overstates the oloid's flattest
// ends' pressure against the body's own end (docs/methods/flat-rim.md).
// A side on a short ruling whose shortened window does not converge is
// solved over its whole loaded ruling instead (study::needs_whole_ruling).
//
// A rounded edge stands for a finished part, the hull rounded by a ball of
// radius r_e rolled inside it: no radius of its surface is below r_e. Near a
// sheet's apex the hull's R -> 0 at a ruling's end (the oloid's: where the
// centre of pressure lies a quarter of the ruling from one end, whose ruling
// touches the rim's circle there, R falling linearly to 0), its line Hertz
// pressure grows without bound and its b / R leaves line contact; the
// finished part's end is taken at R = r_e (study/loop_scores/loop_sds.h
// loop_scores::end_aware_scores; the direct ends too).
//
// The result's JSON: study/rims/rim_loop_json.cpp; its text report:
// study/rims/rim_report.h.
#include "fem/scenes/rim_end_contact.h"
#include "study/loop_scores/fem_sds.h"
#include "study/rims/end_ratios.h"
#include "study/rims/end_table.h"
#include "study/rims/flat_rim_table.h"
#include "study/rims/loop_largest_end.h"
#include "study/rims/rule_loop_samples.h"
#include <cstddef>
#include <mpi.h>
#include <nlohmann/json.hpp>
#include <numbers>
#include <optional>
#include <vector>

namespace rollcheck::study::rims
{
struct RimLoopSettings
{
  /// The body, its loop, the K orientations solved directly (6: the ends
  /// of 12 loaded rulings), F and the material (which the end models share),
  /// and the load rule (loop.load_rule, study/rims/rule_loop_samples.h): how
  /// F is spread along each sample's ruling, which sets each loaded end's q
  /// and the interior's pressures alike.
  loop_scores::FemSdsSettings loop = [] {
    loop_scores::FemSdsSettings s;
    s.orientations = 6;
    return s;
  }();
  /// The end models: counter-face, edge radius, mesh levels, tolerance. Their
  /// radius, line load, interior angle and material are set per end, and
  /// with a rounded edge the depth H / b at least depth_over_edge_radius
  /// r_e / b of the end.
  fem::RimEndSettings end;
  /// A rounded edge: every end model's block at least this many r_e deep
  /// however small the end's b (above 1 / fem::largest_edge_radius_over_depth,
  /// for the fillet to fit). Not a reduction to make freely: an acute end's
  /// ratio depends on it (docs/results/rim-ends.md#the-blocks-depth: 8 % higher at
  /// 4 r_e than at 10.5 r_e at 66.7 deg, R = r_e).
  double depth_over_edge_radius = 10.5;
  /// Largest spacing of the end table's nodes over the dihedral angle.
  double end_table_step_rad = 10 * std::numbers::pi / 180;
  /// Below the square end (90 deg), if positive, the largest spacing there
  /// instead, with a node at 90 deg: an acute rounded end's ratio rises
  /// steeply towards 90 deg and bends (the preprint's body at R = 8.2 mm:
  /// 2.369, 3.075, 3.347 at 60, 87.5, 115 deg), above it is nearly flat, so
  /// a table even in the angle misses the acute ends first (docs/notes/rims-log.md).
  double end_table_acute_step_rad = 0;
  /// A rounded edge: the largest ratio between neighbouring columns' R in
  /// the end table (> 1), or 0 for one column at the direct ends' median q
  /// and R (the reduction that put the preprint's body's table 4.7 % from its
  /// direct ends, docs/methods/rims.md).
  double end_table_radius_step = 2;
  /// A rounded edge's ends of at least this section angle are solved in 3D
  /// on the body's own loop by half-space theory (flat-rim: its surface, its
  /// load along the ruling, its balance), nodes at most flat_rim_step_rad
  /// apart up to the loop's flattest end; the FEM end table stops there. pi:
  /// never. Half-space theory is checked against the FEM end model at 160
  /// and 170 deg (docs/methods/flat-rim.md).
  double flat_rim_from_rad = 160 * std::numbers::pi / 180;
  double flat_rim_step_rad = 2.5 * std::numbers::pi / 180;
  /// A rounded edge's ends (direct and end table nodes) of at least this
  /// dihedral angle whose fillet is at least
  /// smallest_half_space_edge_over_half_width b take the end by half-space
  /// theory held as deep as their block (study/rims/half_space_end.h)
  /// instead of the FEM end model: seconds instead of minutes to hours
  /// where r_e >> b, 0.6-3.4 % above the FEM from 120 deg at R / r_e = 1
  /// to 100 (docs/methods/rims.md#half-space-theory-as-a-reduction). pi: never.
  double half_space_from_rad = std::numbers::pi;
  /// Also score the loop under the two other load rules (in the order of
  /// contact::load_rule_names), sharing the interior's FEM, the flat-rim
  /// table and the end table (whose range and reached nodes then cover every
  /// rule's ends); the direct ends, the end table's q and its check are
  /// loop.load_rule's.
  bool each_load_rule = false;
};

/// The loop under one load rule: its samples' scores with the end-aware
/// ones, and where its largest end pressure sits.
struct RuleLoop
{
  contact::LoadRule rule = contact::LoadRule::dynamic;
  loop_scores::LoopSds loop;
  std::optional<LoopLargestEnd> largest_end;
};

/// One loaded ruling end of a directly solved orientation.
struct RimLoopEnd
{
  std::size_t orientation = 0;       ///< loop_scores::FemSdsOrientation::index
  int end = 0;                       ///< 0 the ruling's start, 1 its end
  double section_angle_rad = 0;      ///< the section in the ruling's vertical plane: 90 deg + the rim's lean
  /// Normal to the rim (contact/rim_dihedral_angle.h): the wedge's angle,
  /// which the end model (its edge square to the ruling) and the end table take.
  double dihedral_angle_rad = 0;
  double modelled_angle_rad = 0;     ///< the dihedral within the end model's [60, 179.5] deg ([60, 170] rounded)
  fem::RimEndStudy study;            ///< at the end's q and R (no levels when outside the model)
  /// Set where the end was solved by half-space theory (RimLoopSettings::
  /// half_space_from_rad); `study` then holds what the loop reads of it.
  std::optional<HalfSpaceEndStudy> half_space;
  /// Why the end model cannot stand for this end (empty: it does): b / R
  /// beyond fem::largest_half_width_over_radius, where the ruling ends near
  /// the apex of its sheet and the contact there is no line contact.
  std::string outside_model;
  /// The orientation's FEM peak along the ruling (fem-sds's slices, under
  /// the static load); 0 under another load rule, whose ruling fem-sds did not solve.
  double interior_peak_pa = 0;
  /// end_to_interior times the end model's interior pressure (none: singular or not converged).
  std::optional<double> end_peak_pa;
  std::optional<double> table_ratio; ///< the end table's ratio at this angle (none: singular)
};

struct RimLoopResult
{
  fem::RimEndSettings end_setup;     ///< the settings' end models (counter-face, edge, material)
  loop_scores::FemSdsResult fem_sds;              ///< the interior: loop scores and the K orientations
  contact::LoadRule load_rule = contact::LoadRule::dynamic; ///< the settings' loop.load_rule
  std::vector<RimLoopEnd> ends;
  /// RimLoopSettings::half_space_from_rad: from this dihedral angle the
  /// rounded ends with r_e >= 20 b were solved by half-space theory (pi: none).
  double half_space_from_rad = std::numbers::pi;
  /// The directly modelled ends' median q and R: the end table's q, and
  /// its R when it has one column.
  double reference_load_n_per_m = 0, reference_radius_m = 0;
  /// Dihedral angles above this are singular (a sharp edge; pi when rounded).
  double singular_from_rad = 0;
  /// The loaded ends' dihedral angles over the loop (none loaded: 0, 0).
  double loaded_end_dihedral_min_rad = 0, loaded_end_dihedral_max_rad = 0;
  /// Over the loop's loaded ends, a sharp edge's wedge exponent at the
  /// dihedral angle less that at the section angle (end_table.h
  /// sharp_edge_exponent): how much too negative the section made it, on
  /// average and at most.
  double exponent_shift_mean = 0, exponent_shift_max = 0;
  /// Over the dihedral angles of the loop's non-singular loaded ends whose
  /// section angle lies below flat_from_rad, column by column (ascending R),
  /// each over the angles.
  std::vector<EndTableNode> table;
  /// Ends of this section angle on take the flat-rim table's ratio (pi: none do).
  double flat_from_rad = std::numbers::pi;
  std::vector<FlatRimNode> flat_table;
  /// Why the flat-rim table does not start at flat_rim_from_rad although
  /// the loop has ends there: the refused nodes, or why there is none
  /// (empty: it starts there, or none was due).
  std::string flat_rim_refused;
  /// Largest |table - direct| of the end/interior ratio over the direct ends
  /// with one, over the larger of the direct ratio and 1 (the interior).
  std::optional<double> table_vs_direct;
  bool table_converged = true;       ///< every node's end model converged (the flat-rim table's too)
  /// Where the largest end pressure over the loop sits (none without an
  /// end that has one).
  std::optional<LoopLargestEnd> largest_end;
  /// The loop's scores under the load rule (fem_sds.loop's for the static
  /// rule) with the end-aware ones: [0] the table, [1] every other node
  /// (absent with fewer than 3 nodes).
  loop_scores::LoopSds loop;
  double wall_s = 0;

  /// Largest end/interior peak over the directly modelled ends that have one.
  std::optional<double> worst_end_to_interior() const;
  /// The loop under the other load rules (RimLoopSettings::each_load_rule;
  /// empty without it).
  std::vector<RuleLoop> other_rules;
  /// The accessors below for the loop under another rule: `of` a RuleLoop's loop.
  std::optional<double> loop_end_to_interior(const loop_scores::LoopSds& of) const;
  std::optional<double> covered_end_to_interior(const loop_scores::LoopSds& of) const;
  std::optional<double> covered_limit_change(const loop_scores::LoopSds& of) const;
  std::string end_aware_status(const loop_scores::LoopSds& of) const;
  /// Over every sample of the loop: the largest end pressure (the table's)
  /// over the largest interior pressure (FEM-SDS's mapped points); none when
  /// an end is singular or outside the model, or no sample loads a rim.
  std::optional<double> loop_end_to_interior() const;
  /// The same over the loaded ends the end model covers (b / R below
  /// fem::largest_half_width_over_radius); none when an end is singular or
  /// no end is covered. Equals loop_end_to_interior when every end is covered.
  std::optional<double> covered_end_to_interior() const;
  /// covered_end_to_interior's change when the limit on b / R halves (none
  /// without ends below half the limit): beyond the loop's tolerance, the
  /// covered ends' largest pressure is set by the limit, not converged.
  std::optional<double> covered_limit_change() const;
  /// In words: singular, converged, or not converged and why.
  std::string end_aware_status() const;
  /// Where the two tables meet (none without both, or without the end
  /// table's ratios there): the FEM end model (a straight rim under a
  /// uniform load) against the body's own end (flat-rim) at its first node,
  /// of section angle flat_from_rad: the end table read at that node's
  /// dihedral angle (flat_rim_seam_dihedral), at the R of its side with the
  /// largest ratio (held to r_e).
  struct FlatRimSeam
  {
    double dihedral_angle_rad = 0;
    double sheet_radius_m = 0;
    double end_table_ratio = 0;
    double flat_rim_ratio = 0;
  };
  std::optional<FlatRimSeam> flat_rim_seam() const;
  /// The seam's R (with a flat-rim table).
  double flat_rim_seam_radius() const;
  /// The seam's angle in the end table (with a flat-rim table): the first
  /// flat-rim node's dihedral angle, held to the end model's range.
  double flat_rim_seam_dihedral() const;
};

/// `e` resolved as the loop resolves every end model: the fillet's boundary
/// layer resolved, one extra level where the last two differ, and for a
/// rounded edge the block at least `depth_over_edge_radius` r_e deep (b
/// varies from end to end, so H / b is deepened where it is too shallow).
fem::RimEndSettings resolved_as_loop_end(fem::RimEndSettings e, double depth_over_edge_radius);

/// Collective on `comm` (every rank gets the result). The end's counter-face
/// sets the loop's too (settings.loop.elastic_plane: a steel block gives the
/// slices the pair's E*). InputError naming the setting for bad settings;
/// ComputationError from the FEM.
RimLoopResult run_rim_loop(MPI_Comm comm, const RimLoopSettings& settings);

// The loop's JSON (study/rims/rim_loop_json.cpp; an end table's node and a
// flat-rim node's beside their structs).
nlohmann::json to_json(const RimLoopEnd& end);
nlohmann::json to_json(const RimLoopResult& result);
} // namespace rollcheck::study::rims
