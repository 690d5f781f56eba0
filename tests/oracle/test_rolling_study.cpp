// Real rolling of the preprint's bodies, scored by the normalised uniformity
// score: the table of the README's "corrected physics" section.
#include "geometry/body.h"
#include "core/error.h"
#include "oracle/rolling_study.h"
#include <cmath>
#include <limits>
#include <string>
#include <gtest/gtest.h>

using namespace rollcheck;
using namespace rollcheck::oracle;

namespace
{
geometry::BodySpec paper_roller(double theta, double offset, double ratio)
{
  geometry::BodySpec spec;
  spec.body = "roller";
  spec.family = geometry::RollerFamily::paper;
  spec.genome = {theta, offset, ratio, 2};
  return spec;
}

RollingStudyResult study(const char* name, geometry::BodySpec spec, ContactWidthModel model)
{
  RollingStudyParameters p;
  p.contact_width.model = model;
  p.face_subdivisions = 8;
  const RollingStudyResult r = rolling_study(spec, p);
  std::printf("| %-16s | %-5s | %6.3f | %6.3f | %6.3f | %5.3f | %-3s | %5.2f | %6.3f | %5.3f..%5.3f | %5.3f | %7ld |\n", name,
              model == ContactWidthModel::hertz ? "hertz" : "rigid", r.uniformity, r.continuum_uniformity,
              r.coverage, r.initial_rate_rad_s, r.contact_held ? "yes" : "no", r.loops_completed, r.scored_time_s,
              r.centre_of_pressure_min, r.centre_of_pressure_max, r.friction_ratio_max, r.faces);
  EXPECT_LT(r.max_energy_error, 1e-9) << name;
  return r;
}
} // namespace

TEST(RollingStudy, PreprintBodiesUnderRealRolling)
{
  std::printf("| body | width | U (mesh) | U (continuum) | coverage | rate0 rad/s | held | loops | window s | "
              "centre of pressure | friction | faces |\n");
  geometry::BodySpec oloid, paper_oloid, cylinder;
  oloid.body = "oloid";
  paper_oloid.body = "paper-oloid";
  cylinder.body = "cylinder";
  for (const auto model : {ContactWidthModel::hertz, ContactWidthModel::rigid})
  {
    const RollingStudyResult o = study("oloid", oloid, model);
    const RollingStudyResult c = study("cylinder", cylinder, model);
    const RollingStudyResult p = study("paper-oloid", paper_oloid, model);
    const RollingStudyResult c2 = study("(120,1.30,0.80)", paper_roller(120, 1.3, 0.8), model);
    const RollingStudyResult c3 = study("(90,0.70,0.80)", paper_roller(90, 0.7, 0.8), model);
    const RollingStudyResult c1 = study("(120,0.70,0.80)", paper_roller(120, 0.7, 0.8), model);
    // The true oloid and the cylinder roll whole loops on their rulings.
    EXPECT_TRUE(o.contact_held && c.contact_held && p.contact_held && c2.contact_held);
    EXPECT_EQ(o.loops_completed, 1.0);
    // The cylinder touches its side only, uniformly: U -> A_caps / A_side = 1/2.
    EXPECT_NEAR(c.uniformity, 0.5, 0.01);
    // The preprint's candidates #1 and #3 cannot roll over their potential
    // barrier on the ruled surface without lifting a rim at this energy.
    EXPECT_FALSE(c1.contact_held);
    EXPECT_FALSE(c3.contact_held);
    if (model == ContactWidthModel::rigid)
      EXPECT_NEAR(o.coverage, 1.0, 1e-9) << "the rulings sweep the whole oloid";
  }
}

TEST(RollingStudy, FasterRollingSpreadsTheOloidsContact)
{
  // U of one loop against the initial energy: the slower the body crosses its
  // potential barriers, the longer it dwells on the rulings there. The oloid
  // keeps its ruling up to (1 + 3) dV; the preprint's rollers lift a rim sooner.
  std::printf("| body | energy excess | rate0 rad/s | held | loops | U (continuum) | centre of pressure |\n");
  geometry::BodySpec oloid, paper_oloid;
  oloid.body = "oloid";
  paper_oloid.body = "paper-oloid";
  double previous = std::numeric_limits<double>::infinity();
  for (const auto& [name, spec] :
       {std::pair{"oloid", oloid}, std::pair{"paper-oloid", paper_oloid}, std::pair{"(120,1.30,0.80)", paper_roller(120, 1.3, 0.8)}})
    for (double excess : {0.02, 0.1, 0.5, 1.0, 3.0})
    {
      RollingStudyParameters p;
      p.rolling_energy = excess;
      const RealRolling run = real_rolling(spec, p);
      const RollingStudyResult r = score_real_rolling(run, geometry::make_body(spec), p);
      std::printf("| %-16s | %4.2f | %5.3f | %-3s | %4.2f | %6.3f | %5.3f..%5.3f |\n", name, excess,
                  r.initial_rate_rad_s, r.contact_held ? "yes" : "no", r.loops_completed, r.continuum_uniformity,
                  r.centre_of_pressure_min, r.centre_of_pressure_max);
      if (std::string(name) == "oloid")
      {
        ASSERT_TRUE(r.contact_held) << excess;
        EXPECT_LT(r.continuum_uniformity, previous) << excess;
        previous = r.continuum_uniformity;
      }
    }
  EXPECT_LT(previous, 0.1) << "fast rolling spreads the oloid's contact almost evenly";
}

TEST(RollingStudy, SphereTrackDoesNotConvergeUnderRefinement)
{
  // Point contact: the contact measure lives on the track, so U grows like the
  // number of faces across it (about x2 per subdivision level of the icosphere).
  geometry::BodySpec sphere;
  sphere.body = "sphere";
  double previous = 0;
  for (int subdivisions : {2, 3, 4})
  {
    sphere.subdivisions = subdivisions;
    const RollingStudyResult r = rolling_study(sphere, {});
    EXPECT_EQ(r.contact, "point");
    EXPECT_TRUE(std::isnan(r.continuum_uniformity));
    EXPECT_GT(r.uniformity, 1.7 * previous);
    previous = r.uniformity;
  }
}

TEST(RollingStudy, RejectsBodiesAndParametersItDoesNotModel)
{
  geometry::BodySpec spec;
  spec.body = "hemisphere";
  EXPECT_THROW(rolling_study(spec, {}), InputError);
  spec = paper_roller(90, 1, 1);
  spec.genome.n_circles = 3;
  EXPECT_THROW(rolling_study(spec, {}), InputError);
  spec.body = "oloid";
  RollingStudyParameters p;
  p.loops = 0;
  EXPECT_THROW(rolling_study(spec, p), InputError);
  p = {};
  p.rolling_resistance_n_m_s = 0.02; // the loop period is then unknown: a duration is needed
  EXPECT_THROW(rolling_study(spec, p), InputError);
  p.duration_s = 10;
  const RollingStudyResult damped = rolling_study(spec, p);
  EXPECT_TRUE(damped.contact_held);
  EXPECT_LT(damped.max_energy_error, 1e-9);
}
