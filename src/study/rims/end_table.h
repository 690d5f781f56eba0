#pragma once
// The rim loop's FEM end table (study/rims/rim_loop.h): end models
// (fem/scenes/rim_end_contact.h) at evenly spaced dihedral angles across the
// loop's range of loaded ends, and for a rounded edge at geometrically
// spaced R across the range of the loop's ends (its columns), all at one q;
// its end/interior ratio at an end, interpolated linearly in the angle and
// in log R (study/rims/table_nodes.h).
//
// The end model stands for dihedral angles in [60, 179.5] deg, a rounded
// edge's in [60, 170] deg; a sharp edge is singular above the angle where
// its wedge's exponent turns negative (contact/wedge_exponent.h on the
// rigid plane, contact/edge_on_elastic_block_exponent.h on a block of the
// body's own material), and has no ratio there.
#include "fem/scenes/rim_end_contact.h"
#include "study/rims/half_space_end.h"
#include <nlohmann/json.hpp>
#include <numbers>
#include <optional>
#include <vector>

namespace rollcheck::study::rims
{
/// The end model's range of dihedral angles, 180 deg open.
constexpr double smallest_modelled_angle_rad = 60 * (std::numbers::pi / 180);
constexpr double largest_modelled_angle_rad = 179.5 * (std::numbers::pi / 180);
/// A rounded edge's largest: OpenCASCADE finds no edge to fillet between
/// faces this close to tangent (176 deg failed, 170 deg meshed); ends above
/// it are modelled at it, where the rounded end's ratio no longer changes
/// with the angle (the oloid's table: 1.945 and 1.939 at 142 and 161 deg).
constexpr double largest_rounded_angle_rad = 170 * (std::numbers::pi / 180);
/// The smallest r_e / b at which an end may be solved by half-space theory
/// (RimLoopSettings::half_space_from_rad): the FEM's ends meet it within
/// 1.5-1.6 % at 20 b and 40 b, 3.3 % at 10 b (120 deg, R / r_e = 10).
constexpr double smallest_half_space_edge_over_half_width = 20;
/// The bisection's tolerance on the angle where sharp edges turn singular.
constexpr double singular_angle_tolerance_rad = 1e-10;

/// lambda - 1 of a sharp edge of `wedge_angle_rad` (measured normal to
/// its edge) against `end`'s counter-face: the rigid plane's wedge
/// (contact/wedge_exponent.h) or a block of the body's own material
/// (contact/edge_on_elastic_block_exponent.h); negative: singular.
double sharp_edge_exponent(const fem::RimEndSettings& end, double wedge_angle_rad);

/// The largest dihedral angle the end model takes with `end`'s edge.
double largest_modelled_angle(const fem::RimEndSettings& end);

/// The smallest dihedral angle whose sharp edge is singular against the
/// counter-face (bisection on the wedge exponent), pi when none is.
double singular_from_angle(const fem::RimEndSettings& end);

struct EndTableNode
{
  double dihedral_angle_rad = 0;
  /// The node's column: R of its end model.
  double sheet_radius_m = 0;
  /// Whether a look-up of the loop reads the node (end_table_nodes_read); a
  /// node none reads is not solved, its study left empty.
  bool reached = true;
  fem::RimEndStudy study;
  /// Set where the node was solved by half-space theory; `study` then
  /// holds what the loop reads of it.
  std::optional<HalfSpaceEndStudy> half_space;
};

/// The node's angle and its end model in brief (study/rims/rim_end_json.h
/// end_model_json; defined in study/rims/rim_loop_json.cpp).
nlohmann::json to_json(const EndTableNode& node);

/// The end table's dihedral angles over [lo, hi]: evenly, at most `step_rad`
/// apart, an odd number of them (every other one is a table too); with
/// `acute_step_rad` > 0 and 90 deg inside the range, [lo, 90 deg] and
/// [90 deg, hi] each so, the first at most `acute_step_rad` apart (their
/// union is odd again, 90 deg an even node). One node where lo = hi.
std::vector<double> end_table_angles(double lo, double hi, double step_rad, double acute_step_rad);

/// The table's end/interior ratio at `dihedral_angle_rad` and the sheet's
/// `radius_m` (unused with one column): within each column linear in the
/// angle, across them linear in log R, held at
/// the table's edges; in a direction with 3 or more nodes by every
/// `stride`-th (the check of its spacing). None when the angle lies above
/// `singular_from_rad`.
std::optional<double> end_table_ratio(const std::vector<EndTableNode>& table, int stride, double singular_from_rad,
                                      double dihedral_angle_rad, double radius_m);

/// The indices into `table` of the nodes end_table_ratio reads at
/// `dihedral_angle_rad` and `radius_m` by every `stride`-th node (none above
/// `singular_from_rad`): in each of the one or two columns about R, the
/// one or two nodes about the angle. Only their ratios enter the look-up, so
/// a table whose nodes no look-up reads are left unsolved gives every
/// look-up the ratio of the whole table; a look-up that reads an unsolved
/// node is an error (end_table_ratio).
std::vector<std::size_t> end_table_nodes_read(const std::vector<EndTableNode>& table, int stride,
                                              double singular_from_rad, double dihedral_angle_rad, double radius_m);
} // namespace rollcheck::study::rims
