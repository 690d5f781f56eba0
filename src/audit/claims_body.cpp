// The claims on the scored body itself: its area (is it the oloid?) and the
// discrete curvatures of its mesh.
#include "audit/claim_groups.h"
#include <fmt/format.h>
#include <numbers>

namespace rollcheck::audit::claims
{
namespace
{
/// The oloid's area over r^2.
constexpr double four_pi = 4 * std::numbers::pi;
} // namespace

std::vector<Claim> body_claims(const ClaimCommands& c)
{
  return {
      {"oloid_area", "The scored body is the oloid: surface area 4π r²", "4π = 12.566 (the paper's body: 12.659)",
       fmt::format("holds when the body's mesh area is within {:.1f} % of 4π (r = 1 m).", 100 * area_tolerance),
       "The true oloid's scores are the 'true oloid' column of the other claims.",
       {{mode::paper, c.mesh.at(mode::paper),
         rules::areas_within(four_pi, area_tolerance, {"reference mesh", "`--body paper-oloid`"})},
        {mode::true_oloid, c.mesh.at(mode::true_oloid), rules::areas_within(four_pi, area_tolerance, {""})}},
       truth_in(mode::paper, "The claim is about the body the preprint scores")},
      {"discrete_gaussian", "The discrete Gaussian curvature is about 1.07 on the oloid, where K = 0", "|K| ≈ 1.07",
       at_claim_tolerance("holds when the mean face Gaussian curvature is within {tolerance} of 1.07."),
       "The preprint's \"affecting SDS by 17 %\" names no computation to rerun.",
       cells_in(oloid_modes, c.oloid,
                rules::each_within({{0, "/curvature/face_gaussian_curvature_mean_per_m2", 1.07, 3, "K"}},
                                   claim_tolerance)),
       truth_in(mode::corrected)},
      {"geometry_only_sds", "Geometry-only SDS under uniform contact, curvature-driven stress CV, \"about 6 %\"",
       "4.8e-8, CV 0.30, ~6 %",
       "cannot be tested: see the cell.",
       "4.8e-8 / 8.07e-7 = 5.9 % is the preprint's own arithmetic; the discrete per-face peak pressures (`--per-face`, "
       "peak_pressure_pa) are not the preprint's corrected curvatures.",
       {{mode::paper, {}, {},
         "the method (\"analytically corrected curvatures, K = 0\", Couey 2026, in preparation) is unpublished, and "
         "with K = 0 the preprint's R_eff = 1/√(κ1κ2) is infinite, so its point Hertz pressure is undefined; no "
         "command computes it"}},
       truth_in(mode::paper)},
      {"mean_curvature_spread", "σ_H of the discrete mean curvature: oloid above cylinder", "0.90 vs 0.28",
       at_claim_tolerance("holds when both are within {tolerance} of the paper's."),
       "The paper-compatible values reproduce reference_outputs.json (H_face_std 0.899, 0.279); corrected physics "
       "halves the reference code's doubled mean curvature.",
       cells_in(oloid_modes, c.pair,
                rules::each_within({{0, "/curvature/face_mean_curvature_std_per_m", 0.90, 2, "oloid"},
                                    {1, "/curvature/face_mean_curvature_std_per_m", 0.28, 2, "cylinder"}},
                                   claim_tolerance)),
       truth_in(mode::corrected)},
  };
}
} // namespace rollcheck::audit::claims
