// The audit's verdicts (study/audit_claims.h, audit_runner.h) on canned
// command outputs whose answers are known by hand: the pointer reading, the
// cell rules (one that holds, one that fails), the claim verdicts, and a
// missing key, which must name the key and the command.
#include "core/error.h"
#include "study/audit_claims.h"
#include "study/audit_runner.h"
#include <cmath>
#include <gtest/gtest.h>
#include <set>

using namespace rollcheck;
using namespace rollcheck::study;
using nlohmann::json;

namespace
{
/// An oracle output with the given CDS and FDS.
CommandOutput oracle(const std::string& name, double cds, json fds = 1e-6)
{
  return CommandOutput(command_line({"oracle", name}), json{{"cds", cds}, {"fds", fds}, {"n_faces", 100}});
}

std::string message_of(const std::function<void()>& f)
{
  try
  {
    f();
  }
  catch (const ComputationError& e)
  {
    return e.what();
  }
  return "no error";
}
} // namespace

TEST(Audit, ReadsNumbersByPointerAndRecordsThem)
{
  CommandOutput out("rollcheck oracle --body oloid --json -",
                    json{{"cds", 2.5e-6}, {"fds", "inf"}, {"convergence", {{"cds", {{50, 3e-5}, {600, 2.5e-6}}}}}});
  EXPECT_EQ(out.number("/cds"), 2.5e-6);
  EXPECT_TRUE(std::isinf(out.number("/fds")));
  EXPECT_EQ(out.number("/convergence/cds/1/0"), 600);
  EXPECT_EQ(out.at("/convergence/cds").size(), 2u);
  const std::map<std::string, double> reads = out.reads();
  EXPECT_EQ(reads.size(), 3u); // at() is not a read of a number
  EXPECT_EQ(reads.at("/cds"), 2.5e-6);
  EXPECT_EQ(reads.at("/convergence/cds/1/0"), 600);
}

TEST(Audit, AMissingKeyNamesTheKeyAndTheCommand)
{
  CommandOutput out("rollcheck oracle --body oloid --json -", json{{"cds", 2.5e-6}, {"label", "x"}});
  const std::string missing = message_of([&] { out.number("/sds"); });
  EXPECT_NE(missing.find("'/sds'"), std::string::npos) << missing;
  EXPECT_NE(missing.find("rollcheck oracle --body oloid --json -"), std::string::npos) << missing;
  const std::string not_number = message_of([&] { out.number("/label"); });
  EXPECT_NE(not_number.find("not a number"), std::string::npos) << not_number;
  EXPECT_NE(message_of([&] { out.at("/genomes"); }).find("'/genomes'"), std::string::npos);
}

TEST(Audit, RatioRuleHoldsWithinItsToleranceOnly)
{
  const Rule rule = rules::ratios_within({{"/cds", 58}}, 0.2);
  CommandOutput oloid = oracle("oloid", 1e-6), near = oracle("near", 6.5e-5), far = oracle("far", 7.5e-5);
  const CellResult holds = rule({&oloid, &near}); // 65 / 58 - 1 = 12 %
  EXPECT_TRUE(holds.holds);
  EXPECT_EQ(holds.value, "65.0x");
  const CellResult fails = rule({&oloid, &far}); // 75 / 58 - 1 = 29 %
  EXPECT_FALSE(fails.holds);
  EXPECT_EQ(fails.value, "75.0x");
}

TEST(Audit, ValueAndFatigueRules)
{
  CommandOutput close = oracle("a", 9e-7), off = oracle("b", 1.2e-6);
  EXPECT_TRUE(rules::value_within("/cds", 8.2e-7, 0.2)({&close}).holds);   // +9.8 %
  EXPECT_FALSE(rules::value_within("/cds", 8.2e-7, 0.2)({&off}).holds);    // +46 %
  EXPECT_EQ(rules::value_within("/cds", 8.2e-7, 0.2)({&close}).value, "9e-07");
  CommandOutput finite = oracle("oloid", 1e-6, 2.42e-6), infinite = oracle("cylinder", 1e-6, "inf");
  const CellResult fds = rules::cylinder_fds_infinite()({&finite, &infinite});
  EXPECT_TRUE(fds.holds);
  EXPECT_EQ(fds.value, "oloid 2.42e-06, cylinder ∞");
  EXPECT_FALSE(rules::cylinder_fds_infinite()({&infinite, &finite}).holds);
  // With a second pair (the right E* alone) both pairs must satisfy it.
  EXPECT_FALSE(rules::cylinder_fds_infinite()({&finite, &infinite, &finite, &finite}).holds);
}

TEST(Audit, FaceCountExponentIsTheLeastSquaresSlope)
{
  // CDS = 3 N^-2 exactly: slope -2, R^2 1; -2 is within 20 % of -2.03.
  std::vector<CommandOutput> runs;
  for (double n : {400.0, 800.0, 1600.0})
    runs.emplace_back(command_line({"oracle", std::to_string(n)}), json{{"n_faces", n}, {"cds", 3 / (n * n)}});
  std::vector<CommandOutput*> outputs;
  for (CommandOutput& r : runs)
    outputs.push_back(&r);
  const CellResult fit = rules::face_count_exponent(-2.03, 0.2)(outputs);
  EXPECT_EQ(fit.value, "-2.00 (R² 1.000)");
  EXPECT_TRUE(fit.holds);
  EXPECT_FALSE(rules::face_count_exponent(-3, 0.2)(outputs).holds);
}

TEST(Audit, ThresholdSpreadAndConvergence)
{
  // Ratios 58 at the default threshold, then 50 and 70: spread 70/58 - 1 = 21 %.
  CommandOutput o = oracle("o", 1e-6), y58 = oracle("y58", 5.8e-5), y50 = oracle("y50", 5e-5),
                y70 = oracle("y70", 7e-5);
  const CellResult spread = rules::threshold_spread(0.2)({&o, &y58, &o, &y50, &o, &y70});
  EXPECT_EQ(spread.value, "50.0x ... 70.0x (21 %)");
  EXPECT_FALSE(spread.holds);
  EXPECT_TRUE(rules::threshold_spread(0.2)({&o, &y58, &o, &y50}).holds); // 14 %

  CommandOutput run("c", json{{"convergence", {{"cds", {{50, 1.2e-5}, {100, 6e-6}, {600, 1e-6}}}}}});
  const CellResult rate = rules::convergence_ratio(12, 0.2)({&run});
  EXPECT_EQ(rate.value, "12.0x (50 → 600 samples)");
  EXPECT_TRUE(rate.holds);
}

TEST(Audit, ClaimVerdictsFromTheirCells)
{
  const Rule ratio = rules::ratios_within({{"/cds", 58}}, 0.2);
  const Claim claim{"demo", "CDS cylinder / oloid", "58.0x", "within 20 % of 58", "",
                    {{paper_compatible_mode, {{"oracle", "o1"}, {"oracle", "y1"}}, ratio},
                     {"corrected physics", {{"oracle", "o1"}, {"oracle", "y2"}}, ratio},
                     {"real rolling", {}, {}}}};
  ASSERT_EQ(distinct_commands({claim}).size(), 3u); // o1 is shared
  std::vector<CommandOutput> outputs = {oracle("o1", 1e-6), oracle("y1", 6e-5), oracle("y2", 2e-5)};
  const AuditTable table = decide_claims({claim}, outputs);
  ASSERT_EQ(table.claims.size(), 1u);
  const AuditClaim& decided = table.claims[0];
  EXPECT_EQ(decided.verdict, Verdict::holds_only_paper_compatible); // 60x holds, 20x does not
  EXPECT_EQ(decided.cells.at("corrected physics").commands, (std::vector<std::string>{"c1", "c3"}));
  EXPECT_FALSE(decided.cells.at("real rolling").built);
  ASSERT_EQ(table.commands.size(), 3u);
  EXPECT_EQ(table.commands[2].command, "rollcheck oracle y2 --json -");
  EXPECT_EQ(table.commands[2].reads.at("/cds"), 2e-5);

  AuditClaim c;
  c.cells[paper_compatible_mode] = {true, true, "", {}, false};
  c.cells["corrected physics"] = {true, true, "", {}, true};
  EXPECT_EQ(judge(c), Verdict::does_not_hold);
  c.cells.erase(paper_compatible_mode);
  EXPECT_EQ(judge(c), Verdict::holds); // no paper-compatible code: the others decide
  c.cells["corrected physics"].built = false;
  EXPECT_EQ(judge(c), Verdict::not_built);
}

TEST(Audit, AMissingKeyInAClaimNamesTheClaimKeyAndCommand)
{
  const Claim claim{"sds_ratio", "SDS", "58.0x", "", "",
                    {{paper_compatible_mode,
                      {{"oracle", "o"}, {"oracle", "y"}},
                      rules::ratios_within({{"/sds", 58}}, 0.2)}}};
  std::vector<CommandOutput> outputs = {oracle("o", 1e-6), oracle("y", 6e-5)};
  const std::string message = message_of([&] { decide_claims({claim}, outputs); });
  EXPECT_NE(message.find("sds_ratio"), std::string::npos) << message;
  EXPECT_NE(message.find("'/sds'"), std::string::npos) << message;
  EXPECT_NE(message.find("rollcheck oracle "), std::string::npos) << message;
}

TEST(Audit, TheClaimTableIsWellFormed)
{
  const std::vector<Claim> claims = audit_claims(ROLLCHECK_REFERENCE_MESH_DIR, true);
  EXPECT_EQ(claims.size(), 11u);
  std::set<std::string> modes, ids;
  for (const auto& [mode, meaning] : audit_modes())
    modes.insert(mode);
  for (const Claim& c : claims)
  {
    EXPECT_TRUE(ids.insert(c.id).second) << c.id;
    EXPECT_FALSE(c.rule.empty()) << c.id;
    for (const ClaimCell& cell : c.cells)
    {
      EXPECT_TRUE(modes.count(cell.mode)) << c.id << ": " << cell.mode;
      EXPECT_EQ(cell.commands.empty(), !cell.rule) << c.id << ": " << cell.mode; // built cells have commands
    }
  }
  // The quick table's oracle commands scan 3 mesh sizes, 2 extra thresholds.
  const Claim& scaling = claims[4];
  ASSERT_EQ(scaling.id, "face_scaling");
  EXPECT_EQ(scaling.cells[0].commands.size(), 3u);
}
