// The rounded rim ends in the life integrals (study/life): the end table's
// interpolation and its file's errors, and the edge radius from which the
// interior governs, interpolated in ln(r_e). The cylinder's end integral is
// checked with its loop integral (test_life_model.cpp).
#include "core/error.h"
#include "study/life/rim_life.h"
#include "study/life/rounded_end_ratios.h"
#include <cmath>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>

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
