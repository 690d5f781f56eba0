// The family search (study/optimize_family.h) on cheap settings: the score of
// a genome is a function of the genome, its (90, 1, 1) members are the bodies
// the library builds by name (the centre-line one the true oloid, area 4 pi),
// the rigid score is the mean of the replicates score_body gives with the
// nudged spins, and the search returns a body no worse than its start.
#include "study/optimize_family.h"
#include "core/error.h"
#include "geometry/body.h"
#include "geometry/mass_properties.h"
#include "study/paper_quirks.h"
#include "study/score_body.h"
#include <cmath>
#include <gtest/gtest.h>
#include <numbers>

using namespace rollcheck;
using namespace rollcheck::study;

namespace
{
/// Approximate oracle, CDS, 100 points per circle: milliseconds per genome.
FamilySearchSettings cheap()
{
  FamilySearchSettings s;
  s.points = 100;
  s.max_evaluations = 15;
  s.sweep_points = 3;
  s.threads = 2;
  return s;
}

/// The scores score_body gives a named body under the search's oracle settings.
BodyScores scores_of(const FamilySearchSettings& s, geometry::BodySpec body)
{
  ScoreBodySettings b = s.scoring;
  b.oracle = s.oracle;
  b.body = std::move(body);
  b.compat = s.paper_compat ? oracle::PaperCompat::reference() : oracle::PaperCompat::corrected();
  b.metrics = contact::MetricSet::parse("cds", "test");
  return score_body(b);
}

const std::vector<double> family_oloid{90, 1, 1};
} // namespace

TEST(OptimizeFamily, TheScoreIsAFunctionOfTheGenome)
{
  const FamilySearchSettings s = cheap();
  const std::vector<double> x{75.5, 1.1, 0.9};
  EXPECT_EQ(family_score(s, x), family_score(s, x));
  EXPECT_NE(family_score(s, x), family_score(s, family_oloid));
}

TEST(OptimizeFamily, ItsNinetyOneOneMembersAreTheNamedOloids)
{
  for (const bool compat : {false, true})
  {
    FamilySearchSettings s = cheap();
    s.paper_compat = compat;
    s.family = geometry::RollerFamily::centre_line;
    geometry::BodySpec oloid;
    oloid.body = "oloid";
    oloid.points = s.points;
    EXPECT_EQ(family_score(s, family_oloid), *scores_of(s, oloid).scores.cds);
    // The true oloid's area is 4 pi r^2; the hull of 100 points per circle is within 1e-3 of it.
    const double area = geometry::mass_properties(geometry::make_body(family_body(s, family_oloid))).area_m2;
    EXPECT_NEAR(area / (4 * std::numbers::pi), 1, 1e-3);

    s.family = geometry::RollerFamily::paper;
    oloid.body = "paper-oloid";
    EXPECT_EQ(family_score(s, family_oloid), *scores_of(s, oloid).scores.cds);
  }
}

TEST(OptimizeFamily, TheRigidScoreIsTheMeanOfTheNudgedRuns)
{
  FamilySearchSettings s = cheap();
  s.oracle = Oracle::rigid;
  s.replicates = 3;
  s.paper_compat = true; // the preprint's chaotic dynamics, over its 10 s runs
  geometry::BodySpec body = family_body(s, family_oloid);
  const double nominal = *scores_of(s, body).scores.cds;
  double sum = nominal;
  // Replicates 1 and 2: every spin nudged by +1e-12 and -1e-12 rad/s along x (the band's first two).
  for (const double nudge : {spin_nudge_rad_s, -spin_nudge_rad_s})
  {
    FamilySearchSettings nudged = s;
    for (Eigen::Vector3d& w : nudged.scoring.rigid.initial_spins)
      w.x() += nudge;
    const double value = *scores_of(nudged, body).scores.cds;
    EXPECT_NE(value, nominal) << "the nudge did not change the run: the replicates measure no noise";
    sum += value;
  }
  EXPECT_DOUBLE_EQ(family_score(s, family_oloid), sum / 3);
}

TEST(OptimizeFamily, TheSearchReturnsABodyNoWorseThanItsStart)
{
  const FamilySearchSettings s = cheap();
  const FamilySearchResult r = optimize_family(s);
  EXPECT_EQ(r.search.start_value, family_score(s, family_oloid));
  EXPECT_LE(r.search.best_value, r.search.start_value);
  EXPECT_EQ(r.search.best_value, family_score(s, r.search.best_x));
  EXPECT_LE(r.search.evaluations, s.max_evaluations);
  EXPECT_GT(r.noise_sigma, 0);
  EXPECT_EQ(r.noise_replicates.values.front(), r.search.start_value);
  ASSERT_TRUE(r.at_start.has_value());
  EXPECT_EQ(r.at_start->value, r.search.start_value);
  ASSERT_EQ(r.sweeps.size(), 3u);
  EXPECT_EQ(r.sweeps[0].values[1], r.search.start_value); // the middle of 3 points is the start
  const nlohmann::json j = to_json(r);
  for (const char* key : {"optimum", "noise", "verdict_at_start", "derivatives_at_start", "derivatives_at_optimum",
                          "sweeps", "score_evaluations", "oracle_runs", "wall_s", "mesh"})
    EXPECT_TRUE(j.contains(key)) << key;
  EXPECT_EQ(j["optimum"]["beats_start"], r.search.beats_start);
}

TEST(OptimizeFamily, BadBoxesAreNamed)
{
  FamilySearchSettings s = cheap();
  s.theta_deg.min = 150; // above its max, 140
  try
  {
    validate(s);
    FAIL() << "theta_min_deg > theta_max_deg accepted";
  }
  catch (const InputError& e)
  {
    EXPECT_NE(std::string(e.what()).find("theta_min_deg"), std::string::npos) << e.what();
  }
  s = cheap();
  s.ratio.start = 1.5;
  EXPECT_THROW(validate(s), InputError);
  s = cheap();
  s.score = FamilyScore::uniformity;
  EXPECT_THROW(validate(s), InputError);
}
