#pragma once
// Runs the audit: every command of the claims (claims.h) once, in
// parallel, as child processes of the `rollcheck` executable (core's process
// runner), then reads each claim's numbers from their JSON outputs and decides
// its cells and verdict (the table of table.h).
#include "audit/claims.h"
#include "audit/table.h"
#include <filesystem>
#include <vector>

namespace rollcheck::audit
{
struct AuditSettings
{
  std::filesystem::path reference_meshes; ///< holds oloid_reference.obj, cylinder_reference.obj
  bool quick = false;                     ///< fewer thresholds and mesh sizes
  unsigned threads = 0;                   ///< commands run at once; 0: one per core
  /// Ids of the claims decided (Claim::id), in the table's order whatever
  /// their order here; empty: every claim. Only their commands run.
  std::vector<std::string> claims = {};
};

/// The claims of `all` whose ids `ids` names, in the order of `all`; every
/// claim when `ids` is empty. An id no claim has is an InputError naming it
/// and the ids there are.
std::vector<Claim> select_claims(std::vector<Claim> all, const std::vector<std::string>& ids);

/// The id the table cites command i by: "c{i+1}".
std::string command_id(std::size_t i);

/// Each command of `claims` once, in the order the claims first list them;
/// command i is cited in the table as "c{i+1}".
std::vector<CommandArgs> distinct_commands(const std::vector<Claim>& claims);

/// Runs each command as `rollcheck -q ARGS --json FILE` with the executable
/// `rollcheck`, `threads` at a time (the long subcommands, optimize, rim,
/// robustness, fem-sds, search and hertz, started first; the outputs stay in
/// the commands' order), FILE in a scratch folder removed after, and parses
/// FILE (the JSON the listed `--json -` prints), each output with its
/// command's wall and CPU time (the ten costliest go to the log). A command
/// that fails or writes no JSON is a ComputationError naming it, with its stderr.
std::vector<CommandOutput> run_commands(const std::vector<CommandArgs>& commands,
                                        const std::filesystem::path& rollcheck, unsigned threads);

/// The claims decided: each cell by its rule on `outputs` (those of
/// distinct_commands(claims), in that order), each claim by judge(); and the
/// commands with the values read from them. A rule reading a key a command did
/// not print is a ComputationError naming the claim, the key and the command.
AuditTable decide_claims(const std::vector<Claim>& claims, std::vector<CommandOutput>& outputs);

/// The whole audit on `settings`, run with the executable `rollcheck`; the
/// commands' outputs (in the table's command order, "c1" first) also go to
/// `outputs` when it is given, for a caller that keeps them.
AuditTable run_audit(const AuditSettings& settings, const std::filesystem::path& rollcheck,
                     std::vector<CommandOutput>* outputs = nullptr);
} // namespace rollcheck::audit
