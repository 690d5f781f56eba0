// The rules that compare numbers of any command with the paper's: one value,
// the cylinder / oloid ratios, a list of expected values, a ratio of two
// outputs, a bound; and their conjunction.
#include "audit/cell_values.h"
#include "audit/rules.h"
#include <fmt/format.h>

namespace rollcheck::audit::rules
{
Rule value_within(std::string pointer, double paper, double tolerance)
{
  return [=](const std::vector<CommandOutput*>& out) {
    const double v = out[0]->number(pointer);
    return CellResult{sci(v), within(v, paper, tolerance)};
  };
}

Rule ratios_within(std::vector<std::pair<std::string, double>> pointer_paper, double tolerance)
{
  return [=](const std::vector<CommandOutput*>& out) {
    CellResult cell{"", true};
    for (const auto& [pointer, paper] : pointer_paper)
    {
      const double r = out[1]->number(pointer) / out[0]->number(pointer);
      cell.holds = cell.holds && within(r, paper, tolerance);
      append_listed(cell.value, times(r));
    }
    return cell;
  };
}

Rule all_of(std::vector<Rule> parts)
{
  return [=](const std::vector<CommandOutput*>& out) {
    CellResult cell{"", true};
    for (const Rule& part : parts)
    {
      const CellResult r = part(out);
      cell.holds = cell.holds && r.holds;
      append_listed(cell.value, r.value, "; ");
    }
    return cell;
  };
}

Rule each_within(std::vector<Expected> expected, double tolerance)
{
  return [=](const std::vector<CommandOutput*>& out) {
    std::vector<Checked> numbers;
    for (const Expected& e : expected)
    {
      const double v = out[e.output]->number(e.pointer) * e.scale;
      numbers.push_back({fmt::format("{} {:.4g}", e.label, v), v, e.paper, e.digits});
    }
    return each_checked(numbers, tolerance);
  };
}

Rule ratio_within(std::string label, std::pair<std::size_t, std::string> numerator,
                  std::pair<std::size_t, std::string> denominator, double paper, double tolerance)
{
  return [=](const std::vector<CommandOutput*>& out) {
    const double r = out[numerator.first]->number(numerator.second) /
                     out[denominator.first]->number(denominator.second);
    return CellResult{fmt::format("{} {:#.3g}x", label, r), within(r, paper, tolerance)};
  };
}

Rule below(std::string label, std::size_t output, std::string pointer, double limit)
{
  return [=](const std::vector<CommandOutput*>& out) {
    const double v = out[output]->number(pointer);
    return CellResult{fmt::format("{} {:.3g}", label, v), v < limit};
  };
}
} // namespace rollcheck::audit::rules
