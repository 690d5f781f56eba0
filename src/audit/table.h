#pragma once
// The claim table of `rollcheck audit`, its result: each quantitative claim of
// the preprint, its paper value, its recomputations (one per mode:
// paper-compatible, matched mesh resolution, true oloid, corrected physics,
// real rolling, contact mechanics) with the exact commands that print the
// numbers used, and two verdicts: `reproduced` (the preprint's method and
// meshes give its number) and `true` (the best physics, over the modelling
// choices). Rendered as Markdown (for the README) and as JSON (for tests and
// scripts). The claims themselves are in audit_claims.h, their runner in
// audit_runner.h.
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace rollcheck::audit
{
/// One `rollcheck ...` command line, the values read from its JSON output,
/// keyed by JSON pointer (e.g. "/cds", "/convergence/cds/0/1"), and what it cost.
struct AuditCommand
{
  std::string id;      ///< "c1", "c2", ... as cited in the table
  std::string command; ///< the full command line, ending in `--json -`
  std::map<std::string, double> reads;
  double wall_s = 0; ///< its run's wall time
  double cpu_s = 0;  ///< its run's CPU time, user + system, its child processes' included
};

enum class Verdict
{
  holds,
  holds_only_paper_compatible,
  does_not_hold,
  cannot_be_tested,
  not_built
};
std::string verdict_text(Verdict v);

/// One recomputation of a claim in one mode. `applicable` false: the mode does
/// not apply to this claim ("n/a"); `built` false: the code is not built yet,
/// or, with an `untestable` reason, no computation can decide it.
struct AuditCell
{
  bool applicable = false;
  bool built = true;
  std::string value;                 ///< the recomputed value, as printed
  std::vector<std::string> commands; ///< ids of the commands it comes from
  bool holds = false;                ///< the verdict rule applied to this cell
  std::string untestable = {};       ///< why it cannot be tested; empty: it can
  /// Why the rule could not decide it, e.g. "cannot be decided at this
  /// resolution" (a difference inside the score's noise); empty: decided.
  std::string undecided = {};
};
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(AuditCell, applicable, built, value, commands, holds, untestable, undecided)

/// One of the two questions a claim answers, answered: its verdict, why, the
/// commands the reason rests on and the mode whose cell gave it (empty: none).
struct Judgement
{
  std::string verdict;
  std::string reason;
  std::vector<std::string> commands;
  std::string mode = {};
};
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(Judgement, verdict, reason, commands, mode)

/// The verdicts of `reproduced`: the preprint's method and meshes give its number.
namespace reproduction
{
inline const std::string reproduced = "reproduced";
inline const std::string not_reproduced = "not reproduced";
inline const std::string cannot_be_tested = "cannot be tested";
} // namespace reproduction
/// The verdicts of `true`: the best physics, robust over the modelling
/// choices; a dependent one is "depends on CHOICE[, CHOICE]".
namespace truth
{
inline const std::string holds = "holds";
inline const std::string does_not_hold = "does not hold";
inline const std::string cannot_be_tested = "cannot be tested";
inline const std::string depends_prefix = "depends on ";
} // namespace truth

struct AuditClaim
{
  std::string id; ///< the claim's short name: "oloid_cds", ...
  std::string claim;
  std::string paper_value;
  std::string rule;                       ///< the verdict rule applied to each cell
  std::map<std::string, AuditCell> cells; ///< by mode name; a mode not listed is n/a
  Verdict verdict = Verdict::not_built; ///< over the modes' cells (judge())
  std::string note;
  Judgement reproduced; ///< does the preprint's method give its number?
  Judgement truth;      ///< does the claim hold under the best physics, over the modelling choices? (JSON "true")
};

struct AuditTable
{
  std::vector<std::pair<std::string, std::string>> modes; ///< name, what it means
  std::vector<std::string> verdict_rules;
  std::vector<AuditClaim> claims;
  std::vector<AuditCommand> commands;
  double wall_s = 0;
  bool quick = false;
};

/// The mode whose cell decides whether a claim holds at all.
inline const std::string paper_compatible_mode = "paper-compatible";

/// holds if the paper-compatible cell holds and every other applicable, built
/// cell does; holds only in paper-compatible mode if the paper-compatible cell
/// holds and another does not; does not hold if the paper-compatible cell
/// does not. A claim with no built paper-compatible cell takes the verdict of
/// its other cells (e.g. the FEM item, which has no paper-compatible code).
/// Cells that cannot be tested or are undecided are left out; a claim with
/// only such cells (and cells not built) cannot be tested.
Verdict judge(const AuditClaim& claim);

/// `reproduced` from the claim's paper-compatible cell: its rule holds:
/// reproduced; fails: not reproduced; undecided or untestable: cannot be
/// tested. `note` is added to the reason; without that cell it is the reason
/// (cannot be tested).
Judgement judge_reproduced(const AuditClaim& claim, const std::string& note);

/// A judgement of `true` from the cell of `mode`: holds, does not hold, its
/// undecided text, or cannot be tested with its reason. `note` is added to the reason.
Judgement truth_from_cell(const AuditClaim& claim, const std::string& mode, const std::string& note);

std::string to_markdown(const AuditTable& table);
nlohmann::json to_json(const AuditTable& table);
void to_json(nlohmann::json& j, const AuditClaim& c);
void to_json(nlohmann::json& j, const AuditCommand& c);
} // namespace rollcheck::audit
