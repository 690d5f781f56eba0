// The claims on the contact stresses: Hertz against the FEM, the SDS's point
// Hertz against the rolling bodies' contact, and stress concentrated at the
// rims, the ends of each contact ruling.
#include "audit/claim_groups.h"
#include <fmt/format.h>

namespace rollcheck::audit::claims
{
std::vector<Claim> stress_claims(const ClaimCommands& c)
{
  return {
      {"fem_hertz",
       "Hertz analytics valid for a sphere and a cylinder; FEM check of Hertz (future work: the preprint's Dirichlet "
       "FEM failed)",
       "no agreement (not done)",
       fmt::format("holds when the penalty-contact FEM's contact size and peak pressure are within {:.0f} % of Hertz.",
                   100 * fem_tolerance),
       "There is no paper-compatible FEM to rerun (the preprint's Dirichlet model is not published). Corrected physics "
       "verifies the Hertz formulas on a sphere and a cylinder; contact mechanics is what the FEM finds about the "
       "pressures the scores use: the rolling bodies touch along a ruling, the FEM slices agree with line-contact "
       "Hertz, and the SDS's point Hertz lies far above both (row sds_point_hertz). The ruling's ends at the rims are "
       "not in this check.",
       {{mode::corrected, c.hertz, rules::fem_agrees_with_hertz(fem_tolerance)},
        {mode::contact, c.fem_sds_body, rules::fem_agrees_with_line_hertz(fem_tolerance)}},
       truth_in(mode::contact),
       "the preprint's Dirichlet FEM is not published (it reports no agreement)"},
      {"sds_point_hertz", "The SDS's point-Hertz pressures are the contact pressures of the rolling bodies",
       "point Hertz, R_eff = 1/√(κ1κ2)",
       at_claim_tolerance("holds when, at each FEM-solved orientation of real rolling, the point-Hertz peak pressure "
                          "the SDS uses is within {tolerance} of the FEM contact peak."),
       "The rolling bodies touch the plane along a ruling (line contact); the FEM slices agree with line-contact Hertz "
       "(value: worst FEM vs line Hertz).",
       {{mode::corrected, c.fem_orientations, rules::point_hertz_is_contact_pressure(claim_tolerance)}},
       truth_in(mode::corrected),
       "an assumption of the preprint's SDS, not a number its method computes"},
      {"fixed_loci",
       "The oloid eliminates stress concentrated at fixed loci of the body, the cylinder's geometric failure mode",
       "the cylinder \"concentrates fatigue damage at fixed loci, the geometric failure mode that the oloid "
       "eliminates\"",
       "holds when no loaded ruling end of the oloid's loop is singular and its largest end pressure over the loop is "
       "at most its largest interior pressure. Fatigue life: holds when, with the rim study's rounded edges, the "
       "oloid's interior governs its life (its rim ends' stress-volume integral below its interior's) at every load.",
       "Every loaded ruling ends on the body's rims, for the oloid its two generating circles: fixed loci of the body. "
       "A sharp obtuse edge there is singular against the rigid plane (Williams's wedge), which a 3D FEM of each end "
       "confirms (`rollcheck rim`, docs/methods/rims.md); against a block of the same steel every sharp edge above 77.45 deg "
       "is, the cylinder's square ends too. Rounded edges are finite: README, \"The rims\".",
       {{mode::contact, c.rims, rules::rims_free_of_concentration()},
        {mode::life, c.life, rules::interior_governs_life("oloid")}},
       truth_in(mode::contact),
       "a statement the preprint makes without a computation of the rims"},
  };
}
} // namespace rollcheck::audit::claims
