// The claims on the searches of the roller family: the preprint's quick grid
// (its approximate screen, the rigid-body revalidation of the top genomes)
// and the title claim searched continuously (`rollcheck optimize`).
#include "audit/claim_groups.h"

namespace rollcheck::audit::claims
{
namespace
{
/// The cells of a claim on the quick-grid search, paper-compatible and corrected.
std::vector<ClaimCell> search_cells(const ClaimCommands& c, const Rule& rule)
{
  return cells_in({mode::paper, mode::corrected}, c.search, rule);
}
} // namespace

std::vector<Claim> search_claims(const ClaimCommands& c)
{
  return {
      {"search_optimum", "Oloid a local optimum of its search family (quick grid, rigid revalidation of the top 5)",
       "no candidate beats the oloid",
       "holds when no revalidated candidate has a lower rigid-body CDS than the anchor oloid. Paper-compatible: "
       "the anchor (400 points per circle) and the candidates (300) are meshed apart, as in the preprint; the value "
       "adds how much the anchor's own CDS changes on the candidates' mesh (the matched search's anchor). True: the "
       "quick grid's best body under the resolution-free FEM-SDS against the oloid over the modelling choices "
       "(`rollcheck robustness`).",
       "The search family is the paper family; the true oloid is not one of its members (n/a).",
       {{mode::paper, {c.search.at(mode::paper)[0], c.search.at(mode::matched)[0]}, rules::no_candidate_beats_anchor()},
        {mode::matched, c.search.at(mode::matched), rules::no_candidate_beats_anchor()},
        {mode::corrected, c.search.at(mode::corrected), rules::no_candidate_beats_anchor()},
        not_built(mode::rolling)},
       truth_over_choices(c, {{"quick-grid best vs oloid", "contact_time_u", false},
                              {"quick-grid best vs oloid", "accumulated_pressure_whole", false},
                              {"quick-grid best vs oloid", "basquin_damage_whole", false}})},
      // The title claim searched continuously (`rollcheck optimize`, issue 17): BOBYQA from the family's
      // (90, 1, 1) in a box wider than the preprint's grid, every body at the same points per circle, the score's
      // noise measured at the start, gradient and Hessian there by finite differences above it.
      {"continuous_optimum",
       "The oloid is a local optimum of the developable roller family (the title claim), searched continuously from it",
       "local optimum",
       "holds when the search from the family's (90, 1, 1) finds no body better by more than the score's noise "
       "threshold and the gradient and Hessian there say local minimum; with a per-face score (all but U and the continuum FEM-SDS) any other "
       "outcome cannot be decided at this resolution. True: the family's optima found under U and FEM-SDS against "
       "the oloid at resolution-free scores (contact time, accumulated pressure, Basquin damage) over the modelling "
       "choices (`rollcheck robustness`).",
       "The paper family's (90, 1, 1) is the preprint's body, the centre-line family's is the true oloid "
       "(docs/methods/optimize.md). Scores over faces fall with the face count, which moves with the genome at a fixed number "
       "of points per circle; U does not depend on it.",
       joined({cells_in({mode::paper, mode::true_oloid, mode::corrected}, c.optimize,
                        rules::start_is_local_optimum(false)),
               cells_in({mode::rolling, mode::contact}, c.optimize, rules::start_is_local_optimum(true))}),
       truth_over_choices(c, {{"U optimum vs oloid", "contact_time_u", false},
                              {"FEM-SDS optimum vs oloid", "accumulated_pressure_whole", false},
                              {"U optimum vs oloid", "basquin_damage_whole", false},
                              {"FEM-SDS optimum vs oloid", "basquin_damage_whole", false}})},
      {"approximate_search",
       "Approximate search: 22 of 45 genomes beat the oloid; top (120, 0.70, 0.80) 38 % better",
       "22 of 45; 1.24e-6 vs 2.00e-6",
       at_claim_tolerance("holds when the count of genomes below the grid's oloid genome, the oloid's and the top "
                          "genome's approximate CDS are within {tolerance} of the paper's and the top genome is (120, "
                          "0.70, 0.80)."),
       "The preprint's 2.00e-6 is the grid's 300-point (90, 1, 1) genome, not the 400-point anchor the revalidation "
       "compares with.",
       search_cells(c, rules::approximate_screen(22, 2.00e-6, {120, 0.70, 0.80}, 1.24e-6, claim_tolerance)),
       truth_in(mode::corrected)},
      {"revalidation", "Rigid-body revalidation: (120, 1.30, 0.80), (90, 0.70, 0.80), (120, 0.70, 0.80)",
       "8.7e-7 (1.06x), 1.09e-6 (1.33x), 1.93e-6 (2.35x)",
       at_claim_tolerance("holds when each genome was revalidated and its rigid-body CDS and its CDS over the "
                          "reference oloid's are within {tolerance} of the paper's."),
       "The preprint's table lists three of the five revalidated genomes; the value names the others.",
       {{mode::paper, c.revalidation,
         rules::revalidated({{{120, 1.30, 0.80}, {8.7e-7, 1.06}},
                             {{90, 0.70, 0.80}, {1.09e-6, 1.33}},
                             {{120, 0.70, 0.80}, {1.93e-6, 2.35}}},
                            claim_tolerance)}},
       truth_untestable(per_face_value_reason)},
      {"improvement_direction",
       "ρ = 0.80 in all three non-oloid positions; the approximate layer finds the direction (ρ < 1, d < 1)",
       "ρ < 1, d < 1",
       "holds when the three revalidated genomes of lowest rigid-body CDS all have ρ < 1 and d < 1.",
       "",
       search_cells(c, rules::improvement_direction()), truth_in(mode::corrected)},
      {"sensitivity", "One-at-a-time sensitivity (approximate oracle, others at the oloid's values)",
       "ρ 0.80: 1.84e-6, 1.20: 2.42e-6; d 0.70: 1.85e-6, 1.30: 2.01e-6; θ 75: 1.85e-6, 120: 1.86e-6, 105: 2.30e-6",
       at_claim_tolerance("holds when each genome's approximate CDS (quick grid, 300 points, 200 steps) is within "
                          "{tolerance} of the paper's."),
       "",
       search_cells(c, rules::approximate_scores({{{90, 1.00, 0.80}, 1.84e-6},
                                                  {{90, 1.00, 1.20}, 2.42e-6},
                                                  {{90, 0.70, 1.00}, 1.85e-6},
                                                  {{90, 1.30, 1.00}, 2.01e-6},
                                                  {{75, 1.00, 1.00}, 1.85e-6},
                                                  {{120, 1.00, 1.00}, 1.86e-6},
                                                  {{105, 1.00, 1.00}, 2.30e-6}},
                                                 claim_tolerance)),
       truth_in(mode::corrected)},
  };
}
} // namespace rollcheck::audit::claims
