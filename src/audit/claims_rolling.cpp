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
       {{mode::rolling, {}, {}, rolling_convergence_reason}},
       truth_in(mode::rolling)},
      {"surface_coverage", "Every point of the oloid's surface touches the plane during one complete roll",
       "every point",
       fmt::format("the preprint's oracles: holds when no face goes untouched; real rolling (geometric contact width, "
                   "`--contact-width geometric`: which points touch, not how long): holds when the touched area fraction "
                   "is at least {:g}.",
                   full_coverage),
       "With the Hertz contact width the coverage falls as the faces are cut finer (the real-rolling cell's values at "
       "1, 8 and 16 subdivisions): the no-tension load rule unloads part of each ruling, where the Hertz strip has no "
       "width, and finer faces resolve those unloaded bands. The geometric width asks the theorem's question, which "
       "points touch.",
       {{mode::paper, c.paper_coverage, rules::every_face_touched()},
        {mode::true_oloid, c.oloid.at(mode::true_oloid), rules::every_face_touched()},
        {mode::corrected, c.oloid.at(mode::corrected), rules::every_face_touched()},
        {mode::rolling, c.rolling_coverage, rules::coverage_at_least(full_coverage)}},
       truth_in(mode::rolling, "A theorem for the true oloid: every point of its surface touches the plane in one "
                               "roll (Dirnböck and Stachel 1997)"),
       "The preprint's body is not the oloid: all of its untouched faces lie in its flat disc x = 1 (398 faces, "
       "3.1415 m²; `scripts/studies/untouched_faces.py`), which the true oloid does not have, and its oracle samples "
       "600 instants of the roll"},
  };
}
} // namespace rollcheck::audit::claims
