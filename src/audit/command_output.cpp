#include "audit/command_output.h"
#include "core/error.h"
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <limits>

namespace rollcheck::audit
{
std::string command_line(const CommandArgs& args) { return fmt::format("rollcheck {} --json -", fmt::join(args, " ")); }

CommandOutput::CommandOutput(std::string command, nlohmann::json json, CommandCost cost)
    : command_(std::move(command)), cost_(cost), json_(std::move(json))
{
}

const nlohmann::json& CommandOutput::at(const std::string& pointer) const
{
  const nlohmann::json::json_pointer p(pointer);
  if (!json_.contains(p))
    throw ComputationError(fmt::format("`{}` printed no '{}'", command_, pointer));
  return json_.at(p);
}

bool CommandOutput::has(const std::string& pointer) const
{
  return json_.contains(nlohmann::json::json_pointer(pointer));
}

double CommandOutput::number(const std::string& pointer)
{
  const nlohmann::json& v = at(pointer);
  if (!v.is_number() && v != "inf")
    throw ComputationError(fmt::format("`{}` printed '{}' = {}, not a number", command_, pointer, v.dump()));
  const double value = v.is_string() ? std::numeric_limits<double>::infinity() : v.get<double>();
  reads_[pointer] = value;
  return value;
}
} // namespace rollcheck::audit
