// The audit's verdicts (audit/rules.h, audit/runner.h) on canned
// command outputs whose answers are known by hand: the pointer reading, the
// cell rules (one that holds, one that fails), the claim verdicts, and a
// missing key, which must name the key and the command.
#include "core/error.h"
#include "audit/claims.h"
#include "audit/runner.h"
#include <array>
#include <cmath>
#include <algorithm>
#include <gtest/gtest.h>
#include <set>

using namespace rollcheck;
using namespace rollcheck::audit;
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
  c.cells["real rolling"] = {true, false, "", {}, false, "no command prints it"};
  EXPECT_EQ(judge(c), Verdict::cannot_be_tested); // only untestable and unbuilt cells
  c.cells["corrected physics"].built = true;
  EXPECT_EQ(judge(c), Verdict::holds); // an untestable cell does not decide a testable claim
}

namespace
{
/// A quick-grid search output: genome (theta, d, rho, approximate CDS, rigid
/// CDS or 0 when not revalidated); the first is the grid's oloid.
CommandOutput search(const std::vector<std::array<double, 5>>& genomes)
{
  json list = json::array();
  for (std::size_t i = 0; i < genomes.size(); ++i)
  {
    const auto& [theta, d, rho, approximate, rigid] = genomes[i];
    json g = {{"theta_deg", theta}, {"offset", d},           {"ratio", rho}, {"approximate", {{"cds", approximate}}},
              {"validated", rigid > 0}, {"is_anchor_genome", i == 0}};
    if (rigid > 0)
      g["rigid"] = {{"cds", rigid}};
    list.push_back(g);
  }
  return CommandOutput(command_line({"search", "--grid", "quick"}), json{{"genomes", list}});
}
} // namespace

TEST(Audit, SearchRulesReadTheGrid)
{
  // Oloid genome 2e-6; two genomes below it, the best (120, 0.70, 0.80) 1.24e-6 (38 % better).
  CommandOutput grid = search({{90, 1.0, 1.0, 2e-6, 0},
                               {120, 0.7, 0.8, 1.24e-6, 1.9e-6},
                               {120, 1.3, 0.8, 1.5e-6, 8.7e-7},
                               {90, 0.7, 0.8, 1.6e-6, 1.1e-6},
                               {105, 1.0, 1.0, 2.3e-6, 0}});
  const CellResult screen = rules::approximate_screen(3, 2e-6, {120, 0.7, 0.8}, 1.24e-6, 0.2)({&grid});
  EXPECT_EQ(screen.value, "3 of 5 below the oloid genome's 2e-06; top (120, 0.70, 0.80) 1.24e-06, 38 % better");
  EXPECT_TRUE(screen.holds);
  EXPECT_FALSE(rules::approximate_screen(22, 2e-6, {120, 0.7, 0.8}, 1.24e-6, 0.2)({&grid}).holds); // 3, not 22
  EXPECT_FALSE(rules::approximate_screen(3, 2e-6, {90, 0.7, 0.8}, 1.24e-6, 0.2)({&grid}).holds);  // other top

  // Rigid best three: (120, 1.30, 0.80), (90, 0.70, 0.80), (120, 0.70, 0.80): rho < 1 in all, d < 1 in two.
  const CellResult direction = rules::improvement_direction()({&grid});
  EXPECT_EQ(direction.value, "rigid-body best 3: (120, 1.30, 0.80), (90, 0.70, 0.80), (120, 0.70, 0.80); ρ < 1 in "
                             "3, d < 1 in 2");
  EXPECT_FALSE(direction.holds);

  CommandOutput oloid = oracle("oloid", 8.2e-7);
  const Rule table = rules::revalidated({{{120, 1.3, 0.8}, {8.7e-7, 1.06}}, {{90, 0.7, 0.8}, {1.09e-6, 1.33}}}, 0.2);
  const CellResult revalidated = table({&grid, &oloid});
  EXPECT_TRUE(revalidated.holds);
  EXPECT_EQ(revalidated.value, "(120, 1.30, 0.80) 8.7e-07 (1.06x), (90, 0.70, 0.80) 1.1e-06 (1.34x); also "
                               "revalidated, not in the table: (120, 0.70, 0.80) 1.9e-06 (2.32x)");
  // A genome listed but not revalidated fails the rule, and one not on the grid names itself.
  EXPECT_FALSE(rules::revalidated({{{105, 1.0, 1.0}, {2e-6, 2.4}}}, 0.2)({&grid, &oloid}).holds);
  const std::string missing =
      message_of([&] { rules::revalidated({{{115, 1.2, 0.65}, {9e-7, 1.1}}}, 0.2)({&grid, &oloid}); });
  EXPECT_NE(missing.find("(115, 1.20, 0.65)"), std::string::npos) << missing;

  // 1.6e-6 is 1.60e-6 to three digits; 2.3e-6 within 20 % of 2.42e-6 but not to its digits.
  const CellResult scores =
      rules::approximate_scores({{{90, 0.7, 0.8}, 1.6e-6}, {{105, 1.0, 1.0}, 2.42e-6}}, 0.2)({&grid});
  EXPECT_EQ(scores.value, "(90, 0.70, 0.80) 1.6e-06, (105, 1.00, 1.00) 2.3e-06 (1 of 2 to the printed digits)");
  EXPECT_TRUE(scores.holds);
  EXPECT_FALSE(rules::approximate_scores({{{105, 1.0, 1.0}, 3e-6}}, 0.2)({&grid}).holds); // -23 %
}

TEST(Audit, ValueListRulesCountPrintedDigits)
{
  // 68.37 MPa is the preprint's 68.3 truncated, 0.0845 its 0.085 rounded; 52 MPa is 5 % off 49.7.
  CommandOutput oloid("o", json{{"mean_peak_pressure_pa", 68.37e6}, {"stress_cv", 0.0845}, {"sds", 8.0e-7}});
  CommandOutput other("y", json{{"mean_peak_pressure_pa", 52e6}, {"stress_cv", 0.06}, {"sds", 8.9e-7}});
  const Rule values = rules::each_within({{0, "/mean_peak_pressure_pa", 68.3, 3, "oloid MPa", 1e-6},
                                          {0, "/stress_cv", 0.085, 2, "CV"},
                                          {1, "/mean_peak_pressure_pa", 49.7, 3, "cylinder MPa", 1e-6}},
                                         0.2);
  const CellResult cell = values({&oloid, &other});
  EXPECT_EQ(cell.value, "oloid MPa 68.37, CV 0.0845, cylinder MPa 52 (2 of 3 to the printed digits)");
  EXPECT_TRUE(cell.holds);
  EXPECT_FALSE(rules::each_within({{1, "/stress_cv", 0.045, 2, "CV"}}, 0.2)({&oloid, &other}).holds); // +33 %
  // SDS 8.9e-7 over 8.0e-7 is 11 % apart: not within 10 %.
  const CellResult gap = rules::ratio_within("SDS ratio", {1, "/sds"}, {0, "/sds"}, 1, 0.10)({&oloid, &other});
  EXPECT_EQ(gap.value, "SDS ratio 1.11x");
  EXPECT_FALSE(gap.holds);
  const CellResult both = rules::all_of({values, rules::below("CV", 0, "/stress_cv", 0.1)})({&oloid, &other});
  EXPECT_TRUE(both.holds);
  EXPECT_EQ(both.value.substr(both.value.rfind("; ")), "; CV 0.0845");
  EXPECT_FALSE(rules::all_of({values, rules::below("CV", 0, "/stress_cv", 0.05)})({&oloid, &other}).holds);
}

TEST(Audit, VectorCoverageAndFemRules)
{
  CommandOutput lowest("o", json{{"cds", 8.2e-7}, {"sds", 8.1e-7}, {"tds", 7.7e-7}, {"wds_vol", 7.7e-7},
                                 {"wds_depth", 1.2e-6}, {"fds", 2.4e-6}});
  const CellResult tds = rules::tds_lowest()({&lowest});
  EXPECT_EQ(tds.value, "TDS 7.7e-07, CDS 8.2e-07; below TDS: none"); // a tie with WDS_vol is not below
  EXPECT_TRUE(tds.holds);
  CommandOutput not_lowest("c", json{{"cds", 1.1e-6}, {"sds", 1.5e-6}, {"tds", 1.6e-6}, {"wds_vol", 1.2e-6},
                                     {"wds_depth", 1.6e-6}, {"fds", "inf"}});
  EXPECT_EQ(rules::tds_lowest()({&not_lowest}).value, "TDS 1.6e-06, CDS 1.1e-06; below TDS: cds, sds, wds_vol");
  EXPECT_FALSE(rules::tds_lowest()({&not_lowest}).holds);

  CommandOutput touched("o", json{{"n_faces", 1198}, {"contact", {{"faces_without_contact", 0}}}});
  CommandOutput gaps("o", json{{"n_faces", 1198}, {"contact", {{"faces_without_contact", 257}}}});
  EXPECT_TRUE(rules::every_face_touched()({&touched}).holds);
  EXPECT_EQ(rules::every_face_touched()({&gaps}).value, "257 of 1198 faces untouched");
  EXPECT_FALSE(rules::every_face_touched()({&gaps}).holds);
  // With the per-face arrays the untouched area is summed: faces 1 and 3 (0.5 + 2 m²).
  CommandOutput per_face("o", json{{"n_faces", 4},
                                   {"contact", {{"faces_without_contact", 2}}},
                                   {"per_face", {{"contact_counts", {3, 0, 7, 0}}, {"face_areas_m2", {1, 0.5, 1, 2}}}}});
  EXPECT_EQ(rules::every_face_touched()({&per_face}).value, "2 of 4 faces untouched (area 2.500 m²)");
  CommandOutput full("r", json{{"coverage", 1.0}}), partial("r", json{{"coverage", 0.948}, {"face_subdivisions", 8}});
  EXPECT_TRUE(rules::coverage_at_least(0.999)({&full}).holds);
  EXPECT_FALSE(rules::coverage_at_least(0.999)({&partial}).holds);
  const CellResult with_hertz = rules::coverage_at_least(0.999)({&full, &partial});
  EXPECT_TRUE(with_hertz.holds); // the first decides, the others explain
  EXPECT_EQ(with_hertz.value, "coverage 1.0000; Hertz width, by face subdivisions: 0.948 (8²)");

  // Point Hertz 114 MPa against FEM 2.2 MPa (52x) and 5.6 MPa (20x); the unsolved orientation is skipped.
  auto orientation = [](bool solved, double point, double fem) {
    return json{{"fem_solved", solved}, {"point_hertz_peak_pa", point}, {"fem_peak_pa", fem}};
  };
  CommandOutput fem("fem-sds", json{{"per_orientation", {orientation(true, 114.4e6, 2.2e6),
                                                          orientation(false, 1e6, 1e6),
                                                          orientation(true, 112e6, 5.6e6)}},
                                    {"fem_vs_line_hertz_worst", 0.0028}});
  const CellResult pressures = rules::point_hertz_is_contact_pressure(0.2)({&fem});
  EXPECT_EQ(pressures.value, "point Hertz / FEM peak 20.0x ... 52.0x; FEM vs line Hertz worst 0.28 %");
  EXPECT_FALSE(pressures.holds);
  CommandOutput agrees("fem-sds", json{{"per_orientation", {orientation(true, 2.3e6, 2.2e6)}},
                                       {"fem_vs_line_hertz_worst", 0.0028}});
  EXPECT_TRUE(rules::point_hertz_is_contact_pressure(0.2)({&agrees}).holds);

  // The title claim: beaten beyond the noise, or a start that is not a local minimum, fails it.
  auto search = [](bool beaten, const char* verdict) {
    return json{{"start_value", 2e-6},
                {"optimum", {{"value", 1.5e-6}, {"significance_threshold", 2e-7}, {"beats_start", beaten},
                             {"x", {72.6, 1.107, 0.942}}}},
                {"verdict_at_start", verdict}};
  };
  CommandOutput beaten("optimize", search(true, "local minimum")), flat("optimize", search(false, "local minimum")),
      sloped("optimize", search(false, "not stationary"));
  const CellResult lost = rules::start_is_local_optimum(true)({&beaten});
  EXPECT_FALSE(lost.holds);
  EXPECT_TRUE(lost.undecided.empty()); // a resolution-free score decides
  EXPECT_EQ(lost.value, "beaten; best (72.6, 1.107, 0.942) 1.5e-06 against 2e-06 at the start (-25.0 %, noise "
                        "threshold 2e-07); at the start: local minimum");
  EXPECT_TRUE(rules::start_is_local_optimum(true)({&flat}).holds);
  EXPECT_FALSE(rules::start_is_local_optimum(true)({&sloped}).holds);
  EXPECT_TRUE(rules::start_is_local_optimum(true)({&sloped}).undecided.empty());
  // A per-face score's gains and gradients are inside its mesh noise: every
  // outcome, a win as well as a loss, is undecided.
  for (CommandOutput* o : {&beaten, &sloped, &flat})
  {
    const CellResult per_face = rules::start_is_local_optimum(false)({o});
    EXPECT_FALSE(per_face.holds);
    EXPECT_EQ(per_face.undecided.rfind("cannot be decided at this resolution", 0), 0u) << per_face.undecided;
  }
}

TEST(Audit, RimRuleFailsOnASingularEndOrAConcentration)
{
  auto rims = [](int loaded, int singular, json end_to_interior) {
    return json{{"loop_scores", {{"loaded_ends", loaded}, {"loaded_end_samples", 10}, {"end_aware", {{{"singular_ends", singular}}}}}},
                {"loop_end_to_interior", end_to_interior}};
  };
  CommandOutput cylinder("rim", rims(20, 0, 0.51));
  CommandOutput sharp("rim", rims(14, 10, nullptr)), square("rim", rims(14, 0, 0.6)), peaked("rim", rims(14, 0, 1.7));
  const CellResult singular = rules::rims_free_of_concentration()({&sharp, &cylinder});
  EXPECT_FALSE(singular.holds);
  EXPECT_EQ(singular.value, "sharp edges on the rigid plane: oloid 10 of 14 loaded rim ends singular (10 samples load "
                            "a rim); cylinder 0 of 20 loaded rim ends singular (10 samples load a rim), largest end "
                            "pressure 0.51x the interior's");
  EXPECT_TRUE(rules::rims_free_of_concentration()({&square, &cylinder}).holds);
  EXPECT_FALSE(rules::rims_free_of_concentration()({&peaked, &cylinder}).holds);
  // No loaded end: nothing at the rims (no end_aware scores are written).
  CommandOutput unloaded("rim", json{{"loop_scores", {{"loaded_ends", 0}, {"loaded_end_samples", 0}}},
                                     {"loop_end_to_interior", nullptr}});
  EXPECT_TRUE(rules::rims_free_of_concentration()({&unloaded, &cylinder}).holds);
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
  EXPECT_EQ(claims.size(), 30u);
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
    // Every claim says where its `true` verdict comes from: one of its cells, a rule on commands, or why not.
    const TruthSource& t = c.truth;
    EXPECT_EQ(!t.mode.empty() + static_cast<bool>(t.rule) + !t.untestable.empty(), 1) << c.id;
    if (!t.mode.empty())
      EXPECT_TRUE(std::ranges::any_of(c.cells, [&](const ClaimCell& cell) { return cell.mode == t.mode; }))
          << c.id << ": no cell of " << t.mode;
    EXPECT_EQ(t.commands.empty(), !t.rule) << c.id;
  }
  // The quick table's oracle commands scan 3 mesh sizes, 2 extra thresholds.
  const auto scaling_row = std::ranges::find(claims, std::string("face_scaling"), &Claim::id);
  ASSERT_NE(scaling_row, claims.end());
  const Claim& scaling = *scaling_row;
  EXPECT_EQ(scaling.cells[0].commands.size(), 3u);
}

TEST(Audit, ACandidateBelowTheAnchorBeatsItAndTheMeshShiftIsStated)
{
  // Anchor 7.44e-7 at its own mesh; the best candidate 7.40e-7 is 0.5 % below it.
  auto grid = [](double anchor) {
    json g = {{"theta_deg", 120}, {"offset", 1.0}, {"ratio", 0.8}, {"approximate", {{"cds", 1e-6}}},
              {"validated", true}, {"is_anchor_genome", false}, {"rigid", {{"cds", 7.40e-7}}}};
    return CommandOutput(command_line({"search", std::to_string(anchor)}),
                         json{{"anchor", {{"rigid", {{"cds", anchor}}}}}, {"genomes", {g}}});
  };
  CommandOutput own = grid(7.44e-7), on_candidates_mesh = grid(1.74e-6), lower_anchor = grid(7.30e-7);
  const CellResult alone = rules::no_candidate_beats_anchor()({&own});
  EXPECT_FALSE(alone.holds);
  EXPECT_EQ(alone.value, "anchor 7.44e-07; 1 of 1 better, best (120, 1.00, 0.80) 0.995x");
  // The anchor's CDS on the candidates' mesh is 134 % higher: a shift of the
  // score, not a noise band that could hide the candidate; it is stated.
  const CellResult shifted = rules::no_candidate_beats_anchor()({&own, &on_candidates_mesh});
  EXPECT_FALSE(shifted.holds);
  EXPECT_EQ(shifted.value, "anchor 7.44e-07; 1 of 1 better, best (120, 1.00, 0.80) 0.995x (the anchor's own CDS is "
                           "+134 % on the candidates' mesh: the meshes, not the shapes, decide a difference this "
                           "small)");
  // A candidate above the anchor does not beat it.
  EXPECT_TRUE(rules::no_candidate_beats_anchor()({&lower_anchor}).holds);
}

namespace
{
/// A `rollcheck robustness` output with one comparison of bodies a, b at score s.
json comparison(const std::string& name, const std::string& score, const std::string& verdict, json lo, json hi,
                json flips = json::array())
{
  return {{"name", name}, {"score", score}, {"bodies", {"a", "b"}}, {"verdict", verdict},
          {"ratio_min", lo},  {"ratio_max", hi},  {"flips", flips}};
}

json flip(const std::string& load_rule, double energy)
{
  return {{"choice", "rolling_energy"}, {"from", "0.1"}, {"to", "0.36"}, {"value", energy},
          {"settings", {{"contact_width", "hertz"}, {"end_margin", "0.05"}, {"load_rule", load_rule}}}};
}
} // namespace

TEST(Audit, RankingsOverTheChoicesHoldFailOrDepend)
{
  CommandOutput robustness(
      command_line({"robustness"}),
      json{{"comparisons",
            {comparison("a vs b", "u", "robust", 0.2, 0.9), comparison("a vs b", "p", "robust", 1.2, "inf"),
             comparison("a vs b", "d", "depends on rolling_energy", 0.5, 2.0,
                        {flip("uniform", 0.0328), flip("dynamic", 0.361)})}}});
  const CellResult as_claimed = rules::rankings_over_choices({{"a vs b", "u", true}})({&robustness});
  EXPECT_TRUE(as_claimed.holds);
  EXPECT_EQ(as_claimed.value, "u a / b 0.2 ... 0.9, robust: a the more even under every choice");
  const CellResult against = rules::rankings_over_choices({{"a vs b", "p", true}})({&robustness});
  EXPECT_FALSE(against.holds);
  EXPECT_TRUE(against.undecided.empty());
  EXPECT_EQ(against.value, "p a / b 1.2 ... ∞, robust: b the more even under every choice");
  // A dependent ranking names the flip nearest the default choices (load rule dynamic).
  const CellResult depends = rules::rankings_over_choices({{"a vs b", "u", true}, {"a vs b", "d", true}})({&robustness});
  EXPECT_FALSE(depends.holds);
  EXPECT_EQ(depends.undecided, "depends on rolling_energy");
  EXPECT_NE(depends.value.find("flips at rolling_energy 0.361 (contact_width hertz, end_margin 0.05, load_rule "
                               "dynamic)"),
            std::string::npos)
      << depends.value;
  // Two dependent rankings name each choice once; a flip placed at an energy comes before one between load rules.
  CommandOutput two(command_line({"robustness", "2"}),
                    json{{"comparisons",
                          {comparison("a vs b", "x", "depends on rolling_energy, load_rule", 0.5, 2.0,
                                      {{{"choice", "load_rule"}, {"from", "dynamic"}, {"to", "uniform"},
                                        {"settings", {{"contact_width", "hertz"}, {"end_margin", "0.05"},
                                                      {"rolling_energy", "0.1"}}}},
                                       flip("dynamic", 0.361)}),
                           comparison("a vs b", "y", "depends on load_rule, end_margin", 0.5, 2.0,
                                      {flip("static", 1)})}}});
  const CellResult both = rules::rankings_over_choices({{"a vs b", "x", true}, {"a vs b", "y", true}})({&two});
  EXPECT_EQ(both.undecided, "depends on rolling_energy, load_rule, end_margin");
  EXPECT_NE(both.value.find("x a / b 0.5 ... 2, depends on rolling_energy, load_rule, flips at rolling_energy 0.361"),
            std::string::npos)
      << both.value;
  // One ranking robust against the claim refutes it, whatever the others.
  const CellResult refuted = rules::rankings_over_choices({{"a vs b", "d", true}, {"a vs b", "p", true}})({&robustness});
  EXPECT_FALSE(refuted.holds);
  EXPECT_TRUE(refuted.undecided.empty());
  // A comparison robustness does not print is an error naming it.
  const std::string missing =
      message_of([&] { rules::rankings_over_choices({{"a vs c", "u", true}})({&robustness}); });
  EXPECT_NE(missing.find("'a vs c'"), std::string::npos) << missing;
}

TEST(Audit, EveryClaimAnswersReproducedAndTrueCitingListedCommands)
{
  const Rule ratio = rules::ratios_within({{"/cds", 58}}, 0.2);
  const Rule ranking = rules::rankings_over_choices({{"a vs b", "u", false}});
  const CommandArgs robustness_args = {"robustness"};
  Claim ranked{"ranked", "CDS cylinder / oloid", "58.0x", "within 20 % of 58", "",
               {{paper_compatible_mode, {{"oracle", "o1"}, {"oracle", "y1"}}, ratio},
                {"corrected physics", {{"oracle", "o1"}, {"oracle", "y2"}}, ratio}},
               {{}, {robustness_args}, ranking, {}, "a note"}};
  Claim from_cell{"celled", "CDS cylinder / oloid", "58.0x", "within 20 % of 58", "",
                  {{paper_compatible_mode, {{"oracle", "o1"}, {"oracle", "y2"}}, ratio},
                   {"corrected physics", {{"oracle", "o1"}, {"oracle", "y1"}}, ratio}},
                  {"corrected physics"}};
  Claim unrunnable{"unrunnable", "a statement", "-", "-", "", {{"corrected physics", {{"oracle", "o1"}, {"oracle", "y1"}}, ratio}},
                   {{}, {}, {}, "no score has it"}, "the preprint computes nothing"};
  std::vector<CommandOutput> outputs = {
      oracle("o1", 1e-6), oracle("y1", 6e-5), oracle("y2", 2e-5),
      CommandOutput(command_line(robustness_args),
                    json{{"comparisons", {comparison("a vs b", "u", "depends on load_rule", 0.5, 2, {flip("static", 1)})}}})};
  const AuditTable table = decide_claims({ranked, from_cell, unrunnable}, outputs);
  ASSERT_EQ(table.claims.size(), 3u);
  const AuditClaim& r = table.claims[0];
  EXPECT_EQ(r.reproduced.verdict, reproduction::reproduced); // 60x within 20 % of 58x
  EXPECT_EQ(r.reproduced.mode, paper_compatible_mode);
  EXPECT_EQ(r.truth.verdict, "depends on load_rule");
  EXPECT_EQ(r.truth.commands, (std::vector<std::string>{"c4"}));
  EXPECT_NE(r.truth.reason.find(". a note"), std::string::npos) << r.truth.reason;
  const AuditClaim& c = table.claims[1];
  EXPECT_EQ(c.reproduced.verdict, reproduction::not_reproduced); // 20x
  EXPECT_EQ(c.reproduced.reason, "20.0x");
  EXPECT_EQ(c.truth.verdict, truth::holds); // its corrected cell: 60x
  EXPECT_EQ(c.truth.mode, "corrected physics");
  const AuditClaim& u = table.claims[2];
  EXPECT_EQ(u.reproduced.verdict, reproduction::cannot_be_tested);
  EXPECT_EQ(u.reproduced.reason, "the preprint computes nothing");
  EXPECT_EQ(u.truth.verdict, truth::cannot_be_tested);
  EXPECT_EQ(u.truth.reason, "no score has it");

  // Every command a cell or a judgement cites is in the table's command list, and the JSON has both answers.
  std::set<std::string> listed;
  for (const AuditCommand& command : table.commands)
    listed.insert(command.id);
  for (const AuditClaim& claim : table.claims)
  {
    for (const auto& [mode, cell] : claim.cells)
      for (const std::string& id : cell.commands)
        EXPECT_TRUE(listed.count(id)) << claim.id << " " << mode << " cites " << id;
    for (const Judgement* j : {&claim.reproduced, &claim.truth})
      for (const std::string& id : j->commands)
        EXPECT_TRUE(listed.count(id)) << claim.id << " cites " << id;
  }
  const json j = to_json(table);
  EXPECT_EQ(j["claims"][0]["true"]["verdict"], "depends on load_rule");
  EXPECT_EQ(j["claims"][1]["reproduced"]["verdict"], "not reproduced");
}

TEST(Audit, UndecidedCellsAreLeftOutOfTheVerdict)
{
  AuditClaim c;
  c.cells[paper_compatible_mode] = {true, true, "-12 %", {"c1"}, false, "", "cannot be decided at this resolution"};
  c.cells["real rolling"] = {true, true, "-36 %", {"c2"}, false};
  EXPECT_EQ(judge(c), Verdict::does_not_hold); // the paper cell undecided: the others decide
  const Judgement reproduced = judge_reproduced(c, "");
  EXPECT_EQ(reproduced.verdict, reproduction::cannot_be_tested);
  EXPECT_EQ(reproduced.reason, "cannot be decided at this resolution: -12 %");
  EXPECT_EQ(truth_from_cell(c, paper_compatible_mode, "").verdict, truth::cannot_be_tested);
  EXPECT_EQ(truth_from_cell(c, "real rolling", "why").reason, "-36 %. why");
  EXPECT_EQ(truth_from_cell(c, "contact mechanics", "").verdict, truth::cannot_be_tested);
}
