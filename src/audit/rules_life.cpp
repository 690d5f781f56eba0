// The rules that read `rollcheck life`: a body's L10 life against others'
// over the grid of modelling choices at every load, and its life with its
// rounded rim ends against without them.
#include "audit/cell_values.h"
#include "audit/rules.h"
#include "core/error.h"
#include <algorithm>
#include <fmt/format.h>
#include <fmt/ranges.h>

namespace rollcheck::audit::rules
{
namespace
{
/// The pointers of the comparisons `name` under `model` (orthogonal shear), one per load.
std::vector<std::string> comparison_pointers(const CommandOutput& life, const std::string& name,
                                             const std::string& model)
{
  std::vector<std::string> found;
  const nlohmann::json& list = life.at("/comparisons");
  for (std::size_t i = 0; i < list.size(); ++i)
    if (list[i].at("name") == name && list[i].at("model") == model && list[i].at("criterion") == "orthogonal_shear")
      found.push_back(fmt::format("/comparisons/{}", i));
  if (found.empty())
    throw ComputationError(fmt::format("`{}` has no comparison '{}' under {}", life.command(), name, model));
  return found;
}

std::string load_text(double load_n) { return fmt::format("{:.4g} N", load_n); }

/// Adds each choice of "depends on a, b" to `choices`, once.
void add_choices(std::vector<std::string>& choices, const std::string& verdict)
{
  std::string list = verdict.substr(std::string("depends on ").size());
  for (std::size_t start = 0, comma; start < list.size(); start = comma + 2)
  {
    comma = std::min(list.find(", ", start), list.size());
    const std::string choice = list.substr(start, comma - start);
    if (std::find(choices.begin(), choices.end(), choice) == choices.end())
      choices.push_back(choice);
  }
}
} // namespace

Rule lives_longer_over_choices(std::string body, std::vector<std::string> others)
{
  return [=](const std::vector<CommandOutput*>& out) {
    CommandOutput& life = *out[0];
    CellResult cell{"", true};
    bool refuted = false; // robust the other way at some load
    std::vector<std::string> depends;
    for (const std::string& other : others)
    {
      const std::string name = body + " vs " + other;
      // Lundberg-Palmgren decides: no fatigue limit, so every cell has a ratio.
      double lo = INFINITY, hi = 0;
      std::vector<std::string> loads;
      for (const std::string& c : comparison_pointers(life, name, "lundberg_palmgren"))
      {
        const std::string verdict = life.at(c + "/verdict").get<std::string>();
        const double min = life.number(c + "/life_ratio_min"), max = life.number(c + "/life_ratio_max");
        if (verdict.rfind("depends on ", 0) == 0)
          add_choices(depends, verdict);
        else if (verdict != "robust")
          throw ComputationError(fmt::format("`{}`: '{}' has verdict '{}'", life.command(), name, verdict));
        else
          refuted = refuted || max < 1;
        lo = std::min(lo, min), hi = std::max(hi, max);
        loads.push_back(load_text(life.number(c + "/load_n")));
      }
      cell.holds = cell.holds && lo >= 1;
      std::string text = fmt::format("L10 {} / {} {} ... {} over the grid's cells where both roll a loop, at {} "
                                     "(Lundberg-Palmgren)", body, other,
                                     sci(lo), sci(hi), fmt::join(loads, ", "));
      text += lo >= 1 ? fmt::format(", {} the longer-lived", body)
              : hi <= 1 ? fmt::format(", {} the longer-lived under every choice", other)
                        : ", the ranking flips";
      // Ioannides-Harris: its fatigue limit leaves loads where both live for ever.
      std::string limited;
      for (const std::string& c : comparison_pointers(life, name, "ioannides_harris"))
      {
        const std::string load = load_text(life.number(c + "/load_n"));
        append_listed(limited, life.at(c + "/untested_because").is_null()
                                   ? fmt::format("{} {} ... {}", load, sci(life.number(c + "/life_ratio_min")),
                                                 sci(life.number(c + "/life_ratio_max")))
                                   : load + " both infinite (cannot be tested)");
      }
      append_listed(cell.value, text + "; with the fatigue limit (Ioannides-Harris): " + limited, "; ");
    }
    if (!refuted && !depends.empty())
      cell.undecided = fmt::format("depends on {}", fmt::join(depends, ", "));
    return cell;
  };
}

Rule interior_governs_life(std::string body)
{
  return [=](const std::vector<CommandOutput*>& out) {
    CommandOutput& life = *out[0];
    const double at = life.number("/rims/rim_study_edge_radius_over_radius");
    const nlohmann::json& lives = life.at("/rims/lives");
    CellResult cell{"", true};
    std::string with_ends, governs;
    for (std::size_t i = 0; i < lives.size(); ++i)
    {
      if (lives[i].at("body") != body || lives[i].at("rows").empty())
        continue;
      const std::string p = fmt::format("/rims/lives/{}", i);
      const std::string load = load_text(life.number(p + "/load_n"));
      const nlohmann::json& rows = lives[i].at("rows");
      for (std::size_t r = 0; r < rows.size(); ++r)
        if (rows[r].at("edge_radius_over_radius").get<double>() == at)
        {
          const std::string row = fmt::format("{}/rows/{}", p, r);
          cell.holds = cell.holds && life.number(row + "/end_over_interior") < 1;
          append_listed(with_ends, fmt::format("{} ({})", sci(life.number(row + "/life_with_over_without_ends")), load));
        }
      const nlohmann::json& from = lives[i].at("interior_governs_from_edge_radius_over_radius");
      append_listed(governs, from.is_null() ? fmt::format("none up to the largest computed ({})", load)
                                            : fmt::format("{} r1 ({})", sci(life.number(p + "/interior_governs_from_edge_radius_over_radius")), load));
    }
    if (with_ends.empty())
      throw ComputationError(fmt::format("`{}` has no rim life of '{}' at r_e = {} r1", life.command(), body, at));
    cell.value = fmt::format("{}'s L10 with its rounded rim ends (r_e = {} r1) over without: {}; the interior governs "
                             "from r_e = {}",
                             body, sci(at), with_ends, governs);
    return cell;
  };
}
} // namespace rollcheck::audit::rules
