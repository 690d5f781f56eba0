// The claims on the oloid's own scores under the rigid-body oracle: its CDS,
// their convergence with the samples and scaling with the mesh, and the
// lowest score of its vector, in each oracle mode.
#include "audit/claim_groups.h"
#include <fmt/format.h>
#include <fmt/ranges.h>

namespace rollcheck::audit::claims
{
std::vector<Claim> oloid_score_claims(const ClaimCommands& c)
{
  return {
      {"oloid_cds", "Oloid CDS (rigid-body oracle, 600 samples)", "8.2e-7",
       at_claim_tolerance("holds when the oloid's CDS is within {tolerance} of 8.2e-7. Real rolling: U is a different "
                          "score than CDS, so the comparison is of discrimination, not values: holds when the oloid's "
                          "U_inf is below the cylinder's."),
       "Matched resolution does not apply to an absolute value: CDS falls with the face count (see the N claim).",
       joined({cells_in(oloid_modes, c.oloid, rules::value_within("/cds", 8.2e-7, claim_tolerance)),
               {{mode::rolling, c.rolling_pair, rules::oloid_more_uniform()}}}),
       truth_untestable(per_face_value_reason)},
      {"convergence", "O(1/T) convergence: CDS(50 samples) / CDS(600 samples)", "10.3x (O(1/T): 12x)",
       at_claim_tolerance("holds when the reduction is within {tolerance} of 12 = 600/50, the O(1/T) rate the paper "
                          "claims; 50 and 600 samples are the first and last `convergence` snapshots."),
       "The reference code's own output (tests/data/reference/reference_outputs.json) has the paper-compatible 2.87e-6 "
       "at 50 samples too, not the preprint's 8.46e-6.",
       joined({cells_in(oloid_modes, c.oloid, rules::convergence_ratio(12, claim_tolerance)),
               {{mode::rolling, {}, {}, rolling_convergence_reason}}}),
       truth_in(mode::corrected, "Under real rolling: " + rolling_convergence_reason)},
      {"face_scaling", "CDS ∝ N_faces^-2.03", "-2.03 (R² 0.999)",
       fmt::format("holds when the least-squares exponent of CDS against the face count (meshes with {} points per "
                   "circle) is within {:.0f} % of -2.03.",
                   fmt::join(c.points, ", "), 100 * claim_tolerance),
       "The paper-compatible and corrected rows mesh the preprint's (90,1,1) roller (`--body paper-oloid`).",
       joined({cells_in({mode::corrected, mode::paper, mode::true_oloid}, c.face_scan,
                        rules::face_count_exponent(-2.03, claim_tolerance)),
               {not_built(mode::rolling)}}),
       truth_in(mode::corrected)},
      {"tds_lowest", "The oloid's TDS is the lowest score of its invariant vector", "TDS 7.77e-7 lowest",
       "holds when no score of the vector (CDS, SDS, WDS_vol, WDS_depth, FDS) is below TDS and TDS is below CDS.",
       "The reference code computes WDS_vol from the same sum as TDS: the two are equal (the preprint's table prints "
       "7.77e-7 for both).",
       cells_in(oracle_modes, c.oloid, rules::tds_lowest()), truth_in(mode::corrected)},
  };
}
} // namespace rollcheck::audit::claims
