// Where the rim loop's two tables meet (study/rims/rim_loop.h,
// study/rims/end_ratios.h): the FEM end table is indexed by an end's
// dihedral angle (normal to its rim), the flat-rim table by its section
// angle (in the ruling's vertical plane). An end below the seam's section
// angle reads the end table at its dihedral angle, one above it the flat-rim
// table at its section; the seam itself (RimLoopResult::flat_rim_seam) reads
// the end table at the first flat-rim node's dihedral angle, not at its
// section angle. Under a load rule other than the static one the flat-rim
// table's peak is at another load than the end's: its ratio to its own line
// Hertz is taken instead.
#include "study/rims/rim_loop.h"
#include <gtest/gtest.h>
#include <numbers>

using namespace rollcheck;

namespace
{
constexpr double degree = std::numbers::pi / 180;

/// An end table whose ratio is the dihedral angle in degrees / 100, one column.
std::vector<study::rims::EndTableNode> angle_table()
{
  std::vector<study::rims::EndTableNode> table;
  for (const double angle : {100.0, 120.0, 140.0, 160.0})
  {
    study::rims::EndTableNode n;
    n.dihedral_angle_rad = angle * degree;
    n.sheet_radius_m = 0.01;
    n.study.end_to_interior = angle / 100;
    table.push_back(n);
  }
  return table;
}

/// A flat-rim node at section angle `section_deg`, dihedral `dihedral_deg`:
/// peak 3 GPa over its line Hertz 2 GPa (ratio 1.5), at R = 0.01 m.
study::rims::FlatRimNode flat_node(double section_deg, double dihedral_deg)
{
  study::rims::FlatRimNode n;
  n.section_angle_rad = section_deg * degree;
  n.dihedral_angle_rad = dihedral_deg * degree;
  n.sides = {{0.3, 1e5, 0.01, 3e9, 2e9, 0, 0, true, 1}};
  return n;
}

study::loop_scores::LoadedEnd end_at(double section_deg, double dihedral_deg, double line_hertz_pa)
{
  study::loop_scores::LoadedEnd end;
  end.interior_angle_rad = section_deg * degree;
  end.dihedral_angle_rad = dihedral_deg * degree;
  end.line_hertz_pa = line_hertz_pa;
  end.radius_m = 0.01;
  return end;
}
} // namespace

TEST(RimSeam, TheSeamReadsTheEndTableAtTheFirstFlatRimNodesDihedralAngle)
{
  study::rims::RimLoopResult r;
  r.end_setup.edge_radius_m = 4e-4; // rounded: the end model takes dihedral angles up to 170 deg
  r.singular_from_rad = std::numbers::pi;
  r.table = angle_table();
  r.flat_from_rad = 160 * degree;
  r.flat_table = {flat_node(160, 126), flat_node(170, 140)};
  EXPECT_NEAR(r.flat_rim_seam_dihedral(), 126 * degree, 1e-12);
  const auto seam = r.flat_rim_seam();
  ASSERT_TRUE(seam.has_value());
  EXPECT_NEAR(seam->dihedral_angle_rad, 126 * degree, 1e-12);
  EXPECT_NEAR(seam->end_table_ratio, 1.26, 1e-12); // at the section angle it would read 1.60
  EXPECT_NEAR(seam->flat_rim_ratio, 1.5, 1e-12);
  // A seam dihedral outside the end model's range is held to it.
  r.flat_table.front().dihedral_angle_rad = 175 * degree;
  EXPECT_NEAR(r.flat_rim_seam_dihedral(), 170 * degree, 1e-12);
}

TEST(RimSeam, EndsOnEitherSideOfTheSeamReadTheirOwnTableAtTheirOwnAngle)
{
  study::rims::EndRatios ratios;
  ratios.table = angle_table();
  ratios.largest_modelled_rad = 170 * degree;
  ratios.flat_from_rad = 160 * degree;
  ratios.flat_table = {flat_node(160, 126), flat_node(170, 140)};
  // Just below the seam's section angle: the end table at the end's dihedral angle.
  EXPECT_NEAR(*ratios(1, end_at(159.9, 110, 1e9)), 1.10, 1e-12);
  // At and above it: the flat-rim table at the section angle, its peak over
  // the end's own line Hertz (the static rule: the table's load is the end's).
  EXPECT_NEAR(*ratios(1, end_at(160, 110, 1e9)), 3.0, 1e-12);
  EXPECT_NEAR(*ratios(1, end_at(165, 110, 1.5e9)), 2.0, 1e-12);
  // Under another load rule: the table's own ratio, whatever the end's line Hertz.
  ratios.flat_rim_own_load = false;
  EXPECT_NEAR(*ratios(1, end_at(165, 110, 1.5e9)), 1.5, 1e-12);
  EXPECT_NEAR(*ratios(1, end_at(159.9, 110, 1.5e9)), 1.10, 1e-12);
}
