#pragma once
// The claims' records, one table per group of claims (claims_*.cpp), and what
// the records share: the tolerances of their rules and the ways a record lists
// its cells. claims.cpp puts the records in the table's order.
#include "audit/claim_commands.h"
#include "audit/claims.h"
#include "audit/modes.h"
#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

namespace rollcheck::audit
{
/// Rule of the ratio and value claims: the preprint's number reproduced to 20 %.
constexpr double claim_tolerance = 0.20;
/// 4 pi r^2 vs a mesh: the true oloid's 400-point hull is 3e-5 below it.
constexpr double area_tolerance = 1e-3;
/// The FEM check confirms Hertz when a and p0 agree to 5 % (the FEM issues'
/// own acceptance is 1-2 %; 5 % leaves room for the coarse default meshes).
constexpr double fem_tolerance = 0.05;

/// The modes that score a body with the rigid-body oracle.
inline const std::vector<std::string> oracle_modes = {mode::paper, mode::matched, mode::true_oloid, mode::corrected};
/// The oracle modes with an oloid of their own (matched resolution meshes
/// only the cylinder anew).
inline const std::vector<std::string> oloid_modes = {mode::paper, mode::true_oloid, mode::corrected};

/// Why a value of the preprint's per-face scores has no `true` verdict.
inline const std::string per_face_value_reason =
    "a value of the preprint's per-face template on its meshes, which moves with the face count (about N^-2, row "
    "face_scaling): no resolution-free score has this number; the bodies' comparisons are judged in rows cds_ratio, "
    "sds_ratio, all_metrics and continuous_optimum";

/// The claim's `true` verdict from its cell of `mode`, the best physics the table has for it.
TruthSource truth_in(std::string mode, std::string note = {});
/// The claim's `true` verdict from rankings of bodies over the modelling choices (`rollcheck robustness`).
TruthSource truth_over_choices(const ClaimCommands& c, std::vector<Ranking> rankings, std::string note = {});
/// A claim with no `true` verdict, for `reason`.
TruthSource truth_untestable(std::string reason);

/// Why no command can show O(1/T) convergence under real rolling.
inline const std::string rolling_convergence_reason =
    "real rolling prints no CDS and no convergence snapshots (`rollcheck oracle --oracle rolling` JSON has neither); "
    "its roll is periodic, so its contact measure is exact after one loop, not converging like 1/T";

/// `text` with each "{tolerance}" the claims' tolerance in per cent: "20 %".
std::string at_claim_tolerance(std::string_view text);

/// One cell per mode of `modes`, each on its mode's commands, all decided by `rule`.
std::vector<ClaimCell> cells_in(const std::vector<std::string>& modes, const PerMode& commands, const Rule& rule);
/// A cell of a mode whose code has no command yet.
ClaimCell not_built(const std::string& mode);
/// The lists of cells one after the other.
std::vector<ClaimCell> joined(std::initializer_list<std::vector<ClaimCell>> lists);

/// The claims' records, one table per group of claims: each record the
/// claim's id, its text, the preprint's value, its rule in words, a note and
/// its cells, on the commands in `c`.
namespace claims
{
/// The oloid's scores: its CDS, their convergence and scaling, its lowest score (claims_oloid_scores.cpp).
std::vector<Claim> oloid_score_claims(const ClaimCommands& c);
/// The cylinder over the oloid (claims_ratios.cpp).
std::vector<Claim> ratio_claims(const ClaimCommands& c);
/// The scored body's area and curvatures (claims_body.cpp).
std::vector<Claim> body_claims(const ClaimCommands& c);
/// The preprint's tables and timings (claims_tables.cpp).
std::vector<Claim> table_claims(const ClaimCommands& c);
/// The searches of the roller family (claims_search.cpp).
std::vector<Claim> search_claims(const ClaimCommands& c);
/// The roll's convergence and coverage (claims_rolling.cpp).
std::vector<Claim> rolling_claims(const ClaimCommands& c);
/// The contact stresses: Hertz, FEM and the rims (claims_stress.cpp).
std::vector<Claim> stress_claims(const ClaimCommands& c);
} // namespace claims
} // namespace rollcheck::audit
