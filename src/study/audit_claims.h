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

namespace rollcheck::study
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
/// yet": the code for that mode has no command yet.
struct ClaimCell
{
  std::string mode;
  std::vector<CommandArgs> commands;
  Rule rule;
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
} // namespace rules
} // namespace rollcheck::study
