#pragma once
// A `rollcheck` command the audit cites and its JSON output, read by JSON
// pointer: the input of every rule (rules.h).
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace rollcheck::audit
{
/// A `rollcheck` command: its arguments after the program name (the runner
/// adds `-q` and `--json -`).
using CommandArgs = std::vector<std::string>;

/// The command as a user types it: `rollcheck ARGS --json -`.
std::string command_line(const CommandArgs& args);

/// What running a command cost: its wall time and its CPU time (user +
/// system, its own child processes' included), in seconds.
struct CommandCost
{
  double wall_s = 0;
  double cpu_s = 0;
};

/// The JSON output of one command, read by JSON pointer. Every number read is
/// recorded, so the table can list what it used from each command.
class CommandOutput
{
public:
  CommandOutput(std::string command, nlohmann::json json, CommandCost cost = {});

  /// The number at `pointer` ("inf" is +infinity). ComputationError naming
  /// the pointer and the command when the key is missing or not a number.
  double number(const std::string& pointer);
  /// The JSON value at `pointer` (labels, flags, arrays), not recorded;
  /// ComputationError naming the pointer and the command when it is missing.
  const nlohmann::json& at(const std::string& pointer) const;
  /// Whether the output has a value at `pointer`.
  bool has(const std::string& pointer) const;

  const std::string& command() const { return command_; }
  const std::map<std::string, double>& reads() const { return reads_; }
  const CommandCost& cost() const { return cost_; }

private:
  std::string command_;
  CommandCost cost_;
  nlohmann::json json_;
  std::map<std::string, double> reads_;
};
} // namespace rollcheck::audit
