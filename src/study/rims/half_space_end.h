#pragma once
// `rim`'s rounded end (a straight rim of edge radius r_e at the end of a
// line contact of line load q across a sheet of radius R) by half-space
// theory on a graded grid (contact/rounded_end_half_space.h), level by
// level: each level halves the cells about the fillet's start. Where r_e >>
// b the FEM end model needs elements of a quarter of the fillet's boundary
// layer s = 2 r_e b / (pi R) in a block 10.5 r_e deep, millions of DOFs and
// tens of minutes a level at the preprint's scale; this solves the same end
// in seconds. It has no interior angle: the body beyond the fillet is a
// half-space, which reads 0.6-3.4 % above the FEM ends from 120 deg at r_e
// >= 20 b and R / r_e = 1 to 100, but more near a square or acute end (docs/notes/rim-ends-tables.md, "A
// rounded end by half-space theory"). The line contact is held over the
// block's depth, as the FEM's far field.
#include "contact/rounded_end_half_space.h"
#include "core/refinement_series.h"
#include <functional>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

namespace rollcheck::study::rims
{
struct HalfSpaceEndSettings
{
  double sheet_radius_m = 0.01;  ///< R across the ruling at the end
  double load_n_per_m = 1e4;     ///< q, the line load
  double edge_radius_m = 1e-3;   ///< r_e of the fillet
  double youngs_modulus_pa = 200e9;
  double poisson_ratio = 0.3;
  bool steel_counter_face = false; ///< a half-space of the body's own material instead of the rigid plane
  /// The line contact held over this many b (the FEM block's depth H / b);
  /// 0: depth_over_edge_radius r_e, as deep as the rim loop's blocks.
  double depth_over_half_width = 0;
  double depth_over_edge_radius = 10.5;
  int levels = 2;
  double tolerance = 0.01; ///< the end factor's largest change between the last two levels that counts as converged
  contact::RoundedEndGridSettings grid;
  unsigned threads = 0; ///< the influence's threads (0: every core)
};

/// The influence and the loaded cells' system of the finest level, at most.
constexpr double largest_half_space_end_bytes = 6.0 * (1ull << 30);
/// The longest hold, in b (`--depth`'s bound, and the default hold's).
constexpr double largest_held_length_over_half_width = 5000;

struct HalfSpaceEndLevel
{
  double finest_over_layer = 0; ///< the cells about the fillet's start, in s
  contact::RoundedEndHalfSpace end;
  double wall_s = 0;
};

struct HalfSpaceEndStudy
{
  HalfSpaceEndSettings settings;
  double effective_modulus_pa = 0;
  double half_width_m = 0;      ///< line Hertz's b at q and R
  double line_hertz_p0_pa = 0;  ///< line Hertz's p0
  double radius_ratio = 0;      ///< R / r_e
  double boundary_layer_m = 0;  ///< s = 2 r_e b / (pi R)
  double held_length_over_half_width = 0;
  std::vector<HalfSpaceEndLevel> levels;
  RefinementSeries end_factor;  ///< peak over far side, by the finest cells (m)
  bool converged = false;
  /// The last level's peak over its far side (the FEM end model's end/interior ratio).
  double end_to_interior() const { return levels.back().end.peak_over_far; }
  double peak_pressure_pa() const { return levels.back().end.peak_over_p0 * line_hertz_p0_pa; }
};

/// Called as each level starts, with its 0-based index and its finest cell (m).
using HalfSpaceEndProgress = std::function<void(int level, double finest_cell_m)>;

/// The end at `settings`. InputError for a non-positive or non-finite R, q,
/// r_e, E, a Poisson ratio outside (-1, 0.5), r_e below 2 b (the body is no
/// half-space at the contact's scale), a hold outside [10, 5000] b or within
/// 4 s of the fillet, or a finest level whose dense matrices would exceed
/// largest_half_space_end_bytes (checked before any solve); ComputationError
/// when a level's contact does not settle, or reaches its grid's border
/// after the grid was widened (contact::rounded_end_half_space) as far as
/// those bytes allow.
HalfSpaceEndStudy half_space_end(const HalfSpaceEndSettings& settings, const HalfSpaceEndProgress& progress = {});

nlohmann::json to_json(const HalfSpaceEndStudy& study);
/// The levels' table and the verdict.
std::string report(const HalfSpaceEndStudy& study);
} // namespace rollcheck::study::rims
