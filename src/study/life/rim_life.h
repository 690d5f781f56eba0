#pragma once
// Wing of the study layer (study/life): the life with and without the
// rounded rim ends, and the edge rounding that makes the interior govern.
//
// Every loaded ruling of the loop ends on the body's rims (the cylinder's on
// its square ends). With rounded edges (radius r_e) each loaded end adds its
// own pass to the stress-volume integral (loop_life.h, for_each_loaded_end):
// its peak rho(R_end / r_e) times line Hertz's at the end's q and
// R = max(R_end, r_e), rho from the rim study's end models
// (rounded_end_ratios.h). At one cell of the grid (the robustness study's
// defaults: rolling energy 0.1, the dynamic load, end margin 0.05) and each
// load, for each r_e (a fraction of the body's radius r1) Lundberg-Palmgren's
// integral (orthogonal shear) of the interior I_i and of the ends I_e give
//     L10 with the ends / L10 without = (I_i / (I_i + I_e))^(1 / e),
// and the interior governs the life when I_e < I_i. A rounder edge lowers
// I_e (rho falls with R_end / r_e, and an element's term falls as
// R^(-13/3) at a given rho once r_e exceeds R_end), so the interior governs
// from the r_e where ln(I_e / I_i) crosses 0, interpolated linearly in
// ln(r_e) between the radii computed.
#include "study/life/loop_life.h"
#include "study/robustness/robustness.h"
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace rollcheck::study::life
{
struct RimLifeSettings
{
  /// r_e / r1, ascending; the rim study's finish is 0.04 (0.4 mm on its 10 mm bodies).
  std::vector<double> edge_radius_over_radius = {0.0025, 0.005, 0.01, 0.02, 0.04, 0.08, 0.16};
  double rim_study_edge_radius_over_radius = 0.04;
  double zone_over_half_width = 1; ///< an end's patch along the ruling, in its b
};

struct RimLifeRow
{
  double edge_radius_over_radius = 0;
  double interior_integral = 0, end_integral = 0; ///< Lundberg-Palmgren, orthogonal shear
  double life_with_over_without_ends = 0;
  long ends = 0, ends_outside_table = 0;
  /// L10 with the ends over the cylinder's with its ends at the same r_e / r1
  /// (none for the cylinder itself).
  std::optional<double> life_ratio_to_cylinder;
};

struct RimLife
{
  std::string body;
  double load_n = 0;
  std::vector<RimLifeRow> rows;
  /// Without the ends, L10 over the cylinder's (none for the cylinder).
  std::optional<double> interior_life_ratio_to_cylinder;
  /// r_e / r1 from which the interior governs; none when it does not within the radii computed.
  std::optional<double> interior_governs_from;
  bool governs_at_every_radius = false; ///< already at the smallest r_e computed
};

/// InputError unless the edge radii are positive and ascending and the zone positive.
void validate(const RimLifeSettings& settings);

/// The rows of every body (runs[b] its loop at the cell's energy) at each
/// load; `loop_settings(load)` the cell's loop settings. `cylinder` indexes
/// the cylinder in `bodies` (none: no ratios to it).
std::vector<RimLife> rim_lives(const RimLifeSettings& settings, const std::vector<robustness::NamedBody>& bodies,
                               const std::vector<const oracle::RealRolling*>& runs, const std::vector<double>& loads_n,
                               const std::function<LoopLifeSettings(double)>& loop_settings,
                               const LifeConstants& constants, const std::array<const DepthIntegrals*, 2>& depth,
                               const std::array<double, 2>& ratio, const RoundedEndRatios& end_ratios,
                               std::optional<std::size_t> cylinder);

/// The first r_e / r1 at which end / interior falls below 1: linear in
/// ln(r_e) between the rows that bracket it; none when no row's does.
std::optional<double> interior_governs_from(const std::vector<RimLifeRow>& rows);

nlohmann::json to_json(const RimLife& life);
} // namespace rollcheck::study::life
