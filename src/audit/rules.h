#pragma once
// The verdict rules of the audit's claims: each decides one cell of the table
// from the JSON outputs of the commands the cell cites (command_output.h).
// Implemented by kind of command read: rules_values.cpp (numbers against the
// paper's, any command), rules_oracle.cpp (the oracle and mesh outputs),
// rules_search.cpp (search and optimize), rules_contact.cpp (FEM, Hertz, rims),
// rules_robustness.cpp (a ranking of bodies over the modelling choices),
// rules_life.cpp (rolling-contact fatigue life).
#include "audit/command_output.h"
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace rollcheck::audit
{
/// A recomputed cell of the table: its value as printed, and whether it
/// satisfies its claim's rule; or, when `undecided` says why, neither (a
/// difference inside the score's noise: "cannot be decided at this
/// resolution"; a ranking that flips: "depends on CHOICE").
struct CellResult
{
  std::string value;
  bool holds = false;
  std::string undecided = {};
};

/// A claim's ranking of two bodies under one score of `rollcheck robustness`:
/// its comparison's name ("oloid vs cylinder"), the score's key, and whether
/// the claim has the comparison's first body the more even (lower score).
struct Ranking
{
  std::string comparison;
  std::string score;
  bool first_more_even = true;
};

/// A verdict rule: decides one cell from the outputs of the cell's commands,
/// given in the order the cell lists them.
using Rule = std::function<CellResult(const std::vector<CommandOutput*>& outputs)>;

/// A genome (theta, d, rho) of the paper family, as the search prints it.
struct Genome
{
  double theta_deg, offset, ratio;
};

/// A number a rule expects: `pointer` in output `output` against the paper's
/// value printed with `digits` significant digits, labelled `label` (values
/// multiplied by `scale`: 1e-6 for MPa).
struct Expected
{
  std::size_t output;
  std::string pointer;
  double paper;
  int digits;
  std::string label;
  double scale = 1;
};

/// The verdict rules the claims use. `oloid, cylinder` outputs come in that
/// order; a ratio is the cylinder's value over the oloid's.
namespace rules
{
// Numbers against the paper's (rules_values.cpp).

/// outputs[0]'s number at `pointer` is within `tolerance` of `paper`.
Rule value_within(std::string pointer, double paper, double tolerance);
/// (oloid, cylinder): each ratio at `pointer` is within `tolerance` of its paper value.
Rule ratios_within(std::vector<std::pair<std::string, double>> pointer_paper, double tolerance);
/// Every rule holds; their values joined by "; ".
Rule all_of(std::vector<Rule> parts);
/// Each expected number is within `tolerance` of its paper value; the value
/// also counts those that agree to the paper's printed digits (rounded or
/// truncated).
Rule each_within(std::vector<Expected> expected, double tolerance);
/// outputs[numerator] / outputs[denominator] (at their pointers) is within
/// `tolerance` of `paper`.
Rule ratio_within(std::string label, std::pair<std::size_t, std::string> numerator,
                  std::pair<std::size_t, std::string> denominator, double paper, double tolerance);
/// outputs[output]'s number at `pointer` is below `limit`.
Rule below(std::string label, std::size_t output, std::string pointer, double limit);

// The oracle and mesh outputs (rules_oracle.cpp).

/// (oloid, cylinder) rolling: the oloid's U_inf (the resolution-free
/// uniformity_score_continuum) is below the cylinder's.
Rule oloid_more_uniform();
/// (oloid, cylinder) rolling: cylinder U_inf / oloid U_inf exceeds 1.
Rule uniformity_ratio_above_one();
/// (oracle): CDS at the first over the last convergence snapshot is within
/// `tolerance` of `rate`.
Rule convergence_ratio(double rate, double tolerance);
/// (oracle runs at several mesh sizes): the least-squares exponent of CDS
/// against the face count is within `tolerance` of `exponent`.
Rule face_count_exponent(double exponent, double tolerance);
/// (oloid, cylinder at the default threshold, then pairs at other thresholds):
/// the CDS ratio stays within `tolerance` of its value at the default.
Rule threshold_spread(double tolerance);
/// (oloid, cylinder[, oloid, cylinder with the right E* alone]): each
/// cylinder's FDS is infinite and each oloid's finite.
Rule cylinder_fds_infinite();
/// (mesh outputs, one per label): each area is within `tolerance` of `area`.
Rule areas_within(double area, double tolerance, std::vector<std::string> labels);
/// (oracle): no score of the vector is below TDS, and TDS is below CDS.
Rule tds_lowest();
/// (preprint's oracles[, the same run with --per-face]): no face goes
/// untouched; with the per-face run the value gives the untouched area.
Rule every_face_touched();
/// (real rolling[, real rolling with the Hertz width at several face
/// subdivisions]): the touched area fraction of the first is at least
/// `fraction`; the value lists the others' coverage by subdivisions.
Rule coverage_at_least(double fraction);

// Search and optimize (rules_search.cpp).

/// (search[, search with the anchor meshed like the candidates]): no
/// revalidated candidate has a lower rigid-body CDS than the anchor. With the
/// second output, a candidate below the anchor by less than the anchor's own
/// change between the two meshes (the score's change under refinement) is
/// within noise: not a beat.
Rule no_candidate_beats_anchor();
/// (search): the approximate layer: `beaten` genomes (within `tolerance`)
/// score below the grid's oloid genome (within `tolerance` of `oloid_cds`),
/// and the best is `top` (its CDS within `tolerance` of `top_cds`).
Rule approximate_screen(int beaten, double oloid_cds, Genome top, double top_cds, double tolerance);
/// (search, oracle on the reference oloid): each genome was revalidated and
/// its rigid-body CDS and CDS over the oloid's are within `tolerance` of the
/// paper's (cds, ratio); the value also names revalidated genomes not listed.
Rule revalidated(std::vector<std::pair<Genome, std::pair<double, double>>> paper, double tolerance);
/// (search): the three revalidated genomes of lowest rigid-body CDS all have
/// rho < 1 and d < 1, the direction the approximate layer found.
Rule improvement_direction();
/// (search): each genome's approximate CDS is within `tolerance` of its paper
/// value (counting those to the printed 3 digits).
Rule approximate_scores(std::vector<std::pair<Genome, double>> paper, double tolerance);
/// optimize: the start is not beaten beyond the noise threshold and its
/// verdict is "local minimum". `resolution_free`: the score does not move
/// with the face count (U); otherwise (a per-face score, which moves with the
/// genome's face count by as much as the gains) anything but a local minimum
/// not beaten cannot be decided at this resolution.
Rule start_is_local_optimum(bool resolution_free);

// FEM, Hertz and the rims (rules_contact.cpp).

/// (hertz axi, hertz plane strain): contact size and peak pressure errors
/// against Hertz are at most `tolerance`.
Rule fem_agrees_with_hertz(double tolerance);
/// (fem-sds): each solved orientation's point-Hertz peak is within
/// `tolerance` of the FEM peak.
Rule point_hertz_is_contact_pressure(double tolerance);
/// (body, cylinder) fem-sds: both converged, and cylinder / body FEM-SDS within `tolerance` of `paper`.
Rule converged_sds_ratio(double paper, double tolerance);
/// (body, cylinder) fem-sds: the largest line-contact stress amplitude at the
/// fatigue load against the endurance limit; holds when only the body's exceeds it.
Rule line_contact_fatigue(double fatigue_load_n, double endurance_limit_pa);
/// fem-sds: the FEM slices and FEM-SDS agree with line-contact Hertz within `tolerance`.
Rule fem_agrees_with_line_hertz(double tolerance);
/// (oloid, cylinder) rim --body: holds when none of the oloid's loaded rim
/// ends is singular and its loop's largest end pressure is at most its
/// largest interior pressure (no stress concentrated at its rims).
Rule rims_free_of_concentration();

// Rankings over the modelling choices (rules_robustness.cpp).

/// (robustness): each ranking's comparison at its score, as `rollcheck
/// robustness` judged it over its grid: holds when every one is robust the
/// claim's way; fails when one is robust the other way; otherwise undecided,
/// "depends on" its choices, the reason naming the flip nearest the default
/// choices (E = 0.1, hertz, dynamic, 0.05).
Rule rankings_over_choices(std::vector<Ranking> rankings);

// Rolling-contact fatigue life (rules_life.cpp).

/// (life): `body`'s L10 life against each of `others` ("BODY vs OTHER" of
/// `rollcheck life`, orthogonal shear): holds when Lundberg-Palmgren's life
/// ratio is at least 1 in every cell of the grid at every load; the value
/// adds Ioannides-Harris's ratios, or why a load cannot be tested (both
/// lives infinite below the fatigue limit); a ranking that flips at some
/// load leaves it undecided ("depends on" its choices).
Rule lives_longer_over_choices(std::string body, std::vector<std::string> others);
/// (life): `body`'s life with its rounded rim ends at the rim study's edge
/// radius over without them, at every load: holds when the interior governs
/// (the ends' integral below the interior's) at every load; the value adds
/// the edge radius from which the interior governs.
Rule interior_governs_life(std::string body);
} // namespace rules
} // namespace rollcheck::audit
