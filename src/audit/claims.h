#pragma once
// The quantitative claims of the preprint as data: for each claim its text, the
// preprint's value, the rule that decides it, and per mode (paper-compatible,
// matched resolution, true oloid, corrected physics, real rolling) the
// `rollcheck` commands whose JSON outputs give the numbers and the rule that
// turns those numbers into a cell of the table. The rules read the outputs by
// JSON pointer. audit_runner.h runs the commands and applies the rules.
#include <filesystem>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

namespace rollcheck::audit
{
/// A `rollcheck` command: its arguments after the program name (the runner
/// adds `-q` and `--json -`).
using CommandArgs = std::vector<std::string>;

/// The command as a user types it: `rollcheck ARGS --json -`.
std::string command_line(const CommandArgs& args);

/// The JSON output of one command, read by JSON pointer. Every number read is
/// recorded, so the table can list what it used from each command.
class CommandOutput
{
public:
  CommandOutput(std::string command, nlohmann::json json);

  /// The number at `pointer` ("inf" is +infinity). ComputationError naming
  /// the pointer and the command when the key is missing or not a number.
  double number(const std::string& pointer);
  /// The JSON value at `pointer` (labels, flags, arrays), not recorded;
  /// ComputationError naming the pointer and the command when it is missing.
  const nlohmann::json& at(const std::string& pointer) const;

  const std::string& command() const { return command_; }
  const std::map<std::string, double>& reads() const { return reads_; }

private:
  std::string command_;
  nlohmann::json json_;
  std::map<std::string, double> reads_;
};

/// A recomputed cell of the table: its value as printed, and whether it
/// satisfies its claim's rule.
struct CellResult
{
  std::string value;
  bool holds = false;
};

/// A verdict rule: decides one cell from the outputs of the cell's commands,
/// given in the order the cell lists them.
using Rule = std::function<CellResult(const std::vector<CommandOutput*>& outputs)>;

/// One mode's recomputation of a claim. Without a rule the cell is "not built
/// yet" (the code for that mode has no command yet), or, when `untestable`
/// gives a reason, "cannot be tested" (no computation can decide it).
struct ClaimCell
{
  std::string mode;
  std::vector<CommandArgs> commands;
  Rule rule;
  std::string untestable = {};
};

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

struct Claim
{
  std::string id;          ///< a short name, for messages: "oloid_cds", ...
  std::string claim;       ///< the claim as the table states it
  std::string paper_value; ///< the preprint's value, as printed
  std::string rule;        ///< the rule that decides each cell, in words
  std::string note;
  std::vector<ClaimCell> cells; ///< a mode without a cell does not apply (n/a)
};

/// The modes of the table, in column order, with what each means.
std::vector<std::pair<std::string, std::string>> audit_modes();

/// How the cells of a claim make its verdict, in words.
std::vector<std::string> audit_verdict_rules();

/// The claims, with commands on the reference meshes in `reference_meshes`
/// (oloid_reference.obj, cylinder_reference.obj). `quick`: fewer thresholds
/// and mesh sizes.
std::vector<Claim> audit_claims(const std::filesystem::path& reference_meshes, bool quick);

/// The verdict rules the claims use. `oloid, cylinder` outputs come in that
/// order; a ratio is the cylinder's value over the oloid's.
namespace rules
{
/// outputs[0]'s number at `pointer` is within `tolerance` of `paper`.
Rule value_within(std::string pointer, double paper, double tolerance);
/// (oloid, cylinder): each ratio at `pointer` is within `tolerance` of its paper value.
Rule ratios_within(std::vector<std::pair<std::string, double>> pointer_paper, double tolerance);
/// (oloid, cylinder) rolling: the oloid's uniformity score U is below the cylinder's.
Rule oloid_more_uniform();
/// (oloid, cylinder) rolling: the ratio of the uniformity scores U exceeds 1.
Rule uniformity_ratio_above_one();
/// (search): no revalidated candidate has a lower rigid-body CDS than the anchor.
Rule no_candidate_beats_anchor();
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
/// (hertz axi, hertz plane strain): contact size and peak pressure errors
/// against Hertz are at most `tolerance`.
Rule fem_agrees_with_hertz(double tolerance);
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
/// (oracle): no score of the vector is below TDS, and TDS is below CDS.
Rule tds_lowest();
/// (preprint's oracles): no face goes untouched.
Rule every_face_touched();
/// (real rolling): the touched area fraction is at least `fraction`.
Rule coverage_at_least(double fraction);
/// (fem-sds): each solved orientation's point-Hertz peak is within
/// `tolerance` of the FEM peak.
Rule point_hertz_is_contact_pressure(double tolerance);
/// optimize: the start is not beaten beyond the noise threshold and its verdict is "local minimum".
Rule start_is_local_optimum();
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
} // namespace rules
} // namespace rollcheck::audit
