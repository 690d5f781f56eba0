// The claims on the preprint's tables (the Hertz oracle's, the pressures', the
// fatigue scores') and its timings, recomputed paper-compatible.
#include "audit/claim_groups.h"
#include <array>
#include <fmt/format.h>

namespace rollcheck::audit::claims
{
namespace
{
/// Speed claim: the approximate oracle scores a body in under 0.01 s, the rigid-body oracle in about 2 s.
constexpr double approximate_seconds = 0.01, rigid_seconds = 2.0;

/// The Hertz table's numbers (CDS, SDS, mean peak pressure in MPa) for the
/// bodies of claim_commands().hertz_table, in that order.
std::vector<Expected> hertz_table_expected()
{
  const std::vector<std::string> names = {"oloid", "(120,1.30,0.80)", "(115,1.20,0.65)", "(115,1.30,0.65)",
                                          "(115,0.70,0.65)", "cylinder"};
  const std::vector<std::array<double, 3>> paper_rows = {{8.2e-7, 8.1e-7, 68.3},  {8.7e-7, 8.9e-7, 68.3},
                                                         {9.3e-7, 9.8e-7, 76.0},  {8.6e-7, 9.8e-7, 76.6},
                                                         {1.8e-6, 1.8e-6, 79.2},  {4.75e-5, 4.68e-5, 49.7}};
  std::vector<Expected> expected;
  for (std::size_t i = 0; i < names.size(); ++i)
  {
    const int digits = i == 5 ? 3 : 2; // the cylinder's CDS and SDS have three
    expected.push_back({i, "/cds", paper_rows[i][0], digits, names[i] + " CDS"});
    expected.push_back({i, "/sds", paper_rows[i][1], digits, "SDS"});
    expected.push_back({i, "/mean_peak_pressure_pa", paper_rows[i][2], 3, "p̄ MPa", 1e-6});
  }
  return expected;
}
} // namespace

std::vector<Claim> table_claims(const ClaimCommands& c)
{
  return {
      {"hertz_table", "Hertz-oracle table: CDS, SDS, mean peak pressure",
       "oloid 8.2e-7, 8.1e-7, 68.3 MPa; (120,1.30,0.80) 8.7e-7, 8.9e-7, 68.3; (115,1.20,0.65) 9.3e-7, 9.8e-7, 76.0; "
       "(115,1.30,0.65) 8.6e-7, 9.8e-7, 76.6; (115,0.70,0.65) 1.8e-6, 1.8e-6, 79.2; cylinder 4.75e-5, 4.68e-5, 49.7",
       at_claim_tolerance("holds when each number is within {tolerance} of the paper's; the value counts those equal "
                          "to the printed digits (2-3 significant)."),
       "Rollers meshed as the search's candidates (300 points per circle). The oloid and the cylinder reproduce the "
       "published code's own outputs (tests/data/reference/reference_outputs.json: SDS 8.04e-7, 68.37 MPa, 4.68e-5, "
       "49.68 MPa), so the preprint's 8.1e-7 and 68.3 are not what its code prints (68.37 truncated; 8.1e-7 is inside "
       "the rigid runs' 5-10 % spin-nudge band); the (115, ...) genomes are not in the reference data (not on its "
       "grid).",
       {{mode::paper, c.hertz_table, rules::each_within(hertz_table_expected(), claim_tolerance)}},
       truth_untestable(per_face_value_reason)},
      {"pressure_uniformity",
       "Mean peak pressure and its CV; the nearest neighbour (120, 1.30, 0.80): CV 0.084, SDS within 10 %",
       "oloid 68.3 MPa, CV 0.085; cylinder 49.7 MPa, CV 0.045; neighbour CV 0.084, SDS +10 %",
       at_claim_tolerance("holds when each pressure and CV is within {tolerance} of the paper's and the neighbour's "
                          "SDS is within 10 % of the oloid's."),
       "The published code prints 68.37 MPa, CV 0.0845, 49.68 MPa, CV 0.0446 (reference_outputs.json), which the "
       "paper-compatible run reproduces; the preprint's 68.3 is truncated. Its neighbour SDS gap (8.9e-7 vs 8.1e-7) "
       "uses the oloid SDS 8.1e-7, not the code's 8.04e-7.",
       {{mode::paper, c.neighbour_pressures,
         rules::all_of({rules::each_within({{0, "/mean_peak_pressure_pa", 68.3, 3, "oloid MPa", 1e-6},
                                            {0, "/stress_cv", 0.085, 2, "CV"},
                                            {1, "/mean_peak_pressure_pa", 49.7, 3, "cylinder MPa", 1e-6},
                                            {1, "/stress_cv", 0.045, 2, "CV"},
                                            {2, "/stress_cv", 0.084, 2, "neighbour CV"}},
                                           claim_tolerance),
                        rules::ratio_within("neighbour SDS / oloid SDS", {2, "/sds"}, {0, "/sds"}, 1, 0.10)})}},
       truth_untestable(per_face_value_reason)},
      {"fatigue_values", "FDS of the oloid, its damage ratio, and 6.8x over the nearest competitor",
       "2.42e-6; 23x; 6.8x",
       at_claim_tolerance("holds when FDS and the damage ratio are within {tolerance} of the paper's and the nearest "
                          "competitor's (120, 1.30, 0.80) FDS over the oloid's is within {tolerance} of 6.8. Fatigue "
                          "life (the competitors' question): holds when the oloid's L10 life is at least the "
                          "preprint's body's and the family's best bodies' in every cell of the grid at every load."),
       "The published code prints FDS 2.35e-6 and damage ratio 24.2 (reference_outputs.json), which the "
       "paper-compatible run reproduces: the preprint's 2.42e-6 and 23x are not its code's output. No pair of the "
       "published outputs gives 6.8x.",
       {{mode::paper, c.neighbour_fatigue,
         rules::all_of({rules::each_within({{0, "/fds", 2.42e-6, 3, "FDS"},
                                            {0, "/fatigue/damage_ratio", 23, 2, "damage ratio"}},
                                           claim_tolerance),
                        rules::ratio_within("competitor FDS / oloid FDS", {1, "/fds"}, {0, "/fds"}, 6.8,
                                            claim_tolerance)})},
        {mode::life, c.life,
         rules::lives_longer_over_choices("oloid", {"paper-oloid", "u-optimum", "fem-sds-optimum"})}},
       truth_untestable(per_face_value_reason)},
      {"speed", "Speed: the approximate oracle scores a body in under 0.01 s, the rigid-body oracle in about 2 s",
       "< 0.01 s; ~2 s",
       fmt::format("holds when rollcheck's approximate oracle takes under {:g} s and its rigid-body oracle at most "
                   "{:g} s on the reference oloid (cpu_s: the scoring's processor time, without process start-up, "
                   "so that the verdict does not move with the machine's load).",
                   approximate_seconds, rigid_seconds),
       "rollcheck is C++, not the published Python: its times bound the method's cost, not the preprint's code. The "
       "published code on this machine kind takes 8-14 ms (approximate) and 0.9-1.5 s (rigid-body) per body "
       "(tests/data/reference/README.md): its approximate oracle is not under 0.01 s.",
       {{mode::paper, c.speed,
         rules::all_of({rules::below("approximate s", 0, "/cpu_s", approximate_seconds),
                        rules::below("rigid-body s", 1, "/cpu_s", rigid_seconds)})}},
       truth_in(mode::paper, "The claim is about the methods' cost, measured on rollcheck's implementation")},
  };
}
} // namespace rollcheck::audit::claims
