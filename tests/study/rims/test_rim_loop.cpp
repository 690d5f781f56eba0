// The rim loop's own arithmetic (study/rims/rim_loop.h): where a sharp edge turns
// singular against each counter-face, and the end table's interpolation. The
// FEM behind them is tested in test_rim_end_contact and tests/cli/rim.sh.
#include "contact/edge_on_elastic_block_exponent.h"
#include "contact/hertz.h"
#include "contact/wedge_exponent.h"
#include "core/error.h"
#include "study/rims/rim_loop.h"
#include <gtest/gtest.h>
#include <numbers>

using namespace rollcheck;

namespace
{
constexpr double degree = std::numbers::pi / 180;

study::rims::EndTableNode node(double angle_deg, std::optional<double> end_to_interior, double sheet_radius_m = 0.01)
{
  study::rims::EndTableNode n;
  n.dihedral_angle_rad = angle_deg * degree;
  n.sheet_radius_m = sheet_radius_m;
  n.study.end_to_interior = end_to_interior;
  return n;
}

/// A loaded end at `angle_deg` (its section and its dihedral angle: a rim
/// square to the ruling) with line Hertz's peak `line_hertz_pa` and R.
study::loop_scores::LoadedEnd loaded_end(double angle_deg, double line_hertz_pa, double radius_m = 0.01)
{
  study::loop_scores::LoadedEnd end;
  end.interior_angle_rad = end.dihedral_angle_rad = angle_deg * degree;
  end.line_hertz_pa = line_hertz_pa;
  end.radius_m = radius_m;
  return end;
}
} // namespace

TEST(RimLoop, SharpEdgeOnTheRigidPlaneTurnsSingularAtTheSquareEnd)
{
  fem::RimEndSettings end;
  const double from = study::rims::singular_from_angle(end);
  // Williams: the mirrored wedge 2a is singular beyond 180 deg.
  EXPECT_NEAR(from / degree, 90.0, 1e-3);
  EXPECT_LT(contact::edge_on_rigid_plane_exponent(from + 0.01 * degree), 0);
  EXPECT_GE(contact::edge_on_rigid_plane_exponent(from - 0.01 * degree), 0);
}

TEST(RimLoop, SharpEdgeOnSteelTurnsSingularBelowTheSquareEnd)
{
  fem::RimEndSettings end;
  end.counter_face = fem::CounterFace::block;
  const double from = study::rims::singular_from_angle(end);
  // docs/methods/rims.md: for steel on steel from 77.45 deg (the square end: -0.226).
  EXPECT_NEAR(from / degree, 77.45, 0.01);
  const double E = end.youngs_modulus_pa, nu = end.poisson_ratio;
  EXPECT_LT(contact::edge_on_elastic_block_exponent(from + 0.01 * degree, E, nu, E, nu), 0);
  EXPECT_GE(contact::edge_on_elastic_block_exponent(from - 0.01 * degree, E, nu, E, nu), 0);
}

TEST(RimLoop, RoundedEdgeIsNeverSingular)
{
  fem::RimEndSettings end;
  end.edge_radius_m = 1e-4;
  EXPECT_EQ(study::rims::singular_from_angle(end), std::numbers::pi);
}

TEST(RimLoop, EndTableInterpolatesLinearlyAndHoldsItsEnds)
{
  // A ratio linear in the angle, 0.2 + 0.01 (a - 90 deg): interpolation is exact.
  const std::vector<study::rims::EndTableNode> table
      = {node(90, 0.2), node(100, 0.3), node(110, 0.4), node(120, 0.5), node(130, 0.6)};
  const double singular_from = std::numbers::pi;
  EXPECT_NEAR(*study::rims::end_table_ratio(table, 1, singular_from, 105 * degree, 1.0), 0.35, 1e-12);
  EXPECT_NEAR(*study::rims::end_table_ratio(table, 2, singular_from, 105 * degree, 1.0), 0.35, 1e-12);
  EXPECT_NEAR(*study::rims::end_table_ratio(table, 1, singular_from, 80 * degree, 1.0), 0.2, 1e-12);
  EXPECT_NEAR(*study::rims::end_table_ratio(table, 1, singular_from, 140 * degree, 1.0), 0.6, 1e-12);
}

TEST(RimLoop, EveryOtherNodeSeesOnlyItsOwnNodes)
{
  // A kink at 100 deg that the table of every other node (90, 110) cannot see.
  const std::vector<study::rims::EndTableNode> table = {node(90, 0.2), node(100, 1.0), node(110, 0.2)};
  EXPECT_NEAR(*study::rims::end_table_ratio(table, 1, std::numbers::pi, 100 * degree, 1.0), 1.0, 1e-12);
  EXPECT_NEAR(*study::rims::end_table_ratio(table, 2, std::numbers::pi, 100 * degree, 1.0), 0.2, 1e-12);
}

TEST(RimLoop, EndTableAnglesAreDenserBelowTheSquareEndWhenAsked)
{
  auto degrees = [](const std::vector<double>& angles) {
    std::vector<double> d;
    for (const double a : angles)
      d.push_back(std::round(a / degree * 1e6) / 1e6);
    return d;
  };
  // The preprint's body's range, 60 to 170 deg: even at 45 deg, 27.5 apart.
  EXPECT_EQ(degrees(study::rims::end_table_angles(60 * degree, 170 * degree, 45 * degree, 0)),
            (std::vector<double>{60, 87.5, 115, 142.5, 170}));
  // 15 deg below the square end, 45 above: 60, 75, 90 and 90, 130, 170, so
  // every other node (60, 90, 170) is the table of twice the steps.
  const std::vector<double> split = degrees(study::rims::end_table_angles(60 * degree, 170 * degree, 45 * degree, 15 * degree));
  EXPECT_EQ(split, (std::vector<double>{60, 75, 90, 130, 170}));
  // A range wholly on one side of 90 deg takes that side's step.
  EXPECT_EQ(degrees(study::rims::end_table_angles(60 * degree, 90 * degree, 45 * degree, 10 * degree)),
            (std::vector<double>{60, 67.5, 75, 82.5, 90}));
  EXPECT_EQ(degrees(study::rims::end_table_angles(100 * degree, 170 * degree, 45 * degree, 10 * degree)),
            (std::vector<double>{100, 135, 170}));
  EXPECT_EQ(degrees(study::rims::end_table_angles(75 * degree, 75 * degree, 45 * degree, 10 * degree)),
            (std::vector<double>{75}));
}

TEST(RimLoop, AboveTheSingularAngleThereIsNoRatio)
{
  const std::vector<study::rims::EndTableNode> table = {node(80, 0.1), node(90, 0.27)};
  EXPECT_FALSE(study::rims::end_table_ratio(table, 1, 90 * degree, 90.5 * degree, 1.0).has_value());
  EXPECT_TRUE(study::rims::end_table_ratio(table, 1, 90 * degree, 90 * degree, 1.0).has_value());
}

// A rounded edge's columns over the sheet's R: a ratio linear in the angle
// and in log R, 2 + 0.01 (a - 90 deg) + 0.5 ln(R / 4 mm), is interpolated
// exactly between them and held beyond them.
TEST(RimLoop, EndTableInterpolatesAcrossItsColumnsInLogRadius)
{
  auto ratio = [](double angle_deg, double radius_mm) { return 2 + 0.01 * (angle_deg - 90) + 0.5 * std::log(radius_mm / 4); };
  std::vector<study::rims::EndTableNode> table;
  for (const double radius_mm : {4.0, 8.0, 16.0})
    for (const double angle : {80.0, 100.0, 120.0})
      table.push_back(node(angle, ratio(angle, radius_mm), radius_mm * 1e-3));
  const double open = std::numbers::pi;
  EXPECT_NEAR(*study::rims::end_table_ratio(table, 1, open, 110 * degree, 6e-3), ratio(110, 6.0), 1e-12);
  EXPECT_NEAR(*study::rims::end_table_ratio(table, 1, open, 85 * degree, 12e-3), ratio(85, 12.0), 1e-12);
  // Every other column (4 and 16 mm) and angle (80 and 120 deg): still exact for this ratio.
  EXPECT_NEAR(*study::rims::end_table_ratio(table, 2, open, 110 * degree, 6e-3), ratio(110, 6.0), 1e-12);
  // Held at the table's edges in both directions.
  EXPECT_NEAR(*study::rims::end_table_ratio(table, 1, open, 110 * degree, 2e-3), ratio(110, 4.0), 1e-12);
  EXPECT_NEAR(*study::rims::end_table_ratio(table, 1, open, 130 * degree, 32e-3), ratio(120, 16.0), 1e-12);
  // Columns need an R to interpolate at.
  EXPECT_THROW(study::rims::end_table_ratio(table, 1, open, 110 * degree, 0.0), ComputationError);
}

TEST(RimLoop, EveryOtherColumnSeesOnlyItsOwnColumns)
{
  // The middle column (R = 8 mm) differs; every other column skips it.
  std::vector<study::rims::EndTableNode> table;
  for (const auto& [radius_mm, value] : {std::pair{4.0, 2.0}, {8.0, 3.0}, {16.0, 2.0}})
    for (const double angle : {80.0, 120.0})
      table.push_back(node(angle, value, radius_mm * 1e-3));
  EXPECT_NEAR(*study::rims::end_table_ratio(table, 1, std::numbers::pi, 100 * degree, 8e-3), 3.0, 1e-12);
  EXPECT_NEAR(*study::rims::end_table_ratio(table, 2, std::numbers::pi, 100 * degree, 8e-3), 2.0, 1e-12);
}

// A loaded end reads the column of its own R (as finished_end has it).
TEST(RimLoop, EndRatiosReadTheColumnOfTheEndsOwnRadius)
{
  study::rims::EndRatios ratios;
  ratios.largest_modelled_rad = 170 * degree;
  for (const auto& [radius_mm, value] : {std::pair{2.0, 3.0}, {4.0, 2.5}, {8.0, 2.0}})
    for (const double angle : {80.0, 120.0})
      ratios.table.push_back(node(angle, value, radius_mm * 1e-3));
  EXPECT_NEAR(*ratios(1, loaded_end(100, 1e9, 4e-3)), 2.5, 1e-12);
  EXPECT_NEAR(*ratios(1, loaded_end(100, 1e9, 4e-3 * std::sqrt(2.0))), 2.25, 1e-12); // halfway in log R
  // A part finished with r_e = 4 mm takes an end of R = 1 mm at R = r_e.
  study::loop_scores::LoadedEnd sharper = loaded_end(100, 1e9, 1e-3);
  sharper.load_ratio = 1e-4;
  const study::loop_scores::LoadedEnd finished = study::loop_scores::finished_end(sharper, 4e-3);
  EXPECT_EQ(finished.radius_m, 4e-3);
  EXPECT_NEAR(finished.line_hertz_pa, 0.5e9, 1e-3);
  EXPECT_NEAR(finished.load_ratio, 0.25e-4, 1e-18);
  EXPECT_NEAR(*ratios(1, finished), 2.5, 1e-12);
}

// An oblique rim's end: the end table is read at its dihedral angle, normal
// to the rim, and singular by it; the flat-rim table at its section (its
// nodes are the loop's own ends, whatever their angles).
TEST(RimLoop, EndRatiosReadTheEndTableAtTheDihedralAngle)
{
  study::rims::EndRatios ratios;
  ratios.table = {node(60, 1.0), node(80, 1.2), node(120, 2.0), node(160, 2.4)};
  ratios.largest_modelled_rad = 170 * degree;
  study::loop_scores::LoadedEnd oblique = loaded_end(148.5, 1e9);
  oblique.dihedral_angle_rad = 129 * degree;
  EXPECT_NEAR(*ratios(1, oblique), 2.0 + 0.4 * 9 / 40, 1e-12); // not 2.0 + 0.4 * 28.5 / 40
  // A sharp edge on steel is singular from 77.45 deg: an end of section
  // 80 deg but dihedral 76 deg is not.
  ratios.singular_from_rad = 77.45 * degree;
  study::loop_scores::LoadedEnd acute = loaded_end(80, 1e9);
  acute.dihedral_angle_rad = 76 * degree;
  EXPECT_NEAR(*ratios(1, acute), 1.0 + 0.2 * 16 / 20, 1e-12);
  acute.dihedral_angle_rad = 78 * degree;
  EXPECT_FALSE(ratios(1, acute).has_value());
  // From flat_from_rad on, by the section: the flat-rim table's single node.
  study::rims::FlatRimNode flat;
  flat.section_angle_rad = 160 * degree;
  flat.sides = {{0.3, 1e5, 1e-3, 3e9, 2e9, 0, 0, true, 1}};
  ratios.flat_table = {flat};
  ratios.flat_from_rad = 160 * degree;
  ratios.singular_from_rad = std::numbers::pi;
  study::loop_scores::LoadedEnd flattish = loaded_end(165, 1e9);
  flattish.dihedral_angle_rad = 150 * degree;
  EXPECT_NEAR(*ratios(1, flattish), 3.0, 1e-12);
}

TEST(RimLoop, ANodeWithoutARatioIsAnError)
{
  const std::vector<study::rims::EndTableNode> table = {node(90, 0.2), node(100, std::nullopt)};
  EXPECT_THROW(study::rims::end_table_ratio(table, 1, std::numbers::pi, 99 * degree, 1.0), ComputationError);
}

// On a steel block the loop's slices meet the block too: the pair's E*
// (half the rigid plane's for identical bodies, Johnson 1985 eq. 4.22), so
// that its pressures and its ends' b / R are the pair's. The cylinder's
// square ends are then all singular (the elastic wedge's -0.226).
TEST(RimLoop, SteelBlockGivesTheLoopThePairsModulus)
{
  study::rims::RimLoopSettings s;
  s.loop.body.body = "cylinder";
  s.loop.samples_per_loop = 512;
  s.loop.orientations = 1;
  s.loop.fem_slices = 2;
  s.end.counter_face = fem::CounterFace::block;
  s.end.levels = 1;
  ASSERT_FALSE(s.loop.elastic_plane);
  const study::rims::RimLoopResult r = study::rims::run_rim_loop(MPI_COMM_WORLD, s);
  const double rigid = contact::effective_modulus(s.loop.youngs_modulus_pa, s.loop.poisson_ratio, false);
  const double pair = contact::effective_modulus(s.loop.youngs_modulus_pa, s.loop.poisson_ratio, true);
  EXPECT_NEAR(pair / rigid, 0.5, 1e-12);
  EXPECT_NEAR(r.fem_sds.effective_modulus_pa / pair, 1.0, 1e-12);
  ASSERT_FALSE(r.ends.empty());
  for (const study::rims::RimLoopEnd& e : r.ends)
    EXPECT_NEAR(e.study.effective_modulus_pa / pair, 1.0, 1e-12);
  ASSERT_EQ(r.loop.end_aware.size(), 1u);
  EXPECT_EQ(r.loop.end_aware[0].singular_ends, r.loop.loaded_ends);
}

// Refused flat-rim nodes (slopes above 0.1, a failed solve) cost only the
// nodes up to the last of them: the table starts after it, one node later
// where that keeps an odd count, so every other node still ends on the
// flattest; a refused flattest node refuses it all.
TEST(RimLoop, FlatRimTableStartsAfterItsLastRefusedNode)
{
  const auto start = [](std::vector<bool> refused) { return study::rims::flat_rim_table_start(refused); };
  EXPECT_EQ(start({false, false, false, false, false}), 0u);
  EXPECT_EQ(start({true, false, false, false, false}), 2u);  // 3 nodes kept, not 4
  EXPECT_EQ(start({true, true, false, false, false}), 2u);   // 3 kept
  EXPECT_EQ(start({false, true, false, false, false}), 2u);  // a refused node inside: after it
  EXPECT_EQ(start({true, false, true, false, false}), 4u);   // 1 kept: the flattest alone
  EXPECT_EQ(start({true, false, false}), 2u);
  EXPECT_EQ(start({false, false, true}), std::nullopt);      // the flattest refused
  EXPECT_EQ(start({true}), std::nullopt);
  EXPECT_EQ(start({false}), 0u);
}

// A rounded edge's flattest ends take the flat-rim table (the loop's own
// ends by half-space theory) from its first angle on: its peak at the angle
// over the end's line Hertz peak. Below it the end table, held at its last
// node, never reaches into the flat-rim range.
TEST(RimLoop, FlatRimTableTakesOverFromItsFirstAngle)
{
  study::rims::EndRatios ratios;
  ratios.table = {node(60, 1.5), node(100, 1.8), node(160, 1.96)};
  ratios.largest_modelled_rad = 170 * degree;
  ratios.flat_from_rad = 160 * degree;
  for (const auto& [angle, peak_gpa] : {std::pair{160.0, 4.0}, {165.0, 3.6}, {170.0, 3.0}, {175.0, 2.4}, {180.0, 2.2}})
  {
    study::rims::FlatRimNode n;
    n.section_angle_rad = angle * degree;
    // Two sides that are not mirror images: the larger peak counts.
    n.sides = {{0.3, 1e5, 1e-3, peak_gpa * 1e9, 2e9, 0, 0, true, 1},
               {0.3, 1e5, 1e-3, 0.5 * peak_gpa * 1e9, 2e9, 0, 0, true, 1}};
    ratios.flat_table.push_back(n);
  }
  const double line_hertz = 1e9; // the end's own
  EXPECT_NEAR(*ratios(1, loaded_end(150, line_hertz)), 1.8 + 0.16 * 50 / 60, 1e-12); // the end table
  EXPECT_NEAR(*ratios(1, loaded_end(160, line_hertz)), 4.0, 1e-12); // the flat-rim table from here
  EXPECT_NEAR(*ratios(1, loaded_end(172.5, 2 * line_hertz)), 1.35, 1e-12);
  EXPECT_NEAR(*ratios(2, loaded_end(175, line_hertz)), 2.6, 1e-12); // every other node: 170, 180
  EXPECT_NEAR(*ratios(1, loaded_end(180, line_hertz)), 2.2, 1e-12);
  EXPECT_NEAR(ratios.flat_table.back().ratio(), 1.1, 1e-12);
  EXPECT_TRUE(ratios.flat_table.front().converged());
  ratios.flat_table.front().sides.back().converged = false;
  EXPECT_FALSE(ratios.flat_table.front().converged());
}

// The end table solves only the nodes the loop's look-ups read: with the
// others left unsolved every look-up, by every node and by every other, gives
// the whole table's ratio to the last bit, and a look-up that would read an
// unsolved node is an error, not a ratio from farther nodes.
TEST(RimLoop, EndTableLeftUnsolvedWhereNoLookUpReadsGivesTheWholeTablesRatios)
{
  auto ratio = [](double angle_deg, double radius_mm) {
    return 2 + 0.01 * (angle_deg - 90) + 0.003 * (angle_deg - 90) * (angle_deg - 90) / 90 + 0.5 * std::log(radius_mm);
  };
  std::vector<study::rims::EndTableNode> whole;
  for (const double radius_mm : {1.0, 2.0, 4.0, 8.0, 16.0})
    for (const double angle : {60.0, 75.0, 90.0, 105.0, 120.0, 135.0, 150.0})
      whole.push_back(node(angle, ratio(angle, radius_mm), radius_mm * 1e-3));
  // Acute ends at small R, obtuse ones at large R, one held beyond the table.
  const std::vector<std::pair<double, double>> look_ups
      = {{62, 1.1e-3}, {70, 1.5e-3}, {88, 2.5e-3}, {118, 9e-3}, {140, 15e-3}, {155, 20e-3}};
  const double open = std::numbers::pi;
  std::vector<study::rims::EndTableNode> part = whole;
  for (auto& n : part)
    n.reached = false;
  for (const auto& [angle, radius] : look_ups)
    for (const int stride : {1, 2})
      for (const std::size_t k : study::rims::end_table_nodes_read(whole, stride, open, angle * degree, radius))
        part[k].reached = true;
  std::size_t reached = 0;
  for (auto& n : part)
    if (n.reached)
      ++reached;
    else
      n.study.end_to_interior.reset();
  EXPECT_LT(reached, whole.size());
  // No acute end at large R: 60 deg at R = 16 mm (the last column's first
  // node) is read by none, every node or every other (16 mm with 4 mm, 120
  // and 150 deg at most).
  EXPECT_FALSE(part[4 * 7].reached);

  for (const auto& [angle, radius] : look_ups)
    for (const int stride : {1, 2})
      EXPECT_EQ(*study::rims::end_table_ratio(part, stride, open, angle * degree, radius),
                *study::rims::end_table_ratio(whole, stride, open, angle * degree, radius))
          << angle << " deg, R = " << radius << ", stride " << stride;
  // An obtuse end at small R reads nodes no look-up above reached.
  EXPECT_THROW(study::rims::end_table_ratio(part, 1, open, 140 * degree, 1.1e-3), ComputationError);
  // Above the singular angle a look-up reads nothing.
  EXPECT_TRUE(study::rims::end_table_nodes_read(whole, 1, 100 * degree, 120 * degree, 2e-3).empty());
}
