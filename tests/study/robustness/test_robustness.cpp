// Resolution-free loop scores against closed forms and an independent
// computation, the verdict rule on grids with known answers, and the family
// ranking's ratio on a made-up family.
#include "contact/continuum_loop_scores.h"
#include "core/error.h"
#include "oracle/rolling_study.h"
#include "oracle/uniformity_score.h"
#include "study/robustness/comparison_verdict.h"
#include "study/robustness/family_ranking.h"
#include <array>
#include <cmath>
#include <limits>
#include <utility>
#include <gtest/gtest.h>
#include <numbers>

using namespace rollcheck;
using namespace rollcheck::study::robustness;

namespace
{
oracle::RealRolling roll(const std::string& body, double energy_excess, long samples = 8000)
{
  geometry::BodySpec spec;
  spec.body = body;
  oracle::RollingStudyParameters p;
  p.rolling_energy = energy_excess;
  p.samples_per_loop = samples;
  return oracle::real_rolling(spec, p);
}

contact::ContinuumLoopScores scores(const oracle::RealRolling& run, contact::ContinuumLoopSettings s)
{
  return contact::continuum_loop_scores(run.trajectory, 0, run.first_loop_end_s, run.surface_area_m2,
                                        {run.mass.centre_of_mass_m, run.mass.mass_kg, 9.81}, s);
}
} // namespace

TEST(ContinuumLoopScores, CylinderMeetsItsClosedFormUnderEveryChoice)
{
  // r = 1, L = 2: every quantity is uniform on the side, none on the caps:
  // V_whole = A_caps / A_side = r / L, V_touched = 0, max / mean = 1.
  const oracle::RealRolling run = roll("cylinder", 0.1);
  for (auto rule : {contact::LoadRule::static_through_centre_of_mass, contact::LoadRule::dynamic,
                    contact::LoadRule::uniform})
    for (auto width : {oracle::ContactWidthModel::hertz, oracle::ContactWidthModel::rigid})
      for (double margin : {0.02, 0.1})
      {
        contact::ContinuumLoopSettings s;
        s.load_rule = rule;
        s.width = width;
        s.end_margin = margin;
        const contact::ContinuumLoopScores r = scores(run, s);
        for (const contact::ContinuumScore& x : {r.contact_time, r.peak_pressure, r.accumulated_pressure, r.damage})
        {
          EXPECT_NEAR(x.whole, 0.5, 2e-4); // the mass mesh's area: 2048 sides
          EXPECT_NEAR(x.touched, 0.0, 1e-6);
          EXPECT_NEAR(x.peak_to_mean, 1.0, 1e-6);
        }
        EXPECT_NEAR(r.swept_area_m2, 4 * std::numbers::pi, 4 * std::numbers::pi * 2e-4);
      }
}

TEST(ContinuumLoopScores, OloidContactTimeIsTheOraclesContinuumU)
{
  // The oracle integrates U_inf its own way (oracle/uniformity_score.h, the
  // dynamic load); so do these scores, with the dynamic rule.
  // Hertz width: the same trapezoid rule on the same samples, to rounding.
  // (The geometric width's second moment is integrated between samples here,
  // where the oracle's trapezoid rule converges slowly: see the next test.)
  const oracle::RealRolling run = roll("oloid", 0.1);
  const double oracle_u = oracle::continuum_uniformity(run.trajectory, 0, run.first_loop_end_s, run.surface_area_m2);
  EXPECT_NEAR(scores(run, {}).contact_time.whole / oracle_u, 1.0, 1e-4);
  // Every point of the true oloid is swept once in a loop (Dirnboeck and
  // Stachel 1997): the swept area is the whole surface, 4 pi r^2.
  EXPECT_NEAR(scores(run, {}).swept_area_m2 / (4 * std::numbers::pi), 1.0, 1e-3);
}

TEST(ContinuumLoopScores, OloidUOverTheRollingEnergyMatchesAnIndependentComputation)
{
  // An independent implementation of the oloid's rolling and of U_inf gave,
  // at energy excess 0.02, 0.1, 0.36, 1, 3: Hertz width 1.758, 0.899, 0.501,
  // 0.255, 0.063; geometric width 3.33, 1.63, 0.99, 0.74, 0.63.
  const double energies[] = {0.02, 0.1, 0.36, 1, 3};
  const double hertz[] = {1.758, 0.899, 0.501, 0.255, 0.063};
  const double geometric[] = {3.33, 1.63, 0.99, 0.74, 0.63};
  for (int i = 0; i < 5; ++i)
  {
    const oracle::RealRolling run = roll("oloid", energies[i]);
    contact::ContinuumLoopSettings s;
    EXPECT_NEAR(scores(run, s).contact_time.whole / hertz[i], 1.0, 0.01) << energies[i];
    s.width = oracle::ContactWidthModel::rigid;
    EXPECT_NEAR(scores(run, s).contact_time.whole / geometric[i], 1.0, 0.01) << energies[i];
  }
}

TEST(ContinuumLoopScores, OloidScoresAreResolutionFree)
{
  // The samples of the loop and the pieces along each ruling doubled.
  const oracle::RealRolling coarse = roll("oloid", 0.1, 8000), fine = roll("oloid", 0.1, 16000);
  for (auto rule : {contact::LoadRule::static_through_centre_of_mass, contact::LoadRule::dynamic})
    for (auto width : {oracle::ContactWidthModel::hertz, oracle::ContactWidthModel::rigid})
  {
    contact::ContinuumLoopSettings s;
    s.load_rule = rule;
    s.width = width;
    const contact::ContinuumLoopScores a = scores(coarse, s);
    s.pieces = 128;
    const contact::ContinuumLoopScores b = scores(fine, s);
    EXPECT_NEAR(b.contact_time.whole / a.contact_time.whole, 1.0, 0.01);
    EXPECT_NEAR(b.peak_pressure.whole / a.peak_pressure.whole, 1.0, 0.01);
    EXPECT_NEAR(b.accumulated_pressure.whole / a.accumulated_pressure.whole, 1.0, 0.01);
    EXPECT_NEAR(b.damage.whole / a.damage.whole, 1.0, 0.01);
  }
}

TEST(ContinuumLoopScores, AccumulatedPressureAloneIsTheSameNumber)
{
  // FEM-SDS reads the accumulated pressure alone: skipping the other scores
  // must not move it by a bit, under either width and the FEM factor.
  const oracle::RealRolling run = roll("oloid", 0.1, 2000);
  for (auto width : {oracle::ContactWidthModel::hertz, oracle::ContactWidthModel::rigid})
  {
    contact::ContinuumLoopSettings s;
    s.width = width;
    s.pressure_factor = [](double lambda) { return 1 + 0.1 * std::log10(lambda); };
    const contact::ContinuumLoopScores all = scores(run, s);
    s.accumulated_pressure_only = true;
    const contact::ContinuumLoopScores alone = scores(run, s);
    EXPECT_GT(all.accumulated_pressure.whole, 0);
    EXPECT_EQ(alone.accumulated_pressure.whole, all.accumulated_pressure.whole);
    EXPECT_EQ(alone.accumulated_pressure.touched, all.accumulated_pressure.touched);
    EXPECT_EQ(alone.accumulated_pressure.peak_to_mean, all.accumulated_pressure.peak_to_mean);
    EXPECT_EQ(alone.load_ratio_min, all.load_ratio_min);
    EXPECT_EQ(alone.load_ratio_max, all.load_ratio_max);
    EXPECT_GT(all.damage.whole, 0);
    EXPECT_EQ(alone.damage.whole, 0);
    EXPECT_EQ(alone.contact_time.whole, 0);
  }
}

TEST(ContinuumLoopScores, ASecondPressureFactorScoresAsItsOwnPassToTheBit)
{
  // pressure_factors' pair in one pass: the first factor's scores are those
  // of a pass with it as pressure_factor, the second's accumulated pressure
  // that of a pass with the second, to the bit (the FEM table and its half,
  // study/loop_scores/fem_sds_continuum.h). Both kinds of factor at once are refused.
  const oracle::RealRolling run = roll("oloid", 0.1, 1000);
  const auto g = [](double lambda) { return 1 + 0.1 * std::log10(lambda); };
  const auto h = [](double lambda) { return 1.2 - 0.03 * std::log10(lambda); };
  for (const oracle::ContactWidthModel width : {oracle::ContactWidthModel::hertz, oracle::ContactWidthModel::rigid})
    for (const bool accumulated_only : {true, false})
    {
      contact::ContinuumLoopSettings s;
      s.width = width;
      s.accumulated_pressure_only = accumulated_only;
      s.pressure_factors = [&](double lambda) { return std::array<double, 2>{g(lambda), h(lambda)}; };
      const contact::ContinuumLoopScores both = scores(run, s);
      s.pressure_factors = nullptr;
      s.pressure_factor = g;
      const contact::ContinuumLoopScores first = scores(run, s);
      s.pressure_factor = h;
      const contact::ContinuumLoopScores second = scores(run, s);
      // The first factor's every score, the peak pressure and damage included.
      for (const auto& [a, b] : {std::pair{both.accumulated_pressure, first.accumulated_pressure},
                                 std::pair{both.peak_pressure, first.peak_pressure},
                                 std::pair{both.damage, first.damage}, std::pair{both.contact_time, first.contact_time}})
      {
        EXPECT_EQ(a.whole, b.whole);
        EXPECT_EQ(a.peak_to_mean, b.peak_to_mean);
      }
      EXPECT_EQ(both.peak_pressure_max_pa, first.peak_pressure_max_pa);
      const contact::ContinuumScore& b = both.accumulated_pressure_second_factor;
      EXPECT_EQ(b.whole, second.accumulated_pressure.whole);
      EXPECT_EQ(b.touched, second.accumulated_pressure.touched);
      EXPECT_EQ(b.peak_to_mean, second.accumulated_pressure.peak_to_mean);
      EXPECT_EQ(b.touched_area_m2, second.accumulated_pressure.touched_area_m2);
      EXPECT_NE(b.whole, both.accumulated_pressure.whole);
      EXPECT_EQ(first.accumulated_pressure_second_factor.whole, 0); // no second factor, no score
      s.pressure_factors = [&](double lambda) { return std::array<double, 2>{g(lambda), h(lambda)}; };
      EXPECT_THROW(scores(run, s), InputError);
    }
}

TEST(ContinuumLoopScores, PartsOfTheWindowAddUpToTheWhole)
{
  // The window's intervals integrated in three parts (as ranks do, study/
  // loop_scores/fem_sds_continuum.h) and added give the whole window's
  // moments and scores, to rounding; a fourth part of three is refused.
  const oracle::RealRolling run = roll("oloid", 0.1, 2000);
  contact::ContinuumLoopSettings s;
  s.pressure_factors = [](double lambda) { return std::array<double, 2>{1.0, 1 + 0.1 * std::log10(lambda)}; };
  const contact::RollingBodyMass mass{run.mass.centre_of_mass_m, run.mass.mass_kg, 9.81};
  const double end = run.first_loop_end_s;
  const contact::ContinuumMoments whole = contact::continuum_loop_moments(run.trajectory, 0, end, mass, s);
  contact::ContinuumMoments added;
  for (int part = 0; part < 3; ++part)
  {
    const contact::ContinuumMoments m = contact::continuum_loop_moments(run.trajectory, 0, end, mass, s, {part, 3});
    EXPECT_GT(m.swept, 0.2 * whole.swept) << "part " << part; // each part a third of the intervals
    added += m;
  }
  EXPECT_NEAR(added.swept / whole.swept, 1.0, 1e-12);
  for (int q = 0; q < contact::ContinuumMoments::quantities; ++q)
  {
    EXPECT_NEAR(added.first[q] / whole.first[q], 1.0, 1e-12) << q;
    EXPECT_NEAR(added.second[q] / whole.second[q], 1.0, 1e-12) << q;
    EXPECT_EQ(added.max[q], whole.max[q]) << q;
  }
  EXPECT_NEAR(added.second_factor.first / whole.second_factor.first, 1.0, 1e-12);
  EXPECT_NEAR(added.second_factor.second / whole.second_factor.second, 1.0, 1e-12);
  EXPECT_EQ(added.second_factor.max, whole.second_factor.max);
  EXPECT_EQ(added.load_ratio_min, whole.load_ratio_min);
  EXPECT_EQ(added.load_ratio_max, whole.load_ratio_max);
  const contact::ContinuumLoopScores a = contact::continuum_loop_scores(added, run.surface_area_m2, s);
  const contact::ContinuumLoopScores w = scores(run, s);
  EXPECT_NEAR(a.accumulated_pressure.whole / w.accumulated_pressure.whole, 1.0, 1e-10);
  EXPECT_NEAR(a.accumulated_pressure_second_factor.whole / w.accumulated_pressure_second_factor.whole, 1.0, 1e-10);
  EXPECT_THROW(contact::continuum_loop_moments(run.trajectory, 0, end, mass, s, {3, 3}), InputError);
}

TEST(ContinuumLoopScores, RefusesBadSettings)
{
  const oracle::RealRolling run = roll("cylinder", 0.1, 400);
  contact::ContinuumLoopSettings s;
  s.end_margin = 0.5;
  EXPECT_THROW(scores(run, s), InputError);
  s.end_margin = 0.05;
  s.normal_load_n = -1;
  EXPECT_THROW(scores(run, s), InputError);
  EXPECT_THROW(parse_named(contact::load_rule_names(), std::string("quasi"), "load rule", "--load-rule"), InputError);
}

TEST(ComparisonVerdict, RobustDependentAndUntestable)
{
  const std::vector<Choice> grid = {{"energy", {"0.1", "1", "3"}}, {"width", {"hertz", "geometric"}}};
  // Robust: below 1 everywhere.
  Verdict v = judge_comparison(grid, [](const Cell& c) { return std::optional<double>(0.2 + 0.1 * c[0] + 0.05 * c[1]); });
  EXPECT_TRUE(v.robust);
  EXPECT_EQ(v.text, "robust");
  EXPECT_DOUBLE_EQ(v.ratio_min, 0.2);
  EXPECT_DOUBLE_EQ(v.ratio_max, 0.45);
  EXPECT_EQ(v.cells, 6);
  // Flips along energy between "0.1" and "1" for the hertz width only.
  v = judge_comparison(grid, [](const Cell& c) { return std::optional<double>(c[1] == 0 && c[0] >= 1 ? 0.5 : 2.0); });
  EXPECT_FALSE(v.robust);
  EXPECT_EQ(v.text, "depends on energy, width");
  ASSERT_EQ(v.flips.size(), 3u); // energy 0->1 at hertz; width at energy 1 and 2
  EXPECT_EQ(v.flips[0].choice, 0);
  EXPECT_EQ(v.flips[0].from, 0);
  EXPECT_EQ(v.flips[0].to, 1);
  // An undefined cell is left out, not counted as a flip.
  v = judge_comparison(grid, [](const Cell& c) -> std::optional<double> {
    if (c[0] == 2)
      return std::nullopt;
    return 0.5;
  });
  EXPECT_TRUE(v.robust);
  EXPECT_EQ(v.cells, 4);
  // A flip across an undefined cell is still a flip, from the last defined
  // value to the next one.
  v = judge_comparison(grid, [](const Cell& c) -> std::optional<double> {
    if (c[0] == 1)
      return std::nullopt;
    return c[0] == 0 ? 0.5 : 2.0;
  });
  EXPECT_EQ(v.text, "depends on energy");
  ASSERT_EQ(v.flips.size(), 2u); // one per width
  EXPECT_EQ(v.flips[0].from, 0);
  EXPECT_EQ(v.flips[0].to, 2);
  v = judge_comparison(grid, [](const Cell&) -> std::optional<double> { return std::nullopt; });
  EXPECT_EQ(v.text, "cannot be tested");
}

TEST(FamilyRanking, AMirrorPairIsOneBody)
{
  // (75, 0.7, 1) and (105, 0.7, 1) are one body reflected; (120, 1, 1) has no
  // mirror (60 deg) in this grid and stays.
  const std::vector<geometry::RollerGenome> grid = {
      {75, 0.7, 1.0, 2}, {105, 0.7, 1.0, 2}, {105, 1.0, 1.0, 2}, {120, 1.0, 1.0, 2}, {90, 1.0, 1.0, 2}};
  const auto kept = distinct_bodies(grid);
  ASSERT_EQ(kept.size(), 4u);
  EXPECT_EQ(kept[0].theta_deg, 75);
  EXPECT_EQ(kept[1].theta_deg, 105); // its mirror (75, 1, 1) is not in the grid
  EXPECT_EQ(kept[1].offset, 1.0);
  EXPECT_EQ(kept[2].theta_deg, 120);
  EXPECT_EQ(kept[3].theta_deg, 90);
}


TEST(FamilyRanking, TheBestStayTheBestExactlyWhileTheRatioIsBelowOne)
{
  // Four genomes over three cells; the two best at cell 0 are a and b.
  const double nan = std::numeric_limits<double>::quiet_NaN();
  FamilyRanking r;
  r.genomes = {{{90, 1.0, 1.0, 2}, {1.0, 1.0, 1.0}},   // a
               {{90, 0.7, 1.0, 2}, {2.0, 2.0, nan}},   // b: not scored at cell 2
               {{90, 1.3, 1.0, 2}, {3.0, 1.5, 4.0}},   // c: overtakes b at cell 1
               {{90, 1.0, 0.8, 2}, {4.0, nan, 5.0}}};  // d: not scored at cell 1
  r.best = best_genomes(r.genomes, 0, 2);
  ASSERT_EQ(r.best, (std::vector<std::size_t>{0, 1}));
  EXPECT_DOUBLE_EQ(*best_against_rest(r, 0), 2.0 / 3.0); // worst of the best / best of the rest
  EXPECT_DOUBLE_EQ(*best_against_rest(r, 1), 2.0 / 1.5);
  EXPECT_FALSE(best_against_rest(r, 2)); // one of the best has no score there
  EXPECT_EQ(best_genomes(r.genomes, 1, 2), (std::vector<std::size_t>{0, 2}));
  EXPECT_EQ(genome_label(r.genomes[1].genome), "(90, 0.7, 1)");
  const std::vector<Choice> grid = {{"rolling_energy", {"0.1", "1", "3"}}};
  const Verdict v = judge_comparison(grid, [&](const Cell& c) { return best_against_rest(r, c[0]); });
  EXPECT_EQ(v.text, "depends on rolling_energy");
  EXPECT_EQ(v.cells, 2);
  const nlohmann::json j = to_json(r, grid);
  EXPECT_EQ(j.at("best"), (nlohmann::json{"(90, 1, 1)", "(90, 0.7, 1)"}));
  EXPECT_EQ(j.at("genomes").at(3).at("cells_scored"), 2);
}
