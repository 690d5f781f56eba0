// The claims on the roll itself: the convergence of its scores and the
// surface it covers, under the preprint's oracles and under real rolling.
#include "audit/claim_groups.h"
#include <fmt/format.h>

namespace rollcheck::audit::claims
{
namespace
{
/// Real rolling: every point touched, up to the rounding of the sub-face areas.
constexpr double full_coverage = 0.999;
} // namespace

std::vector<Claim> rolling_claims(const ClaimCommands& c)
{
  return {
      {"rolling_convergence", "CDS converges as O(1/T) under real rolling", "O(1/T)",
       "cannot be tested: see the cell.",
       "",
       {{mode::rolling, {}, {}, rolling_convergence_reason}}},
      {"surface_coverage", "Every point of the oloid's surface touches the plane during one complete roll",
       "every point",
       fmt::format("the preprint's oracles: holds when no face goes untouched; real rolling (geometric contact width, "
                   "`--contact-width rigid`: which points touch, not how long): holds when the touched area fraction "
                   "is at least {:g}.",
                   full_coverage),
       "With the Hertz contact width the strip (about 4e-5 m) is narrower than the spacing of the time samples on the "
       "cut faces, so its coverage (0.93-0.95) measures the sampling, not the geometry.",
       joined({cells_in(oloid_modes, c.oloid, rules::every_face_touched()),
               {{mode::rolling, c.rolling_coverage, rules::coverage_at_least(full_coverage)}}})},
  };
}
} // namespace rollcheck::audit::claims
