#include "io/report_json_inputs.h"
#include "core/bounded_file.h"
#include "core/error.h"
#include <fmt/format.h>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace rollcheck::io
{
namespace
{
/// The largest JSON a report reads: an audit's is about 1 MB.
constexpr std::size_t max_report_json_bytes = std::size_t(64) << 20;

void require_json_object(const std::filesystem::path& path, const std::string& option, const char* writer,
                         const std::vector<const char*>& keys)
{
  if (path.empty())
    return;
  const std::string text = core::read_bounded_file(path, option, max_report_json_bytes);
  const nlohmann::json j = nlohmann::json::parse(text, nullptr, false);
  if (!j.is_object())
    throw InputError(fmt::format("{} '{}': not a JSON object (the JSON of `{}`)", option, path.string(), writer));
  for (const char* key : keys)
    if (!j.contains(key))
      throw InputError(fmt::format("{} '{}': no key '{}': not the JSON of `{}`", option, path.string(), key, writer));
}
} // namespace

void require_report_json_inputs(const ReportJsonInputs& inputs, const char* command)
{
  const std::string prefix = fmt::format("{} ", command);
  require_json_object(inputs.validation, prefix + "--validation", "rollcheck validate", {"checks", "passed", "failed"});
  require_json_object(inputs.audit, prefix + "--audit", "rollcheck audit --json",
                      {"modes", "claims", "commands", "verdict_rules", "quick", "wall_s"});
  require_json_object(inputs.robustness, prefix + "--robustness", "rollcheck robustness --json",
                      {"comparisons", "grid"});
  require_json_object(inputs.life, prefix + "--life", "rollcheck life --json", {"comparisons", "rims", "wall_s"});
}
} // namespace rollcheck::io
