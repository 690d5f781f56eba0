#include "audit/table.h"
#include "core/json_number.h"
#include <cmath>
#include <fmt/format.h>

namespace rollcheck::audit
{
std::string verdict_text(Verdict v)
{
  switch (v)
  {
  case Verdict::holds: return "holds";
  case Verdict::holds_only_paper_compatible: return "holds only in paper-compatible mode";
  case Verdict::does_not_hold: return "does not hold";
  case Verdict::cannot_be_tested: return "cannot be tested";
  case Verdict::not_built: return "not built yet";
  }
  return "";
}

Verdict judge(const AuditClaim& claim)
{
  const auto paper = claim.cells.find(paper_compatible_mode);
  const bool has_paper = paper != claim.cells.end() && paper->second.applicable && paper->second.built;
  bool any = has_paper, others_hold = true, untestable = false;
  for (const auto& [mode, cell] : claim.cells)
  {
    untestable = untestable || (cell.applicable && !cell.untestable.empty());
    if (mode != paper_compatible_mode && cell.applicable && cell.built)
    {
      any = true;
      others_hold = others_hold && cell.holds;
    }
  }
  if (!any)
    return untestable ? Verdict::cannot_be_tested : Verdict::not_built;
  if (!has_paper)
    return others_hold ? Verdict::holds : Verdict::does_not_hold;
  if (!paper->second.holds)
    return Verdict::does_not_hold;
  return others_hold ? Verdict::holds : Verdict::holds_only_paper_compatible;
}

namespace
{
std::string cell_text(const AuditCell& cell)
{
  if (!cell.applicable)
    return "n/a";
  if (!cell.untestable.empty())
    return "cannot be tested: " + cell.untestable;
  if (!cell.built)
    return "not built yet";
  std::string refs;
  for (const std::string& id : cell.commands)
    refs += (refs.empty() ? "" : ",") + id;
  return fmt::format("{}{} [{}]", cell.value, cell.holds ? "" : " (✗)", refs);
}
} // namespace

std::string to_markdown(const AuditTable& table)
{
  std::string md = "| claim | paper |";
  std::string rule = "|---|---|";
  for (const auto& [mode, meaning] : table.modes)
  {
    md += fmt::format(" {} |", mode);
    rule += "---|";
  }
  md += " verdict |\n" + rule + "---|\n";
  for (const AuditClaim& c : table.claims)
  {
    md += fmt::format("| {} | {} |", c.claim, c.paper_value);
    for (const auto& [mode, meaning] : table.modes)
    {
      const auto it = c.cells.find(mode);
      md += fmt::format(" {} |", it == c.cells.end() ? std::string("n/a") : cell_text(it->second));
    }
    md += fmt::format(" **{}** |\n", verdict_text(c.verdict));
  }
  md += "\n(✗) marks a recomputation that fails the claim's rule; [cN] are the commands below that print the "
        "numbers used.\n\nModes:\n\n";
  for (const auto& [mode, meaning] : table.modes)
    md += fmt::format("- **{}**: {}\n", mode, meaning);
  md += "\nVerdict rules:\n\n";
  for (const std::string& r : table.verdict_rules)
    md += fmt::format("- {}\n", r);
  md += "\nPer-claim rules and notes:\n\n";
  for (const AuditClaim& c : table.claims)
    md += fmt::format("- *{}*: {}{}\n", c.claim, c.rule, c.note.empty() ? "" : " " + c.note);
  md += "\nCommands (each prints, with `--json -`, the values the audit read from it):\n\n";
  for (const AuditCommand& c : table.commands)
  {
    std::string reads;
    for (const auto& [pointer, value] : c.reads)
      reads += fmt::format("{}{} = {:.6g}", reads.empty() ? "" : ", ", pointer, value);
    md += fmt::format("- {}: `{}` → {}\n", c.id, c.command, reads);
  }
  md += fmt::format("\nAudit wall time: {:.1f} s{}.\n", table.wall_s, table.quick ? " (--quick)" : "");
  return md;
}

void to_json(nlohmann::json& j, const AuditClaim& c)
{
  j = {{"id", c.id},                   {"claim", c.claim},
       {"paper_value", c.paper_value}, {"rule", c.rule},
       {"recomputations", c.cells},    {"verdict", verdict_text(c.verdict)},
       {"note", c.note}};
}

void to_json(nlohmann::json& j, const AuditCommand& c)
{
  nlohmann::json reads = nlohmann::json::object();
  for (const auto& [pointer, value] : c.reads)
    reads[pointer] = json_number(value);
  j = {{"id", c.id}, {"command", c.command}, {"reads", reads}};
}

nlohmann::json to_json(const AuditTable& table)
{
  nlohmann::json modes = nlohmann::json::array();
  for (const auto& [mode, meaning] : table.modes)
    modes.push_back({{"mode", mode}, {"meaning", meaning}});
  return {{"modes", modes},             {"verdict_rules", table.verdict_rules}, {"claims", table.claims},
          {"commands", table.commands}, {"wall_s", table.wall_s},               {"quick", table.quick}};
}
} // namespace rollcheck::audit
