// The rim loop's samples under a load rule (study/rims/rule_loop_samples.h),
// against independent computations: the static rule mapped one sample at a
// time is fem-sds's own mapping of the whole loop (loop_scores::map_loop_samples,
// F through the centre of mass); the uniform rule loads both ends of every
// ruling with the same q = F / L; the dynamic rule on the cylinder, which
// rolls straight with N = m g through its middle, is the static rule; and
// over the oloid's loop the dynamic rule's force averages to F (the vertical
// momentum of a periodic motion: the mean of N over a loop is m g).
#include "contact/continuum_loop_scores.h"
#include "fem/petsc_session.h"
#include "geometry/body.h"
#include "oracle/contact_density.h"
#include "oracle/rolling_body.h"
#include "oracle/rolling_study.h"
#include "study/loop_scores/loop_sds.h"
#include "study/rims/rule_loop_samples.h"
#include <gtest/gtest.h>
#include <cmath>
#include <numbers>

using namespace rollcheck;
using study::loop_scores::LoopSamples;

namespace
{
struct Loop
{
  oracle::RealRolling run;
  geometry::SurfaceMesh mesh;
  oracle::RollingBody body;
  oracle::FaceCones cones;
  study::loop_scores::LoopSource source;
};

Loop roll(const std::string& name, long samples)
{
  fem::ensure_petsc(); // MPI for the mapping's collectives
  geometry::BodySpec spec;
  spec.body = name;
  spec.radius_m = 0.01;
  spec.height_m = 0.02;
  oracle::RollingStudyParameters p;
  p.samples_per_loop = samples;
  Loop l{oracle::real_rolling(spec, p), geometry::make_body(spec), {}, {}, {}};
  l.body = oracle::make_rolling_body(l.mesh, oracle::PaperCompat::corrected());
  l.cones = oracle::face_cones(l.mesh);
  l.source = {l.run.circles, l.run.mass.centre_of_mass_m, {}, {}, {}, ""};
  for (const oracle::RollingSample& s : l.run.trajectory.samples)
    if (s.time_s <= l.run.scored_end_s)
    {
      l.source.rotations.push_back(s.rotation);
      l.source.times_s.push_back(s.time_s);
    }
  return l;
}

constexpr double force_n = 800, modulus_pa = 200e9 / (1 - 0.3 * 0.3);

LoopSamples by_rule(const Loop& l, contact::LoadRule rule)
{
  const std::vector<study::rims::RulingLoad> loads = study::rims::ruling_loads(l.run, rule, force_n, 9.81);
  study::loop_scores::LoopSdsSettings s;
  s.normal_load_n = force_n;
  return study::rims::map_rule_samples(MPI_COMM_WORLD, l.source, loads, l.body, l.cones, modulus_pa, s);
}

LoopSamples fem_sds_mapping(const Loop& l)
{
  study::loop_scores::LoopSdsSettings s;
  s.normal_load_n = force_n;
  return study::loop_scores::map_loop_samples(MPI_COMM_WORLD, l.source, l.body,
                                              Eigen::VectorXd::Zero(l.body.face_areas.size()), l.cones, modulus_pa, s);
}

/// q = p_H^2 pi R / E* of a loaded end (line Hertz's peak inverted).
double end_load(const study::loop_scores::LoadedEnd& e)
{
  return e.line_hertz_pa * e.line_hertz_pa * std::numbers::pi * e.radius_m / modulus_pa;
}

void expect_same_samples(const LoopSamples& a, const LoopSamples& b)
{
  EXPECT_EQ(a.by_contact, b.by_contact);
  ASSERT_EQ(a.rulings.size(), b.rulings.size());
  for (std::size_t k = 0; k < a.rulings.size(); ++k)
  {
    const auto &x = a.rulings[k], &y = b.rulings[k];
    EXPECT_EQ(x.even, y.even);
    ASSERT_EQ(x.points.size(), y.points.size());
    for (std::size_t i = 0; i < x.points.size(); ++i)
    {
      EXPECT_EQ(x.points[i].face, y.points[i].face);
      EXPECT_NEAR(x.points[i].line_hertz_pa / y.points[i].line_hertz_pa, 1, 1e-9);
      EXPECT_NEAR(x.points[i].load_ratio / y.points[i].load_ratio, 1, 1e-9);
    }
    ASSERT_EQ(x.ends.size(), y.ends.size());
    for (std::size_t i = 0; i < x.ends.size(); ++i)
    {
      EXPECT_EQ(x.ends[i].face, y.ends[i].face);
      EXPECT_NEAR(x.ends[i].line_hertz_pa / y.ends[i].line_hertz_pa, 1, 1e-9);
      EXPECT_NEAR(x.ends[i].interior_angle_rad, y.ends[i].interior_angle_rad, 1e-12);
      EXPECT_NEAR(x.ends[i].dihedral_angle_rad, y.ends[i].dihedral_angle_rad, 1e-12);
    }
  }
  EXPECT_NEAR(a.load_ratio_min / b.load_ratio_min, 1, 1e-9);
  EXPECT_NEAR(a.load_ratio_max / b.load_ratio_max, 1, 1e-9);
  EXPECT_NEAR((a.line_all - b.line_all).norm() / b.line_all.norm(), 0, 1e-9);
  EXPECT_NEAR((a.line_even - b.line_even).norm() / b.line_even.norm(), 0, 1e-9);
}
} // namespace

TEST(RimLoadRule, TheStaticRuleSampleBySampleIsFemSdsMapping)
{
  const Loop oloid = roll("oloid", 128);
  const LoopSamples fem_sds = fem_sds_mapping(oloid);
  ASSERT_GT(fem_sds.ruling_count(), 0u);
  expect_same_samples(by_rule(oloid, contact::LoadRule::static_through_centre_of_mass), fem_sds);
}

TEST(RimLoadRule, TheUniformRuleLoadsBothEndsOfEveryRulingAlike)
{
  const Loop oloid = roll("oloid", 128);
  const LoopSamples uniform = by_rule(oloid, contact::LoadRule::uniform);
  const LoopSamples fem_sds = fem_sds_mapping(oloid);
  // No ruling tips under a load through its middle.
  EXPECT_GE(uniform.ruling_count(), fem_sds.ruling_count());
  std::size_t ends = 0;
  for (const study::loop_scores::RulingSample& r : uniform.rulings)
  {
    ASSERT_EQ(r.ends.size(), 2u);
    EXPECT_NEAR(end_load(r.ends[0]) / end_load(r.ends[1]), 1, 1e-9);
    for (const auto& e : r.ends)
      EXPECT_NEAR(e.load_ratio * modulus_pa * e.radius_m / end_load(e), 1, 1e-9);
    ends += 2;
  }
  EXPECT_EQ(ends, 2 * uniform.rulings.size());
}

TEST(RimLoadRule, TheCylindersDynamicRuleIsItsStaticRule)
{
  const Loop cylinder = roll("cylinder", 64);
  for (const study::rims::RulingLoad& load :
       study::rims::ruling_loads(cylinder.run, contact::LoadRule::dynamic, force_n, 9.81))
    EXPECT_NEAR(load.force_n / force_n, 1, 1e-6);
  expect_same_samples(by_rule(cylinder, contact::LoadRule::dynamic),
                      by_rule(cylinder, contact::LoadRule::static_through_centre_of_mass));
}

TEST(RimLoadRule, TheOloidsDynamicForceAveragesToTheLoadOverItsLoop)
{
  const Loop oloid = roll("oloid", 512);
  const std::vector<study::rims::RulingLoad> loads
      = study::rims::ruling_loads(oloid.run, contact::LoadRule::dynamic, force_n, 9.81);
  ASSERT_EQ(loads.size(), oloid.source.times_s.size());
  // The time average by the trapezoid rule over the samples.
  double integral = 0, lowest = force_n, highest = force_n;
  for (std::size_t j = 0; j + 1 < loads.size(); ++j)
    integral += 0.5 * (loads[j].force_n + loads[j + 1].force_n) * (oloid.source.times_s[j + 1] - oloid.source.times_s[j]);
  for (const auto& l : loads)
    lowest = std::min(lowest, l.force_n), highest = std::max(highest, l.force_n);
  const double mean = integral / (oloid.source.times_s.back() - oloid.source.times_s.front());
  EXPECT_NEAR(mean / force_n, 1, 1e-3);
  // The motion's own load does vary, by far more than its mean misses F.
  EXPECT_GT(highest - lowest, 10 * std::abs(mean - force_n));
  EXPECT_LT(lowest, 0.995 * force_n);
}
