// The normalised uniformity score of real rolling converges under mesh
// refinement, towards its continuum value computed without any mesh.
#include "geometry/body.h"
#include "oracle/rolling_study.h"
#include <cmath>
#include <gtest/gtest.h>
#include <numbers>

using namespace rollcheck;
using namespace rollcheck::oracle;

namespace
{
/// Three levels: points per circle (cylinder sides / 4) doubled and the faces
/// cut into 4, 8, 16 parts per edge (the hull faces of the rollers run the whole
/// ruling, so only the cut resolves the density along it).
std::vector<RollingStudyResult> refine(geometry::BodySpec spec, const RealRolling& run, RollingStudyParameters p)
{
  std::vector<RollingStudyResult> levels;
  for (int level = 0; level < 3; ++level)
  {
    spec.points = 64 << level;
    spec.sections = 16 << level;
    p.face_subdivisions = 4 << level;
    levels.push_back(score_real_rolling(run, geometry::make_body(spec), p));
  }
  return levels;
}

void expect_converges(const char* name, const geometry::BodySpec& spec)
{
  const RollingStudyParameters p; // Hertz contact width, one loop, undamped
  const RealRolling run = real_rolling(spec, p);
  ASSERT_TRUE(run.trajectory.contact_held) << name;
  ASSERT_EQ(run.loops_completed, 1.0) << name;
  const auto levels = refine(spec, run, p);
  std::printf("%-12s", name);
  for (const auto& l : levels)
    std::printf(" | %7ld faces U = %.5f", l.faces, l.uniformity);
  const double last_change = std::abs(levels[2].uniformity - levels[1].uniformity) / levels[2].uniformity;
  std::printf(" | last change %.2f %% | continuum %.5f | coverage %.3f\n", 100 * last_change,
              levels[2].continuum_uniformity, levels[2].coverage);
  EXPECT_LT(levels[0].uniformity, levels[1].uniformity) << name << ": monotone";
  EXPECT_LT(levels[1].uniformity, levels[2].uniformity) << name << ": monotone";
  EXPECT_LT(last_change, 0.05) << name;
  // Towards the value of the exact density, which needs no mesh.
  EXPECT_NEAR(levels[2].uniformity, levels[2].continuum_uniformity, 0.02 * levels[2].continuum_uniformity) << name;
}

/// The same for a named body at its defaults.
void expect_converges(const char* body)
{
  geometry::BodySpec spec;
  spec.body = body;
  expect_converges(body, spec);
}
} // namespace

TEST(UniformityConvergence, TrueOloid)
{
  expect_converges("oloid");
}

TEST(UniformityConvergence, Cylinder)
{
  expect_converges("cylinder");
}

TEST(UniformityConvergence, PaperOloidRoller)
{
  expect_converges("paper-oloid");
}

TEST(UniformityConvergence, PreprintCandidateTwo)
{
  geometry::BodySpec spec;
  spec.body = "roller";
  spec.family = geometry::RollerFamily::paper;
  spec.genome = {120, 1.3, 0.8, 2};
  expect_converges("(120,1.3,0.8)", spec);
}

TEST(UniformityConvergence, CylinderSideIsUniformSoUIsTheAreaRatio)
{
  // Only the side is touched, uniformly: U = A_caps / A_side, which for the
  // N-sided prism of radius r and height 2 r is cos(pi / N) / 2 (1/2 in the limit).
  geometry::BodySpec spec;
  spec.body = "cylinder";
  RollingStudyParameters p;
  const RealRolling run = real_rolling(spec, p);
  for (const auto model : {ContactWidthModel::hertz, ContactWidthModel::rigid})
  {
    p.contact_width.model = model;
    for (int sections : {12, 60})
    {
      spec.sections = sections;
      const RollingStudyResult r = score_real_rolling(run, geometry::make_body(spec), p);
      EXPECT_NEAR(r.uniformity, std::cos(std::numbers::pi / sections) / 2, 1e-6);
      EXPECT_NEAR(r.continuum_uniformity, 0.5, 1e-5);
    }
  }
}

TEST(UniformityConvergence, RigidWidthConvergesSlowlyOnTheOloid)
{
  // Without a contact width the density grows like 1/R where a ruling end
  // pivots on a rim: the mesh score still rises towards U_inf, but slowly.
  geometry::BodySpec spec;
  spec.body = "oloid";
  RollingStudyParameters p;
  p.contact_width.model = ContactWidthModel::rigid;
  const RealRolling run = real_rolling(spec, p);
  const auto levels = refine(spec, run, p);
  std::printf("oloid, rigid width: U = %.3f, %.3f, %.3f; continuum %.3f\n", levels[0].uniformity,
              levels[1].uniformity, levels[2].uniformity, levels[2].continuum_uniformity);
  EXPECT_LT(levels[0].uniformity, levels[1].uniformity);
  EXPECT_LT(levels[1].uniformity, levels[2].uniformity);
  EXPECT_LT(levels[2].uniformity, levels[2].continuum_uniformity);
}
