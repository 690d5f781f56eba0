// FEM-SDS's continuum value (study/loop_scores/fem_sds_continuum.h): the
// cylinder against its closed form, V = A_caps / A_side = r / L, under every
// load rule and contact width (its line load is the same on every generator,
// so the FEM's g is one constant and cancels); the true oloid's and the
// cylinder's values when the loop's samples and the pieces along each ruling
// double; the oloid's FEM value against its line-Hertz value within the FEM's
// correction (under 1 %, docs/results/fem-sds.md); its own FEM table check
// (every other node), and a loop scored for its continuum value alone.
#include "core/error.h"
#include "fem/petsc_session.h"
#include "fem/scenes/slice_scaling.h"
#include "study/loop_scores/fem_sds.h"
#include "study/loop_scores/fem_sds_continuum.h"
#include <cmath>
#include <gtest/gtest.h>

using namespace rollcheck;
using study::loop_scores::ContinuumSds;
using study::loop_scores::FemSdsSettings;

namespace
{
oracle::RealRolling roll(const std::string& body, long samples)
{
  geometry::BodySpec spec;
  spec.body = body;
  oracle::RollingStudyParameters p;
  p.samples_per_loop = samples;
  return oracle::real_rolling(spec, p);
}

ContinuumSds continuum(const oracle::RealRolling& run, const FemSdsSettings& s, fem::SliceScaling& table)
{
  return study::loop_scores::continuum_sds(MPI_COMM_WORLD, run, study::loop_scores::continuum_settings(s), table);
}
} // namespace

TEST(FemSdsContinuum, CylinderMeetsItsClosedFormUnderEveryLoadRuleAndWidth)
{
  fem::ensure_petsc();
  FemSdsSettings s; // r = 1 m, L = 2 m: V = r / L = 0.5
  fem::SliceScaling table(study::loop_scores::slice_settings(s), s.table_nodes_per_decade);
  const oracle::RealRolling run = roll("cylinder", 2000);
  for (auto rule : {contact::LoadRule::static_through_centre_of_mass, contact::LoadRule::dynamic,
                    contact::LoadRule::uniform})
    for (auto width : {oracle::ContactWidthModel::rigid, oracle::ContactWidthModel::hertz})
    {
      s.load_rule = rule;
      s.contact_width = width;
      const ContinuumSds c = continuum(run, s, table);
      EXPECT_NEAR(c.fem, 0.5, 2e-4); // the 2048-sided mass mesh's area
      EXPECT_NEAR(c.line_hertz, 0.5, 2e-4);
      EXPECT_NEAR(c.load_ratio_min / c.load_ratio_max, 1.0, 1e-9); // one line load
      EXPECT_LT(std::abs(c.change()), 1e-6);
    }
}

TEST(FemSdsContinuum, OloidAndCylinderAreResolutionFree)
{
  fem::ensure_petsc();
  FemSdsSettings s; // the defaults: dynamic load, geometric width, 5 % end margin
  fem::SliceScaling table(study::loop_scores::slice_settings(s), s.table_nodes_per_decade);
  for (const char* body : {"oloid", "cylinder"})
  {
    s.continuum_pieces = 32;
    const ContinuumSds coarse = continuum(roll(body, 4000), s, table);
    s.continuum_pieces = 64;
    const ContinuumSds fine = continuum(roll(body, 8000), s, table);
    EXPECT_LT(std::abs(fine.fem / coarse.fem - 1), 0.01) << body << ": " << coarse.fem << " -> " << fine.fem;
    EXPECT_LT(std::abs(fine.line_hertz / coarse.line_hertz - 1), 0.01) << body;
    EXPECT_LT(std::abs(fine.change()), 0.01) << body;
    // The FEM's correction g varies by under 1 % over the loop's load ratios.
    EXPECT_NEAR(fine.fem / fine.line_hertz, 1.0, 0.01) << body;
  }
}

TEST(FemSdsContinuum, OloidIsAboveTheCylinderAndRefusesAUniformRateUnderTheDynamicLoad)
{
  fem::ensure_petsc();
  FemSdsSettings s;
  s.samples_per_loop = 2000;
  s.body.body = "oloid";
  s.time_law = contact::TimeLaw::uniform_rate;
  fem::SliceScaling table(study::loop_scores::slice_settings(s), s.table_nodes_per_decade);
  EXPECT_THROW(study::loop_scores::score_body_loop(MPI_COMM_WORLD, s, table), InputError);
  s.load_rule = contact::LoadRule::static_through_centre_of_mass;
  const study::loop_scores::BodyLoop oloid = study::loop_scores::score_body_loop(MPI_COMM_WORLD, s, table);
  ASSERT_TRUE(oloid.continuum);
  EXPECT_GT(oloid.continuum->fem, 0.5); // the cylinder's r / L: its load is even, the oloid's is not
  const nlohmann::json j = study::loop_scores::continuum_json(oloid.continuum);
  EXPECT_EQ(j.at("fem_sds_continuum").get<double>(), oloid.continuum->fem);
  EXPECT_TRUE(study::loop_scores::continuum_json(std::nullopt).at("fem_sds_continuum").is_null());
}

TEST(FemSdsContinuum, ItsTableIsRefinedUntilEveryOtherNodeAgrees)
{
  // The continuum value's own table check: its value with every other node
  // of the FEM table. At the default tolerance the oloid's starting table
  // (2 nodes a decade) is fine enough; a tolerance no table can meet refines
  // it up to the most nodes a decade allowed, and says so.
  fem::ensure_petsc();
  FemSdsSettings s;
  const oracle::RealRolling run = roll("oloid", 8000); // 2000 samples are not converged: -3.8 %
  fem::SliceScaling table(study::loop_scores::slice_settings(s), s.table_nodes_per_decade);
  const ContinuumSds converged = continuum(run, s, table);
  EXPECT_EQ(converged.nodes_per_decade, 2);
  EXPECT_LT(std::abs(converged.table_change()), converged.tolerance);
  EXPECT_EQ(converged.status(), "converged");
  const ContinuumSds refined = study::loop_scores::continuum_sds(
      MPI_COMM_WORLD, run, study::loop_scores::continuum_settings(s), table, {.tolerance = 1e-12, .max_nodes_per_decade = 4});
  EXPECT_EQ(refined.nodes_per_decade, 4);
  EXPECT_EQ(table.nodes_per_decade(), 4);
  EXPECT_TRUE(refined.status().starts_with("not converged: ")) << refined.status();
  EXPECT_NE(refined.table_change(), 0.0); // two tables, not one read twice
  // Twice the nodes keep the value within the tolerance it was converged to.
  EXPECT_LT(std::abs(refined.fem / converged.fem - 1), converged.tolerance);
}

TEST(FemSdsContinuum, ALoopScoredForItsContinuumValueAloneSkipsTheTemplateAndTakesItsStatus)
{
  // What a search scoring the continuum value computes (fem_sds_family.h
  // fem_sds_scorer): the same continuum value as the whole loop's, no mesh,
  // no template, and the continuum's convergence as the loop's status.
  fem::ensure_petsc();
  FemSdsSettings s;
  s.samples_per_loop = 8000;
  s.body.body = "oloid";
  fem::SliceScaling table(study::loop_scores::slice_settings(s), s.table_nodes_per_decade);
  const study::loop_scores::BodyLoop whole = study::loop_scores::score_body_loop(MPI_COMM_WORLD, s, table);
  const study::loop_scores::BodyLoop alone = study::loop_scores::score_body_loop(
      MPI_COMM_WORLD, s, table, {.uniformity = false, .face_template = false, .continuum = true});
  ASSERT_TRUE(whole.continuum && alone.continuum);
  EXPECT_EQ(alone.continuum->fem, whole.continuum->fem);
  EXPECT_EQ(alone.n_faces, 0);
  EXPECT_EQ(alone.loop.samples, 0U);
  EXPECT_FALSE(alone.uniformity);
  EXPECT_EQ(alone.status(), alone.continuum->status());
  EXPECT_EQ(whole.status(), whole.loop.status());
  const nlohmann::json j = study::loop_scores::continuum_json(alone.continuum);
  EXPECT_EQ(j.at("fem_sds_continuum_status").get<std::string>(), "converged");
  EXPECT_EQ(j.at("fem_sds_continuum_table_change").get<double>(), alone.continuum->table_change());
}

TEST(FemSdsContinuum, ItsStatusNeedsBothChangesBelowTheTolerance)
{
  ContinuumSds c;
  c.tolerance = 0.01;
  c.fem = 1.0;
  c.fem_coarse = 1.0 / 1.005;    // +0.5 % from half the samples and pieces
  c.fem_half_table = 1.0 / 1.02; // +2 % from every other node
  EXPECT_FALSE(c.converged());
  EXPECT_EQ(c.status(), "not converged: halving the samples and pieces changes the continuum value by +0.50 %, "
                        "halving the FEM table by +2.00 % (tolerance 1 %)");
  c.fem_half_table = 1.0 / 0.995;
  EXPECT_EQ(c.status(), "converged");
  c.fem_coarse = 1.0 / 0.98;
  EXPECT_FALSE(c.converged());
}
