// The rule that reads `rollcheck robustness`: a claim's ranking of two bodies
// under one score, as judged over the grid of modelling choices (rolling
// energy, contact width, load rule, end margin). Robust the claim's way: it
// holds; robust the other way: it fails; a ranking that flips: the claim
// depends on the choices it flips on, and the reason names the flip nearest
// the default choices.
#include "audit/cell_values.h"
#include "audit/rules.h"
#include "core/error.h"
#include <algorithm>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <map>

namespace rollcheck::audit::rules
{
namespace
{
/// The choices robustness scores at by default, for the flip a reader meets first.
const std::map<std::string, std::string> default_choices = {
    {"rolling_energy", "0.1"}, {"contact_width", "hertz"}, {"load_rule", "dynamic"}, {"end_margin", "0.05"}};

/// The pointer of the comparison `name` at `score` in the robustness output.
std::string comparison_pointer(const CommandOutput& robustness, const Ranking& r)
{
  const nlohmann::json& list = robustness.at("/comparisons");
  for (std::size_t i = 0; i < list.size(); ++i)
    if (list[i].at("name") == r.comparison && list[i].at("score") == r.score)
      return fmt::format("/comparisons/{}", i);
  throw ComputationError(
      fmt::format("`{}` has no comparison '{}' at score '{}'", robustness.command(), r.comparison, r.score));
}

/// "a, b, c" as its items.
std::vector<std::string> split_list(const std::string& list)
{
  std::vector<std::string> items;
  for (std::size_t start = 0, comma; start < list.size(); start = comma + 2)
  {
    comma = std::min(list.find(", ", start), list.size());
    items.push_back(list.substr(start, comma - start));
  }
  return items;
}

/// How many of the other choices of `flip` differ from their defaults.
int distance_from_defaults(const nlohmann::json& flip)
{
  int distance = 0;
  for (const auto& [choice, value] : flip.at("settings").items())
  {
    const auto d = default_choices.find(choice);
    distance += d != default_choices.end() && value != d->second;
  }
  return distance;
}

/// Whether the flip is placed at a value (a rolling energy), not between two named choices.
bool placed(const nlohmann::json& flip) { return flip.contains("value") && flip.at("value").is_number(); }

/// The flip nearest the default choices, one placed at a value first among
/// equals: "rolling_energy 0.361 (contact_width hertz, end_margin 0.05,
/// load_rule dynamic)" or "load_rule static -> dynamic (...)".
std::string nearest_flip(const nlohmann::json& flips)
{
  const nlohmann::json* nearest = nullptr;
  auto rank = [](const nlohmann::json& f) { return 2 * distance_from_defaults(f) + !placed(f); };
  for (const nlohmann::json& flip : flips)
    if (!nearest || rank(flip) < rank(*nearest))
      nearest = &flip;
  if (!nearest)
    return "";
  const nlohmann::json& f = *nearest;
  std::string where = placed(f)
                          ? fmt::format("{} {:.3g}", f.at("choice").get<std::string>(), f.at("value").get<double>())
                          : fmt::format("{} {} -> {}", f.at("choice").get<std::string>(),
                                        f.at("from").get<std::string>(), f.at("to").get<std::string>());
  std::string settings;
  for (const auto& [choice, value] : f.at("settings").items())
    append_listed(settings, fmt::format("{} {}", choice, value.get<std::string>()));
  return fmt::format("{} ({})", where, settings);
}
} // namespace

Rule rankings_over_choices(std::vector<Ranking> rankings)
{
  return [=](const std::vector<CommandOutput*>& out) {
    CommandOutput& robustness = *out[0];
    CellResult cell{"", true};
    bool refuted = false; // one ranking robust against the claim refutes it
    std::vector<std::string> depends; // the choices any ranking flips on, each once
    for (const Ranking& r : rankings)
    {
      const std::string c = comparison_pointer(robustness, r);
      const std::string verdict = robustness.at(c + "/verdict").get<std::string>();
      const double lo = robustness.number(c + "/ratio_min"), hi = robustness.number(c + "/ratio_max");
      const nlohmann::json& bodies = robustness.at(c + "/bodies");
      const std::string first = bodies[0].get<std::string>(), second = bodies[1].get<std::string>();
      std::string text = fmt::format("{} {} / {} {} ... {}", r.score, first, second, sci(lo), sci(hi));
      if (verdict == "robust")
      {
        const bool first_more_even = hi < 1;
        refuted = refuted || first_more_even != r.first_more_even;
        text += fmt::format(", robust: {} the more even under every choice", first_more_even ? first : second);
      }
      else if (verdict.rfind("depends on ", 0) == 0)
      {
        cell.holds = false;
        for (const std::string& choice : split_list(verdict.substr(std::string("depends on ").size())))
          if (std::find(depends.begin(), depends.end(), choice) == depends.end())
            depends.push_back(choice);
        text += fmt::format(", {}, flips at {}", verdict, nearest_flip(robustness.at(c + "/flips")));
      }
      else
        throw ComputationError(fmt::format("`{}`: comparison '{}' at '{}' has verdict '{}'", robustness.command(),
                                           r.comparison, r.score, verdict));
      append_listed(cell.value, text, "; ");
    }
    cell.holds = cell.holds && !refuted;
    if (!refuted && !depends.empty())
      cell.undecided = fmt::format("depends on {}", fmt::join(depends, ", "));
    return cell;
  };
}
} // namespace rollcheck::audit::rules
