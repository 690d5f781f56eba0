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
  const bool has_paper = paper != claim.cells.end() && paper->second.applicable && paper->second.built &&
                         paper->second.undecided.empty();
  bool any = has_paper, others_hold = true, untestable = false;
  for (const auto& [mode, cell] : claim.cells)
  {
    untestable = untestable || (cell.applicable && (!cell.untestable.empty() || !cell.undecided.empty()));
    if (mode != paper_compatible_mode && cell.applicable && cell.built && cell.undecided.empty())
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
std::string references(const std::vector<std::string>& commands)
{
  std::string refs;
  for (const std::string& id : commands)
    refs += (refs.empty() ? "" : ",") + id;
  return refs;
}

std::string cell_text(const AuditCell& cell)
{
  if (!cell.applicable)
    return "n/a";
  if (!cell.untestable.empty())
    return "cannot be tested: " + cell.untestable;
  if (!cell.built)
    return "not built yet";
  const std::string mark = !cell.undecided.empty() ? " (" + cell.undecided + ")" : cell.holds ? "" : " (✗)";
  return fmt::format("{}{} [{}]", cell.value, mark, references(cell.commands));
}

/// A judgement as a table cell: its verdict, and its reason unless it is the
/// row's cell of its mode.
std::string judgement_text(const Judgement& j)
{
  if (!j.mode.empty())
    return fmt::format("**{}** ({})", j.verdict, j.mode);
  return fmt::format("**{}**: {}{}", j.verdict, j.reason,
                     j.commands.empty() ? "" : fmt::format(" [{}]", references(j.commands)));
}

std::string with_note(std::string reason, const std::string& note)
{
  return note.empty() ? reason : reason + ". " + note;
}
} // namespace

Judgement judge_reproduced(const AuditClaim& claim, const std::string& note)
{
  const auto paper = claim.cells.find(paper_compatible_mode);
  if (paper == claim.cells.end() || !paper->second.applicable)
    return {reproduction::cannot_be_tested, note.empty() ? "the preprint has no computation of it to rerun" : note,
            {}};
  if (!paper->second.built)
    return {reproduction::cannot_be_tested,
            with_note(paper->second.untestable.empty() ? "not built yet" : paper->second.untestable, note), {}};
  const AuditCell& cell = paper->second;
  if (!cell.undecided.empty())
    return {reproduction::cannot_be_tested, with_note(cell.undecided + ": " + cell.value, note), cell.commands,
            paper_compatible_mode};
  return {cell.holds ? reproduction::reproduced : reproduction::not_reproduced, with_note(cell.value, note),
          cell.commands, paper_compatible_mode};
}

Judgement truth_from_cell(const AuditClaim& claim, const std::string& mode, const std::string& note)
{
  const auto it = claim.cells.find(mode);
  if (it == claim.cells.end() || !it->second.applicable)
    return {truth::cannot_be_tested, with_note("no " + mode + " recomputation", note), {}};
  const AuditCell& cell = it->second;
  if (!cell.untestable.empty() || !cell.built)
    return {truth::cannot_be_tested, with_note(cell.untestable.empty() ? "not built yet" : cell.untestable, note),
            {}};
  const std::string verdict = !cell.undecided.empty()
                                  ? (cell.undecided.rfind(truth::depends_prefix, 0) == 0 ? cell.undecided
                                                                                          : truth::cannot_be_tested)
                                  : cell.holds ? truth::holds
                                               : truth::does_not_hold;
  const std::string reason = cell.undecided.empty() || verdict == cell.undecided
                                 ? cell.value
                                 : cell.undecided + ": " + cell.value;
  return {verdict, with_note(reason, note), cell.commands, mode};
}

std::string to_markdown(const AuditTable& table)
{
  std::string md = "| claim | paper |";
  std::string rule = "|---|---|";
  for (const auto& [mode, meaning] : table.modes)
  {
    md += fmt::format(" {} |", mode);
    rule += "---|";
  }
  md += " reproduced | true |\n" + rule + "---|---|\n";
  for (const AuditClaim& c : table.claims)
  {
    md += fmt::format("| {} | {} |", c.claim, c.paper_value);
    for (const auto& [mode, meaning] : table.modes)
    {
      const auto it = c.cells.find(mode);
      md += fmt::format(" {} |", it == c.cells.end() ? std::string("n/a") : cell_text(it->second));
    }
    md += fmt::format(" {} | {} |\n", judgement_text(c.reproduced), judgement_text(c.truth));
  }
  md += "\n(✗) marks a recomputation that fails the claim's rule; [cN] are the commands below that print the "
        "numbers used. *reproduced*: the preprint's method and meshes give its number (the paper-compatible "
        "cell); *true*: the claim under the best physics the table has, over the modelling choices.\n\nModes:\n\n";
  for (const auto& [mode, meaning] : table.modes)
    md += fmt::format("- **{}**: {}\n", mode, meaning);
  md += "\nVerdict rules:\n\n";
  for (const std::string& r : table.verdict_rules)
    md += fmt::format("- {}\n", r);
  md += "\nPer-claim rules and notes:\n\n";
  for (const AuditClaim& c : table.claims)
    md += fmt::format("- *{}*: {}{}\n", c.claim, c.rule, c.note.empty() ? "" : " " + c.note);
  md += "\nWhy each claim is true or not (the reasons of the `true` column that come from a cell):\n\n";
  for (const AuditClaim& c : table.claims)
    if (!c.truth.mode.empty())
      md += fmt::format("- *{}*: {}: {}\n", c.claim, c.truth.verdict, c.truth.reason);
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
       {"note", c.note},               {"reproduced", c.reproduced},
       {"true", c.truth}};
}

void to_json(nlohmann::json& j, const AuditCommand& c)
{
  nlohmann::json reads = nlohmann::json::object();
  for (const auto& [pointer, value] : c.reads)
    reads[pointer] = json_number(value);
  j = {{"id", c.id}, {"command", c.command}, {"reads", reads}, {"wall_s", c.wall_s}, {"cpu_s", c.cpu_s}};
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
