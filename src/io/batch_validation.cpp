#include "io/batch_validation.h"
#include "io/batch_record.h"
#include "io/parameters.h"
#include <algorithm>
#include <fmt/format.h>

namespace rollcheck::io
{
namespace
{
/// A row for what could not be checked at all.
CaseVerdict unchecked(const CaseOutcome& c, const std::string& why)
{
  CaseCheck check;
  check.pointer = "-";
  check.reference = why;
  return {c.name, c.kind, {check, "-", false}};
}
} // namespace

std::vector<CaseVerdict> check_batch(const BatchResult& batch, const std::filesystem::path& out)
{
  std::vector<CaseVerdict> verdicts;
  for (const CaseOutcome& c : batch.outcomes)
  {
    if (c.status != CaseStatus::ok && c.status != CaseStatus::skipped)
    {
      verdicts.push_back(unchecked(c, fmt::format("the case {}: {}", status_name(c.status), c.message)));
      continue;
    }
    const std::vector<CaseCheck> checks = read_case_file(c.file).checks;
    const std::optional<nlohmann::json> record = read_case_record(out, c.hash);
    if (checks.empty() || !record || !record->contains("summary"))
    {
      verdicts.push_back(unchecked(c, checks.empty() ? "the case file states no [[check]]" : "no stored result"));
      continue;
    }
    for (CheckOutcome& o : evaluate_checks(checks, record->at("summary")))
      verdicts.push_back({c.name, c.kind, std::move(o)});
  }
  return verdicts;
}

nlohmann::json to_json(const std::vector<CaseVerdict>& verdicts)
{
  nlohmann::json rows = nlohmann::json::array();
  for (const CaseVerdict& v : verdicts)
    rows.push_back({{"case", v.case_name},
                    {"kind", v.kind},
                    {"pointer", v.outcome.check.pointer},
                    {"criterion", v.outcome.check.pointer == "-" ? "-" : v.outcome.check.criterion()},
                    {"measured", v.outcome.measured},
                    {"reference", v.outcome.check.reference},
                    {"passed", v.outcome.passed}});
  const auto passed = std::ranges::count_if(verdicts, [](const CaseVerdict& v) { return v.outcome.passed; });
  return {{"checks", rows},
          {"passed", passed},
          {"failed", static_cast<std::ptrdiff_t>(verdicts.size()) - passed}};
}

std::string verdict_table(const std::vector<CaseVerdict>& verdicts)
{
  std::string table = "| case | value | criterion | measured | reference | verdict |\n|---|---|---|---|---|---|\n";
  for (const CaseVerdict& v : verdicts)
    table += fmt::format("| {} | {} | {} | {} | {} | {} |\n", v.case_name, v.outcome.check.pointer,
                         v.outcome.check.pointer == "-" ? "-" : v.outcome.check.criterion(), v.outcome.measured,
                         v.outcome.check.reference, v.outcome.passed ? "pass" : "**FAIL**");
  return table;
}
} // namespace rollcheck::io
