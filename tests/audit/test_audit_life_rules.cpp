// The audit's fatigue-life rules on hand-made `rollcheck life` outputs: the
// verdict follows the life ratios' ranges and verdicts at every load, a load
// below the fatigue limit is reported as untestable, and the rim rule
// follows the ends' integral against the interior's.
#include "audit/rules.h"
#include <cmath>
#include <gtest/gtest.h>

using namespace rollcheck::audit;
using json = nlohmann::json;

namespace
{
json comparison(const std::string& name, double load, const std::string& model, const std::string& verdict,
                json min, json max, json untested = nullptr)
{
  return {{"name", name},         {"load_n", load},          {"model", model},
          {"criterion", "orthogonal_shear"}, {"verdict", verdict}, {"life_ratio_min", min},
          {"life_ratio_max", max}, {"untested_because", untested}};
}

/// "oloid vs cylinder" at two loads, Lundberg-Palmgren between lo and hi with `verdict`; Ioannides-Harris
/// untestable at the first load.
CommandOutput life(double lo, double hi, const std::string& verdict = "robust")
{
  json list = json::array();
  for (const double load : {100.0, 5000.0})
  {
    list.push_back(comparison("oloid vs cylinder", load, "lundberg_palmgren", verdict, lo, hi));
    list.push_back(load == 100 ? comparison("oloid vs cylinder", load, "ioannides_harris", "cannot be tested", nullptr,
                                            nullptr, "both lives are infinite")
                               : comparison("oloid vs cylinder", load, "ioannides_harris", "robust", 0, 0));
  }
  return CommandOutput("rollcheck life --json -", json{{"comparisons", list}});
}

CellResult decide(const Rule& rule, CommandOutput& out)
{
  std::vector<CommandOutput*> outputs = {&out};
  return rule(outputs);
}
} // namespace

TEST(AuditLifeRules, LongerLifeHoldsOnlyWhenEveryCellAtEveryLoadSaysSo)
{
  const Rule rule = rules::lives_longer_over_choices("oloid", {"cylinder"});
  CommandOutput shorter = life(4e-6, 0.02), longer = life(1.5, 30), flips = life(0.5, 2, "depends on load_rule");
  const CellResult a = decide(rule, shorter), b = decide(rule, longer), c = decide(rule, flips);
  EXPECT_FALSE(a.holds);
  EXPECT_TRUE(a.undecided.empty());
  EXPECT_NE(a.value.find("4e-06 ... 0.02"), std::string::npos) << a.value;
  EXPECT_NE(a.value.find("cylinder the longer-lived under every choice"), std::string::npos) << a.value;
  EXPECT_NE(a.value.find("100 N both infinite (cannot be tested)"), std::string::npos) << a.value;
  EXPECT_NE(a.value.find("5000 N 0 ... 0"), std::string::npos) << a.value;
  EXPECT_TRUE(b.holds);
  EXPECT_FALSE(c.holds);
  EXPECT_EQ(c.undecided, "depends on load_rule") << c.undecided;
}

TEST(AuditLifeRules, AMissingComparisonIsAnError)
{
  CommandOutput out = life(1, 2);
  EXPECT_THROW(decide(rules::lives_longer_over_choices("oloid", {"u-optimum"}), out), std::exception);
}

TEST(AuditLifeRules, InteriorGovernsWhenTheEndsIntegralIsBelowTheInteriors)
{
  auto rims = [](double end_over_interior) {
    json rows = json::array({{{"edge_radius_over_radius", 0.02}, {"end_over_interior", 10 * end_over_interior},
                              {"life_with_over_without_ends", 0.1}},
                             {{"edge_radius_over_radius", 0.04}, {"end_over_interior", end_over_interior},
                              {"life_with_over_without_ends", std::pow(1 / (1 + end_over_interior), 8.0 / 9)}}});
    json lives = json::array({{{"body", "oloid"}, {"load_n", 100}, {"rows", rows},
                               {"interior_governs_from_edge_radius_over_radius", end_over_interior < 1 ? json(0.03) : json(nullptr)}},
                              {{"body", "cylinder"}, {"load_n", 100}, {"rows", json::array()},
                               {"interior_governs_from_edge_radius_over_radius", nullptr}}});
    return CommandOutput("rollcheck life --json -",
                         json{{"rims", {{"rim_study_edge_radius_over_radius", 0.04}, {"lives", lives}}}});
  };
  CommandOutput governs = rims(0.5), ends = rims(3);
  const CellResult a = decide(rules::interior_governs_life("oloid"), governs);
  const CellResult b = decide(rules::interior_governs_life("oloid"), ends);
  EXPECT_TRUE(a.holds);
  EXPECT_NE(a.value.find("from r_e = 0.03 r1"), std::string::npos) << a.value;
  EXPECT_FALSE(b.holds);
  EXPECT_NE(b.value.find("none up to the largest computed"), std::string::npos) << b.value;
  EXPECT_THROW(decide(rules::interior_governs_life("u-optimum"), governs), std::exception);
}
