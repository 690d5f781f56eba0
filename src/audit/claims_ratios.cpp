// The claims on the cylinder against the oloid: the ratios of their scores
// under the rigid-body oracle in each oracle mode, their dependence on the
// contact threshold and the oracle, the infinite FDS; and what real rolling
// and contact mechanics make of them.
#include "audit/cell_values.h"
#include "audit/claim_groups.h"
#include "contact/contact_parameters.h"

namespace rollcheck::audit::claims
{
namespace
{
/// Why the heat and wear scores have nothing to distribute under real rolling.
const std::string no_sliding_reason
    = "under rolling without slipping the contact ruling is the instantaneous axis of rotation (no slip at both ends, "
      "tests/oracle/test_rolling_dynamics.cpp), so the sliding speed the TDS and WDS accumulate is zero for both "
      "bodies: there is no heat or wear to distribute, and no ratio";

/// The fatigue load and endurance limit the scores use.
const contact::FatigueParameters fatigue_parameters;

/// The cells of a claim on cylinder / oloid ratios, one per oracle mode.
std::vector<ClaimCell> ratio_cells(const ClaimCommands& c, std::vector<std::pair<std::string, double>> pointer_paper)
{
  return cells_in(oracle_modes, c.pair, rules::ratios_within(std::move(pointer_paper), claim_tolerance));
}
} // namespace

std::vector<Claim> ratio_claims(const ClaimCommands& c)
{
  return {
      {"cds_ratio", "CDS cylinder / oloid", times(58),
       at_claim_tolerance("holds when cylinder cds / oloid cds is within {tolerance} of 58. Real rolling: U is a "
                          "different score than CDS, so the comparison is of discrimination, not values: holds when "
                          "cylinder U_inf / oloid U_inf exceeds 1 (the oloid the more uniform), whatever its size."),
       "",
       joined({ratio_cells(c, {{"/cds", 58}}),
               {{mode::rolling, c.rolling_pair, rules::uniformity_ratio_above_one()}}}),
       truth_over_choices(c, {{"oloid vs cylinder", "contact_time_u", true}},
                          "U_inf, the resolution-free contact-time score, stands for CDS; the 58x itself is the face "
                          "counts' (matched resolution: 2.4x)")},
      {"threshold_independence", "Threshold independence of the CDS ratio, eps 0.01-0.16", "ratio varies 10 %",
       at_claim_tolerance("holds when the cylinder/oloid CDS ratio at eps = 0.01 ... 0.16 stays within {tolerance} of "
                          "its value at eps = 0.04."),
       "",
       joined({cells_in(oracle_modes, c.threshold_scan, rules::threshold_spread(claim_tolerance)),
               {not_built(mode::rolling)}}),
       truth_in(mode::corrected)},
      {"sds_ratio", "SDS cylinder / oloid", times(58),
       at_claim_tolerance("holds when cylinder sds / oloid sds is within {tolerance} of 58."),
       "",
       joined({ratio_cells(c, {{"/sds", 58}}),
               {not_built(mode::rolling),
                {mode::contact, c.fem_sds_pair, rules::converged_sds_ratio(58, claim_tolerance)}}}),
       truth_over_choices(c, {{"oloid vs cylinder", "accumulated_pressure_whole", true},
                              {"oloid vs cylinder", "accumulated_pressure_touched", true}})},
      {"damage_ratios", "TDS, WDS_vol, WDS_depth cylinder / oloid (the 46-68x range)", "68x, 68x, 46x",
       at_claim_tolerance("holds when each ratio is within {tolerance} of the paper's (68, 68, 46)."),
       "",
       joined({ratio_cells(c, {{"/tds", 68.0}, {"/wds_vol", 68.0}, {"/wds_depth", 46.0}}),
               {not_built(mode::rolling), {mode::contact, {}, {}, no_sliding_reason}}}),
       truth_in(mode::contact)},
      {"fatigue", "FDS: the cylinder's is infinite (no stress above the endurance limit), the oloid's finite",
       "oloid 2.42e-6, cylinder ∞",
       "holds when the cylinder's FDS is infinite and the oloid's finite. Fatigue life: holds when the oloid's L10 life is "
       "at least the cylinder's in every cell of the grid at every load (Lundberg-Palmgren).",
       "With every quirk corrected both are infinite: the stress amplitude of a zero-to-p0 cycle is p0/2, which alone "
       "makes the oloid's FDS infinite (docs/results/oracles.md#paper-compat-quirk-table); the right E* alone makes the cylinder's finite.",
       joined({cells_in(oracle_modes, c.fatigue, rules::cylinder_fds_infinite()),
               {not_built(mode::rolling),
                {mode::contact, c.fem_sds_pair,
                 rules::line_contact_fatigue(fatigue_parameters.load_n, fatigue_parameters.endurance_limit_pa)},
                {mode::life, c.life, rules::lives_longer_over_choices("oloid", {"cylinder"})}}}),
       truth_in(mode::contact)},
      {"discrimination", "Cylinder / oloid CDS rises from the approximate to the rigid-body oracle", "28x → 58x",
       at_claim_tolerance("holds when the approximate and the rigid-body ratios are within {tolerance} of 28 and 58."),
       "",
       cells_in(oracle_modes, c.approximate_then_rigid,
                rules::all_of({rules::ratio_within("approximate", {1, "/cds"}, {0, "/cds"}, 28, claim_tolerance),
                               rules::ratio_within("rigid", {3, "/cds"}, {2, "/cds"}, 58, claim_tolerance)})),
       truth_in(mode::corrected)},
      {"all_metrics", "The cylinder is 58x worse on all metrics", "58x",
       at_claim_tolerance("holds when each cylinder / oloid ratio (CDS, SDS, TDS, WDS_vol, WDS_depth, FDS) is within "
                          "{tolerance} of 58. Fatigue life (the FDS's question): holds when the oloid's L10 life is at "
                          "least the cylinder's in every cell of the grid at every load."),
       "The preprint's own table gives 46-68x and an infinite FDS ratio.",
       joined({ratio_cells(c, {{"/cds", 58}, {"/sds", 58}, {"/tds", 58}, {"/wds_vol", 58}, {"/wds_depth", 58},
                               {"/fds", 58}}),
               {{mode::life, c.life, rules::lives_longer_over_choices("oloid", {"cylinder"})}}}),
       truth_over_choices(c, {{"oloid vs cylinder", "contact_time_u", true},
                              {"oloid vs cylinder", "accumulated_pressure_whole", true},
                              {"oloid vs cylinder", "basquin_damage_whole", true}})},
  };
}
} // namespace rollcheck::audit::claims
