#pragma once
// The quantitative claims of the preprint as data: for each claim its text, the
// preprint's value, the rule that decides it, and per mode (paper-compatible,
// matched resolution, true oloid, corrected physics, real rolling, contact
// mechanics: modes.h) the `rollcheck` commands whose JSON outputs give the
// numbers and the rule that turns those numbers into a cell of the table
// (rules.h). The records are in claims_*.cpp, one file per group of claims,
// on the commands of claim_commands.h; runner.h runs the commands and applies
// the rules.
#include "audit/command_output.h"
#include "audit/modes.h"
#include "audit/rules.h"
#include <filesystem>
#include <string>
#include <vector>

namespace rollcheck::audit
{
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

/// Where a claim's `true` verdict comes from: the cell of `mode` (the best
/// physics the table has for it), its own `commands` and `rule` (a ranking of
/// bodies over the modelling choices, rules::rankings_over_choices), or
/// nowhere, for the `untestable` reason. `note` is added to its reason.
struct TruthSource
{
  std::string mode = {};
  std::vector<CommandArgs> commands = {};
  Rule rule = {};
  std::string untestable = {};
  std::string note = {};
};

struct Claim
{
  std::string id;          ///< a short name, for messages: "oloid_cds", ...
  std::string claim;       ///< the claim as the table states it
  std::string paper_value; ///< the preprint's value, as printed
  std::string rule;        ///< the rule that decides each cell, in words
  std::string note;
  std::vector<ClaimCell> cells; ///< a mode without a cell does not apply (n/a)
  TruthSource truth = {};
  /// Added to the `reproduced` reason; without a paper-compatible cell, the
  /// reason the preprint's method cannot be rerun.
  std::string reproduced_note = {};
};

/// How the cells of a claim make its verdict, in words.
std::vector<std::string> audit_verdict_rules();

/// The claims, in the table's order, with commands on the reference meshes in
/// `reference_meshes` (oloid_reference.obj, cylinder_reference.obj). `quick`:
/// fewer thresholds and mesh sizes.
std::vector<Claim> audit_claims(const std::filesystem::path& reference_meshes, bool quick);
} // namespace rollcheck::audit
