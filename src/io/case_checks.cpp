#include "io/case_checks.h"
#include <cmath>
#include <fmt/format.h>

namespace rollcheck::io
{
std::string CaseCheck::criterion() const
{
  if (max_abs)
    return fmt::format("abs(x) <= {:g}", *max_abs);
  if (value)
    return fmt::format("within {:g} % of {:g}", 100 * rel_tol, *value);
  return fmt::format("is {}", expect.value_or(false));
}

std::vector<CheckOutcome> evaluate_checks(const std::vector<CaseCheck>& checks, const nlohmann::json& summary)
{
  std::vector<CheckOutcome> outcomes;
  for (const CaseCheck& check : checks)
  {
    CheckOutcome o{check, "missing", false};
    const nlohmann::json::json_pointer pointer(check.pointer);
    if (summary.contains(pointer))
    {
      const nlohmann::json& found = summary.at(pointer);
      if (check.expect && found.is_boolean())
      {
        o.measured = found.get<bool>() ? "true" : "false";
        o.passed = found.get<bool>() == *check.expect;
      }
      else if (!check.expect && found.is_number())
      {
        const double x = found.get<double>();
        o.measured = fmt::format("{:.6g}", x);
        o.passed = check.max_abs ? std::abs(x) <= *check.max_abs
                                 : std::abs(x / *check.value - 1) <= check.rel_tol;
      }
      else
        o.measured = fmt::format("{} (wrong type)", found.dump());
    }
    outcomes.push_back(std::move(o));
  }
  return outcomes;
}
} // namespace rollcheck::io
