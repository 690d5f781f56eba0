// The rounded rim ends in the life integrals (study/life): the end table's
// interpolation and its file's errors, the cylinder's end integral over one
// loop against its closed form (two ends per ruling, every ruling at F / L on
// R = r), and the edge radius from which the interior governs, interpolated
// in ln(r_e).
#include "contact/hertz.h"
#include "core/error.h"
#include "oracle/rolling_study.h"
#include "study/life/rim_life.h"
#include "study/life/rounded_end_ratios.h"
#include <cmath>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <numbers>

using namespace rollcheck;
using namespace rollcheck::study::life;

namespace
{
RoundedEndRatios table()
{
  return {{1, 4, 16}, {1.5, 2, 3}, 87.5, "hand-made"};
}

std::filesystem::path write(const std::string& name, const std::string& text)
{
  const auto path = std::filesystem::temp_directory_path() / name;
  std::ofstream(path) << text;
  return path;
}
} // namespace

TEST(LifeRims, EndTableIsLinearInLogRAndHeldAtItsEnds)
{
  const RoundedEndRatios t = table();
  EXPECT_DOUBLE_EQ(t(0.5), 1.5);
  EXPECT_DOUBLE_EQ(t(1), 1.5);
  EXPECT_NEAR(t(2), 1.75, 1e-12); // halfway in ln between 1 and 4
  EXPECT_NEAR(t(8), 2.5, 1e-12);
  EXPECT_DOUBLE_EQ(t(100), 3);
  EXPECT_TRUE(t.covers(16));
  EXPECT_FALSE(t.covers(16.01));
}

TEST(LifeRims, TheShippedTableAndBadFilesAreRead)
{
  const RoundedEndRatios shipped = read_rounded_end_ratios(default_rounded_end_ratios_path());
  EXPECT_GE(shipped.r_over_edge_radius.size(), 2u);
  EXPECT_FALSE(shipped.source.empty());
  const auto no_key = write("life_no_key.json", R"({"r_over_edge_radius": [1, 2], "interior_angle_deg": 90, "source": "x"})");
  try
  {
    read_rounded_end_ratios(no_key);
    FAIL() << "no error";
  }
  catch (const InputError& e)
  {
    EXPECT_NE(std::string(e.what()).find("end_over_line_hertz"), std::string::npos) << e.what();
  }
  const auto descending = write("life_descending.json", R"({"r_over_edge_radius": [2, 1], "end_over_line_hertz": [1, 2],
    "interior_angle_deg": 90, "source": "x"})");
  EXPECT_THROW(read_rounded_end_ratios(descending), InputError);
  EXPECT_THROW(read_rounded_end_ratios("/nonexistent/table.json"), InputError);
}

TEST(LifeRims, CylinderEndIntegralMatchesItsClosedForm)
{
  geometry::BodySpec spec;
  spec.body = "cylinder";
  oracle::RollingStudyParameters p;
  p.samples_per_loop = 400;
  const oracle::RealRolling run = oracle::real_rolling(spec, p);
  const LifeConstants k;
  const DepthIntegrals orthogonal(contact::FatigueCriterion::orthogonal_shear, k);
  const DepthIntegrals largest(contact::FatigueCriterion::largest_shear, k);
  LoopLifeSettings s;
  s.normal_load_n = 5000;
  s.load_rule = contact::LoadRule::uniform;
  const RoundedEndRatios t = table();
  for (const double re : {0.05, 0.5, 2.0}) // R / r_e = 20 (held), 2, and r_e above R
  {
    const RoundedEnds ends{re, &t, 1.5};
    const LoopIntegrals li = loop_integrals(run, s, k, {&orthogonal, &largest}, {1.0, 1.0}, largest, &ends);
    // Each of the loop's rulings has two loaded ends at q = F / L on R = max(1 m, r_e): over one loop (2 pi
    // of sigma) each sweeps 2 pi R, on a patch 1.5 b long.
    const double r = std::max(1.0, re);
    const contact::LineHertz h = contact::line_contact(s.normal_load_n / 2, r, s.effective_modulus_pa, 0.3);
    const double expected = 2 * 2 * std::numbers::pi * r * 1.5 * h.half_width_m
                            * std::pow(t(1 / re) * h.peak_pressure_pa, k.stress_exponent)
                            * std::pow(h.half_width_m, 1 - k.depth_exponent) * orthogonal.integral(0, k.stress_exponent);
    EXPECT_NEAR(li.end_lundberg_palmgren[0] / expected, 1, 1e-3) << "r_e = " << re;
    EXPECT_EQ(li.ends_outside_table > 0, re == 0.05);
  }
}

TEST(LifeRims, InteriorGovernsFromWhereTheEndsIntegralCrossesTheInteriors)
{
  // end / interior 4 at r_e 0.01, 1/4 at 0.04: the crossing halfway in ln, at 0.02.
  std::vector<RimLifeRow> rows = {{0.01, 1, 4, 0, 0, 0, std::nullopt}, {0.04, 1, 0.25, 0, 0, 0, std::nullopt}};
  ASSERT_TRUE(interior_governs_from(rows));
  EXPECT_NEAR(*interior_governs_from(rows), 0.02, 1e-12);
  rows[1].end_integral = 2;
  EXPECT_FALSE(interior_governs_from(rows));
  rows[0].end_integral = 0.5;
  EXPECT_DOUBLE_EQ(*interior_governs_from(rows), 0.01);
}
