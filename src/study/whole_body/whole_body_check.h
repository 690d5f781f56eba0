#pragma once
// Issue 14's fuller check at small scale: one orientation of a body (r1 =
// 10 mm, b / L about 1e-3 at the preprint's F = 100 N on steel) meshed
// whole and pressed on the rigid plane in 3D (fem/mesh/whole_body_mesh.h,
// fem/scenes/whole_body_contact.h), against the reduced models fem-sds and rim use:
//  - along the ruling: the plane-strain slices (fem/scenes/slice_contact.h) at
//    stations between the end margins, each under the load rule's line
//    load q(s) and radius R(s): the contact locus's (contact/contact_locus.h:
//    F through the centre of mass, the no-tension linear rule; fem-sds's,
//    the default), the body's own sections' (study/whole_body/section_share.h,
//    ShareRule::sections) or the whole body's at a coarse mesh
//    (ShareRule::coarse_body); the end models under the rule's q at the
//    ends, or d_m inside them where the rule softens the ends itself
//    (EndComparison); the whole body is meshed from the locus's b under
//    every rule; its peak across the ruling at each station (its node
//    planes interpolated) against the slice's peak;
//  - at both loaded ends: the end model (fem/scenes/rim_end_contact.h) under the
//    end's q and R at its interior angle 90 deg + the rim's lean
//    (contact/rim_overhang.h), its block as deep as the whole body's held
//    section (EndModelDepth::body), a square end on the structured grid
//    (fem/mesh/scene_mesh.h build_square_end_grid_mesh: gmsh's Delaunay end at
//    that depth has about 1e6 DOFs a level) solved by MUMPS LU (GAMG stalled
//    on the deep grid). Not singular (square or acute on the rigid plane):
//    its converged edge pressure over its plane-strain interior (or, under
//    a rule that softens the ends, over its own pressure at d_m), times the
//    slice's peak at the end's q and R (or the rule's q and R at d_m), is
//    the reduced models' edge pressure, against the whole body's (mean
//    nodal pressure of the end plane's nodes with |y| <= b / 2, end layers
//    of body_end_layer b).
//    Acute: the edge's own pressure falls to zero under refinement, so the
//    largest pressure within 2 b of the edge is compared instead, converged
//    when its ratio to the far side's changes by less than `tolerance` (of
//    the larger of it and 1, the rim scene's measure) between the end
//    model's last two levels.
//    Singular (obtuse): no number is compared; the check reports the end
//    singular (the wedge's exponent; `rollcheck rim` measures its growth)
//    and does not pass; as a secondary reading only, the whole body's edge
//    against the end model's at the body's end layer (matched mesh: one
//    level, h_e the body's end layer, body_end_layer times the smaller b of
//    the locus's ends).
//  - the load distribution: the whole body's line load at each station
//    against the rule's q(s), and its centre of pressure (held at the
//    centre of mass's foot by the solver).
// PASS when every station and both ends agree within `tolerance` (3 %);
// SINGULAR ENDS when every station and every end with a value do and the
// other ends are singular; FAIL otherwise (WholeBodyOutcome).
//
// Bodies: the cylinder (its section extruded) and the oloid (the cylinder's
// reference mesh mapped onto its sections, fem/mesh/whole_body_mesh.h
// build_mapped_body_mesh); any other body is an InputError that says so.
#include "fem/scenes/rim_end_contact.h"
#include "fem/scenes/slice_contact.h"
#include "fem/scenes/whole_body_contact.h"
#include "study/whole_body/section_share.h"
#include "geometry/body.h"
#include "oracle/rolling_dynamics.h"
#include <array>
#include <cmath>
#include <mpi.h>
#include <nlohmann/json.hpp>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace rollcheck::study::whole_body
{
enum class EndModelDepth
{
  body,
  local
};

/// How the reduced models share F along the ruling: the contact locus's
/// no-tension linear rule (fem-sds's); each section's own compliance under
/// one rigid approach and tilt (study/whole_body/section_share.h); or the whole
/// body meshed coarsely (b / rule_contact_elements across the ruling, end
/// layers of rule_end_layer b, no refinement at the ends), its line load on
/// each node plane: the body's 3D compliance, the sections coupled along the
/// ruling, at a quarter of the fine mesh's DOFs. The contact's local
/// compliance is then off by its coarse strip, nearly uniformly along the
/// ruling, which the load's distribution hardly feels (docs/results/whole-body.md
/// has the measured difference from the fine body's line load). Each rule
/// is one strategy, chosen once per check (study/whole_body/share_rules.h).
enum class ShareRule
{
  locus,
  sections,
  coarse_body
};

/// Whether a rule's line load already falls towards the ends, as the body's
/// own does (the sections', the coarse body's): an end model under it is
/// matched to the rule near the edge, not at its far side, so that the
/// end's softening is not counted twice (EndComparison).
bool softens_ends(ShareRule rule);

struct WholeBodyCheckSettings
{
  /// The body: its r1 (radius_m), the cylinder's height (2 r1 by default).
  geometry::BodySpec body = [] {
    geometry::BodySpec b;
    b.body = "cylinder";
    b.radius_m = 0.01;
    b.height_m = 0.02;
    return b;
  }();
  /// The orientation: the ground's normal u (body frame, pointing into the
  /// ground) nearest to (cos a, sin a, 0) on the body's contact curve.
  double direction_deg = 0;
  /// Above 0: no check; the orientations of the directions this far apart
  /// (scan_whole_body_orientations), to choose a direction from.
  double scan_step_deg = 0;
  double normal_load_n = 100;       ///< F (the preprint's)
  double youngs_modulus_pa = 200e9; ///< steel (the preprint's)
  double poisson_ratio = 0.3;       ///< steel (the preprint's)
  int contact_elements = 6;         ///< across b in the strip (the whole body)
  double strip_over_half_width = 1.5; ///< the strip |y| < this b
  double section_growth = 0.3;      ///< element size per distance beyond the strip
  double layer_growth = 1.5;        ///< neighbouring layers along the ruling
  int layers_across_length = 24;    ///< the largest layer is L / this
  double penalty_c = 100;           ///< the whole body's kappa = c E / h_c (the slices' c)
  int stations = 9;                 ///< slices along the ruling
  ShareRule share_rule = ShareRule::locus; ///< the slices' and end models' q(s)
  int rule_stations = 16;           ///< the sections' share rule's N
  int rule_contact_elements = 2;    ///< the coarse body's elements across b (the fine body's: contact_elements)
  double rule_end_layer = 0.5;      ///< the coarse body's end layers, h / b (the fine body's: body_end_layer)
  double end_match_over_half_width = 4; ///< d_m / b, where an end model meets a rule that softens the ends
  double end_margin = 0.05;      ///< stations this fraction of the ruling inside its loaded ends (fem-sds's)
  int slice_refine = -1;            ///< the slices' level (SliceSettings::refine)
  /// The end models' block: as deep as the whole body's held section (the
  /// cut through the centre of mass, e.g. 588 b for the 10 mm cylinder), or
  /// the rim scene's local default 10 b. The square end's edge pressure
  /// falls as the block deepens, since its top is held flat (grid, h_e = b/32:
  /// 0.538 at 10 b, 0.488 at 400 b; docs/results/rim-ends.md#the-blocks-depth): a local block overstates
  /// a deep body's square end by about 10 %.
  EndModelDepth end_depth = EndModelDepth::body;
  int end_levels = 2;               ///< the end models' edge levels
  double end_edge_element = 1.0 / 16; ///< their first h_e / b; each level halves it
  /// Along the edge and across the strip, elements per b of the end models
  /// (rim --contact-elements): at 6 the deep grid's far side reached only
  /// 0.95-0.98 of Hertz's p0 and its edge did not converge.
  int end_contact_elements = 12;
  /// The whole body's end layers (and, unless end_layers_only, its section
  /// near the contact line at the ends), h / b of the smallest of the locus's
  /// b at the loaded ends.
  double body_end_layer = 1.0 / 16;
  /// Unless set, the whole body's section is refined to the end layer's
  /// size within end_zone_over_half_width b of the contact line, so that its
  /// elements at the ends are isotropic (as the end model's at its edge).
  /// Set, only the end layers are thin: the edge pressure then is a number of
  /// the mesh (docs/results/whole-body.md), kept to show it.
  bool end_layers_only = false;
  double end_zone_over_half_width = 1.0;
  double tolerance = 0.03;          ///< largest relative difference that passes
};

/// The orientation of one direction as the check takes it: the ruling on
/// the body's contact curve whose ground normal is nearest (cos a, sin a, 0)
/// (oracle::contact_curve_point, oracle::ruling_at), the locus's centre of
/// pressure c = (G - s_1) . b / L and its no-tension loaded part
/// (oracle::line_load: both ends loaded for 1/3 <= c <= 2/3, else the
/// nearer one), the rims' leans (contact::rim_overhang; interior angle 90
/// deg + lean), and at each end the locus's line load and line Hertz's b
/// (0 where the end is unloaded). Out of equilibrium (c outside (0, 1),
/// the body tips) nothing is loaded. A scan of directions (`whole-body
/// --scan-directions`) shows where an orientation's ends are square enough
/// to check.
struct WholeBodyOrientation
{
  double direction_deg = 0;
  oracle::Ruling ruling{};
  double centre_of_pressure = 0;         ///< the locus's c (fraction of L)
  double centre_of_mass_height_m = 0;    ///< where the body is cut and held
  bool in_equilibrium = false;           ///< 0 < c < 1
  double loaded_from = 0, loaded_to = 0; ///< fractions of L
  std::array<double, 2> rim_overhang_rad{};
  std::array<double, 2> end_load_n_per_m{}, end_half_width_m{};
  double interior_angle_deg(int end) const;
  double radius_m(int end) const { return end == 0 ? ruling.start_radius_m : ruling.end_radius_m; }
};

/// `settings.body` (cylinder or oloid: any hull of two circles) at
/// `direction_deg` under settings' F, E and nu. InputError for a body that is
/// not a hull of two circles; ComputationError where no ruling is found.
WholeBodyOrientation whole_body_orientation(const WholeBodyCheckSettings& settings, double direction_deg);
/// Directions 0, step, 2 step, ... below 360 deg (step in (0, 360]).
std::vector<WholeBodyOrientation> scan_whole_body_orientations(const WholeBodyCheckSettings& settings,
                                                               double step_deg);
/// One row per direction: c, the loaded part, R, interior angle, q and b at
/// each end, the rigid plane's wedge exponent at a loaded obtuse end.
std::string orientation_table(std::span<const WholeBodyOrientation> orientations);
/// The scan as `whole-body --scan-directions` logs it: the body, then orientation_table.
std::string scan_report(const WholeBodyCheckSettings& settings, std::span<const WholeBodyOrientation> scan);
nlohmann::json to_json(const WholeBodyOrientation& orientation);
/// {body, normal_load_n, orientations: [to_json(orientation), ...]}
nlohmann::json scan_json(const WholeBodyCheckSettings& settings, std::span<const WholeBodyOrientation> scan);

struct StationComparison
{
  double position_m = 0, radius_m = 0;
  double rule_load_n_per_m = 0;     ///< q(s) of the load rule (the locus's or the sections')
  double slice_peak_pa = 0;         ///< plane strain under q(s)
  double hertz_peak_pa = 0;         ///< line Hertz under q(s)
  double body_peak_pa = 0;          ///< the whole body's peak across the ruling
  double body_load_n_per_m = 0;     ///< the whole body's line load
  double peak_difference() const { return body_peak_pa / slice_peak_pa - 1; }
  double load_difference() const { return body_load_n_per_m / rule_load_n_per_m - 1; }
  /// The whole body's peak against the slice's scaled to the whole body's
  /// own line load there, p ~ sqrt(q) (line Hertz at fixed R): what is left
  /// when the load distribution's difference is taken out.
  double peak_difference_at_body_load() const
  {
    return body_peak_pa / (slice_peak_pa * std::sqrt(body_load_n_per_m / rule_load_n_per_m)) - 1;
  }
};

/// The end models' reading of a loaded end.
/// Under the locus's rule (uniform towards the end) the end model, loaded by
/// the rule's q at the end, stands for the whole end zone: its edge over its
/// far side (plane strain, the interior) times the slice at the end's q.
/// Under a rule that softens the ends itself (softens_ends) the end model is
/// matched to the rule a short distance d_m from the edge (global-local
/// matching): loaded by the rule's q at d_m, its reading over its own
/// centre-line pressure at d_m, times the slice at the rule's q and R there.
/// d_m = end_match_over_half_width b (the locus's b at the end, 4 by
/// default): inside it lies the edge's own 3D zone (an acute end's near-edge
/// peak within 2 b), beyond it the coarse body's line load meets the fine
/// body's within 1 % (docs/methods/whole-body.md).
struct EndComparison
{
  double position_m = 0, radius_m = 0, load_n_per_m = 0, half_width_m = 0;
  double interior_angle_deg = 90;
  fem::RimEndStudy end_model;            ///< its levels, exponent, ratio
  /// d_m, where the end model meets a rule that softens the ends (none:
  /// the end model against its far side).
  std::optional<double> rule_match_distance_m;
  double slice_peak_pa = 0;              ///< plane strain at the rule's q and R at the end, or at d_m
  /// What is compared: the edge's own pressure (square), or at an acute end,
  /// whose edge pressure falls towards zero under refinement (0.317, 0.279
  /// of the interior at h_e = b/16, b/32 for the oloid's 87.2 deg end), the
  /// largest pressure within 2 b of the edge (the end model's end_peak_pa,
  /// the whole body's largest node-plane peak there).
  bool near_edge_peak = false;
  /// The end model's reading over its reference pressure (far side, or at
  /// d_m) at its last level, if converged, and that ratio's change from the
  /// level before (over the larger of it and 1).
  std::optional<double> end_model_ratio, end_model_ratio_change;
  std::optional<double> predicted_edge_pa; ///< end_model_ratio x slice_peak (not singular, converged)
  double body_near_edge_peak_pa = 0;     ///< the whole body's largest plane peak within 2 b of the edge
  double body_edge_pa = 0;               ///< the whole body's
  double body_interior_pa = 0;           ///< the whole body's peak at the nearest station
  std::optional<double> difference;      ///< body / predicted - 1
  /// A singular end, read secondarily at matched meshes (never a pass): the
  /// end model's level whose edge elements are nearest the whole body's end
  /// layer, its edge / far pressure times the slice's peak, against the
  /// whole body's edge. Both are numbers of the mesh (they grow as h_e^(lambda - 1)).
  std::optional<std::size_t> matched_level;
  std::optional<double> matched_edge_pa;
  std::optional<double> matched_difference; ///< body / matched - 1
};

/// The check's outcome. pass: every station and every loaded end within the
/// tolerance. singular_ends: every station and every end that has a value
/// within it, the other ends singular in the end model (a sharp obtuse
/// edge: no value exists to compare; reported with the wedge's exponent
/// and, where solved, the secondary matched-mesh reading), so `pass` stays
/// false. fail: a station or a finite end beyond the tolerance, or an end
/// model that did not converge.
enum class WholeBodyOutcome
{
  pass,
  singular_ends,
  fail
};

struct WholeBodyCheck
{
  WholeBodyCheckSettings settings;
  std::string body;                      ///< geometry::body_label
  WholeBodyOrientation orientation;
  double effective_modulus_pa = 0;       ///< E / (1 - nu^2), the rigid plane
  double half_width_m = 0;               ///< line Hertz's b at the centre of mass's foot
  fem::WholeBodySizes sizes;
  std::int64_t section_nodes = 0;
  std::size_t node_planes = 0;
  double gmsh_s = 0;
  fem::WholeBodyFem fem;
  std::optional<SectionShare> section_share; ///< with ShareRule::sections
  /// With ShareRule::coarse_body: its mesh and solve (its q on each node plane).
  struct CoarseBody
  {
    fem::WholeBodySizes sizes;
    std::size_t node_planes = 0;
    fem::WholeBodyFem fem;
    double wall_s = 0;
  };
  std::optional<CoarseBody> coarse_body;
  std::vector<StationComparison> stations;
  std::vector<EndComparison> ends;       ///< the loaded ends
  double worst_along = 0;                ///< largest |peak_difference| over the stations
  std::optional<double> worst_end;       ///< largest |difference| over the ends (none if one is singular)
  double worst_load = 0;                 ///< largest |load_difference| over the stations
  /// The orientation's interior peak as fem-sds takes it, the largest over
  /// the stations: the whole body's over the slices' - 1 (not a pass
  /// criterion; what a station's misstated load costs the scores).
  double largest_peak_difference = 0;
  WholeBodyOutcome outcome = WholeBodyOutcome::fail;
  bool pass = false;                     ///< outcome == pass
  std::string verdict;
  double slices_s = 0, ends_s = 0, body_s = 0, wall_s = 0; ///< body_s: mesh + solve of the whole body
};

/// The outcome of a check whose stations' largest |peak difference| is
/// worst_along and whose loaded ends are compared (`difference` set),
/// singular in their end model, or neither (not converged).
WholeBodyOutcome check_outcome(double worst_along, std::span<const EndComparison> ends, double tolerance);

/// "PASS", "SINGULAR ENDS", "FAIL": the verdict's first word(s) and the JSON's `outcome`.
std::string outcome_name(WholeBodyOutcome outcome);

/// The largest of the whole body's station peaks over the largest of the
/// slices' - 1 (the two may lie at different stations).
double largest_peak_difference(std::span<const StationComparison> stations);

/// Every rank gets the result; rank 0 logs progress. InputError for bad
/// settings or a body without a whole-body mesh; ComputationError from the FEM.
WholeBodyCheck run_whole_body_check(MPI_Comm comm, const WholeBodyCheckSettings& settings);

nlohmann::json to_json(const StationComparison& station);
nlohmann::json to_json(const EndComparison& end);
nlohmann::json to_json(const WholeBodyCheck& check);
/// The comparison as a Markdown table (stations, then ends).
std::string markdown_table(const WholeBodyCheck& check);
/// The check as `whole-body` logs it: the body, markdown_table, the verdict.
std::string report(const WholeBodyCheck& check);
} // namespace rollcheck::study::whole_body
