#pragma once
// The rim loop's flat-rim table (study/rims/rim_loop.h): a rounded edge's
// flattest loaded ends, the body's own, at interior angles at most a step
// apart up to the loop's flattest (study/rims/flattest_loop_ends.h), each
// solved in 3D by half-space theory on the hull's own surface with the
// ruling's own load and the body's balance (study/rims/flat_rim_contact.h).
// The loop's ends near the flattest are one family per side, whose c, q and
// R follow the angle: a node holds one end per side (one when the sides are
// mirror images) and the largest peak over them, interpolated linearly in
// the angle (study/rims/table_nodes.h).
//
// Half-space theory is refused at a node whose solve failed or whose
// contact meets slopes steeper than 0.1 (an end beside a crease of the
// hull): the table then starts after the last refused node
// (flat_rim_table_start), the FEM end table taking the ends below.
#include "study/rims/flat_rim_contact.h"
#include "core/progress_beat.h"
#include <Eigen/Core>
#include <cstddef>
#include <mpi.h>
#include <nlohmann/json.hpp>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace rollcheck::study::rims
{
/// One loaded end solved by flat-rim (study/rims/flat_rim_contact.h), as the
/// loop needs it.
struct FlatRimSide
{
  double centre_of_pressure = 0;     ///< c from the end
  double end_line_load_n_per_m = 0;
  double end_radius_m = 0;           ///< the hull's R across the ruling at the end
  double peak_pressure_pa = 0;
  double line_hertz_peak_pa = 0;     ///< at the end's q and R = max(R_end, r_e)
  double last_change = 0, window_change = 0;
  bool converged = false;
  double wall_s = 0;
  double after_over_half_width = 0;  ///< the window along the ruling (shortened where the body could not balance)
  double across_scale = 1;           ///< the window's width across over the set one (widened: > 1)
  /// Solved over its whole loaded ruling (study::needs_whole_ruling: its
  /// shortened window did not converge), with that window's peak (Pa).
  bool whole_ruling = false;
  double window_peak_pa = 0;
  /// The peak over line Hertz at the end's q and R = max(R_end, r_e).
  double ratio() const { return peak_pressure_pa / line_hertz_peak_pa; }
};

/// One node of the flat-rim table: the loop's orientations whose loaded end
/// has this angle, one per side of the flattest end (one when the two sides
/// are mirror images: the same c and R within 1e-6).
struct FlatRimNode
{
  double section_angle_rad = 0;     ///< in the ruling's vertical plane: the loop's ends' own angle
  /// Normal to the rim (contact/rim_dihedral_angle.h), the first side's.
  double dihedral_angle_rad = 0;
  std::vector<FlatRimSide> sides;
  /// The largest peak over the sides (Pa): the loop's ends near this angle
  /// take it, interpolated linearly in the angle (it is smooth there, where
  /// line Hertz at R = max(R_end, r_e) has a kink at R_end = r_e).
  double peak_pa() const;
  /// The side with the largest peak over line Hertz, and that ratio, as the
  /// end table's ratio (reported).
  const FlatRimSide& largest_ratio_side() const;
  double ratio() const { return largest_ratio_side().ratio(); }
  bool converged() const;
};

/// The flat-rim table and why it does not start at its first angle: the
/// refused nodes (empty: none was).
struct FlatRimTable
{
  std::vector<FlatRimNode> nodes;
  std::string refused;
};

/// The flat-rim table over [from_rad, the loop's flattest loaded end] of the
/// body of `circles` (two) and its centre of mass: nodes at most `step_rad`
/// apart, every end solved by `setup` (its body's own end; the end's whole
/// loaded ruling where study::needs_whole_ruling says so), the solves shared
/// out over the ranks of `comm` (each is serial); from
/// flat_rim_table_start's node on when some are refused. Collective: every
/// rank gets the table. ComputationError when the flattest node is refused
/// or too few are left; InputError (from flattest_loop_ends_below) when no
/// orientation has a node's angle. `beat`, if given, is told each side this
/// rank solves.
FlatRimTable flat_rim_table(MPI_Comm comm, const FlatRimSettings& setup, std::span<const oracle::Circle> circles,
                            const Eigen::Vector3d& centre_of_mass_m, double from_rad, double step_rad,
                            ProgressBeat* beat = nullptr);

/// Where the flat-rim table starts when some of its nodes are refused (a
/// failed solve, or contact on slopes too steep for half-space theory, as
/// beside a crease of the hull): the first node after the last refused one,
/// moved one on where needed to keep the kept nodes odd in number (every
/// other one, the check of the spacing, still ends on the flattest). None
/// when the flattest node is refused or too few are left. `refused` is in
/// ascending angle.
std::optional<std::size_t> flat_rim_table_start(const std::vector<bool>& refused);

/// The table's peak (Pa) at the section angle `section_angle_rad` by every `stride`-th node,
/// linear in the angle, held at its ends.
double flat_rim_peak(const std::vector<FlatRimNode>& table, int stride, double section_angle_rad);

/// The table's ratio (FlatRimNode::ratio, its largest peak over line Hertz
/// at the table's own load) at `section_angle_rad` by every `stride`-th
/// node, linear in the angle, held at its ends.
double flat_rim_ratio(const std::vector<FlatRimNode>& table, int stride, double section_angle_rad);

// Defined in study/rims/rim_loop_json.cpp with the loop's other records.
nlohmann::json to_json(const FlatRimSide& side);
nlohmann::json to_json(const FlatRimNode& node);
} // namespace rollcheck::study::rims
