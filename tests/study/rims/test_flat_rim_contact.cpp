// The nearly flat rounded rim end by half-space theory (study/rims/flat_rim_contact.h):
// far from the end it is line Hertz, the oloid's balance is recomputed from
// its output, and bad input is refused. Its agreement with the FEM end model
// is tests/cli/flat_rim.sh's (reference data from `rollcheck rim`).
#include "study/rims/flat_rim_contact.h"
#include "contact/hertz.h"
#include "core/error.h"
#include "geometry/body.h"
#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <numbers>

using namespace rollcheck;

namespace
{
study::rims::FlatRimSettings straight_rim(double interior_angle_deg)
{
  study::rims::FlatRimSettings s;
  s.interior_angle_rad = interior_angle_deg * std::numbers::pi / 180;
  s.sheet_radius_m = 1e-3;
  s.load_n_per_m = 1.2e5;
  s.edge_radius_m = 4e-4;
  s.cells_per_half_width = 4;
  s.levels = 1;
  return s;
}

/// The window's columns and the linear rule beyond it carry F through the
/// centre of mass's foot (c L from the end), recomputed from the output.
void expect_balance(const study::rims::FlatRimContact& r, const study::rims::FlatRimLevel& l, double normal_load_n)
{
  const double cell = l.cell_m;
  double force = 0, moment = 0, after = 0;
  for (std::size_t i = 0; i < l.station_m.size(); ++i)
  {
    force += l.station_load_n_per_m[i] * cell;
    moment += l.station_load_n_per_m[i] * cell * l.station_m[i];
    after = l.station_m[i] + cell / 2;
  }
  const double q = l.balanced_end_line_load_n_per_m, slope = l.balanced_slope_n_per_m2, end = l.balanced_loaded_length_m;
  const auto load_to = [&](double x) { return q * x + slope * x * x / 2; };
  const auto moment_to = [&](double x) { return q * x * x / 2 + slope * x * x * x / 3; };
  force += load_to(end) - load_to(after);
  moment += moment_to(end) - moment_to(after);
  EXPECT_NEAR(force / normal_load_n, 1.0, 1e-3);
  EXPECT_NEAR(moment / force / (r.centre_of_pressure * r.ruling_length_m), 1.0, 1e-3);
  EXPECT_GE(q + slope * end, -1e-6 * q); // no tension
}
} // namespace

TEST(FlatRimContact, StraightRimIsLineHertzAwayFromItsEnd)
{
  const study::rims::FlatRimContact r = study::rims::flat_rim_contact(straight_rim(170));
  const study::rims::FlatRimLevel& l = r.levels.back();
  // Line Hertz at the sheet's R (1 mm > r_e) and q.
  const contact::LineHertz hertz =
      contact::line_contact(1.2e5, 1e-3, contact::effective_modulus(200e9, 0.3, false), 0.3);
  EXPECT_NEAR(r.half_width_m / hertz.half_width_m, 1.0, 1e-12);
  EXPECT_NEAR(l.far_peak_pa / hertz.peak_pressure_pa, 1.0, 0.01);
  // Every column from 0.7 to 0.9 of the window carries q within 1 % (the
  // matching holds only the sum and moment over 0.5-0.9; the end's extra
  // load decays through the first half of the window: +1.5 % at 30 b).
  const double after = 100 * r.half_width_m;
  for (std::size_t i = 0; i < l.station_m.size(); ++i)
    if (l.station_m[i] > 0.7 * after && l.station_m[i] < 0.9 * after)
      EXPECT_NEAR(l.station_load_n_per_m[i] / 1.2e5, 1.0, 0.01) << "x' = " << l.station_m[i];
  // The rounded rim concentrates pressure inside the end, within r_e
  // sin(10 deg) / 2 of the rim line; the contact ends before the rim line's
  // far side of the blend.
  EXPECT_GT(l.peak_pressure_pa, 1.5 * hertz.peak_pressure_pa);
  EXPECT_GT(l.peak_along_m, 0.0);
  EXPECT_LT(l.peak_along_m, 4e-4 * std::sin(10 * std::numbers::pi / 180));
  EXPECT_GT(l.contact_start_m, -4e-4 * std::tan(10 * std::numbers::pi / 180) / 2);
}

// A sheet far flatter than the fillet (R = 531 r_e, the rounded oloid's
// first direct end at the preprint's scale): the window's first tilt step
// (0.1 b^2 / (r_e after)) lifted the matching zone off the plane, its
// moment arm was 0 / 0 and the solve stopped on a NaN force. Quartered
// until the zone stays in contact, the window matches q far from the end.
TEST(FlatRimContact, ATiltStepThatLiftsTheMatchingZoneIsQuartered)
{
  study::rims::FlatRimSettings s = straight_rim(150);
  s.sheet_radius_m = 0.531;
  s.load_n_per_m = 92.62;
  s.edge_radius_m = 1e-3;
  const study::rims::FlatRimContact r = study::rims::flat_rim_contact(s);
  const study::rims::FlatRimLevel& l = r.levels.back();
  const contact::LineHertz hertz =
      contact::line_contact(92.62, 0.531, contact::effective_modulus(200e9, 0.3, false), 0.3);
  EXPECT_NEAR(l.far_peak_pa / hertz.peak_pressure_pa, 1.0, 0.01);
  EXPECT_TRUE(std::isfinite(l.peak_pressure_pa));
  EXPECT_GT(l.peak_pressure_pa, hertz.peak_pressure_pa);
}

// Label long (tests/CMakeLists.txt, long_cases): the default job's
// flat_rim_oloid_vertex case solves this vertex with the same checks.
TEST(FlatRimContact, OloidVertexBalancesTheBodyAndConverges)
{
  const study::rims::FlatRimSettings s; // cells of b / 4 and b / 8, a window of 100 b (and 200 b)
  const study::rims::FlatRimContact r = study::rims::flat_rim_contact(s);
  ASSERT_EQ(r.levels.size(), 2u);
  EXPECT_NEAR(r.centre_of_pressure, 0.25, 1e-12);
  const double length = std::sqrt(3.0) * s.body.radius_m;
  EXPECT_NEAR(r.ruling_length_m / length, 1.0, 1e-12);
  EXPECT_NEAR(r.end_line_load_n_per_m / (8 * s.normal_load_n / (3 * length)), 1.0, 1e-12);
  EXPECT_TRUE(r.converged) << r.last_change << " " << r.window_change;
  for (const study::rims::FlatRimLevel& l : r.levels)
  {
    expect_balance(r, l, s.normal_load_n);
    const double q = l.balanced_end_line_load_n_per_m;
    // The finish lifts the apex: the contact starts inside the ruling, and
    // the load it does not take there raises the rule's q(P).
    EXPECT_GT(l.contact_start_m, 0.0);
    EXPECT_LT(l.window_load_change, 0.0);
    EXPECT_GT(q, r.end_line_load_n_per_m);
    EXPECT_NEAR(l.far_peak_pa / l.far_line_hertz_pa, 1.0, 0.01);
  }
  EXPECT_GT(r.end_lift_m, 0.0);
  EXPECT_LT(r.largest_slope, 0.1); // half-space theory's small slopes
}

// Away from the vertex the end's rim leans (interior angle below 180 deg)
// and its sheet is wider than r_e; at the lowest angle, 150 deg, the doubled
// window covers 43 % of the ruling, whose load then answers strongly to the
// rule beyond it (the balance backtracks).
TEST(FlatRimContact, OloidLoopEndBalancesTheBody)
{
  for (const double angle_deg : {150.0})
  {
    study::rims::FlatRimSettings s;
    s.levels = 1;
    const study::rims::LoopEnd end = study::rims::body_loop_end(s.body, angle_deg * std::numbers::pi / 180);
    const study::rims::FlatRimContact r = study::rims::flat_rim_contact(s, end);
    EXPECT_NEAR(r.interior_angle_rad * 180 / std::numbers::pi, angle_deg, 1e-6);
    EXPECT_NEAR(r.centre_of_pressure, end.centre_of_pressure_from_end(), 1e-12);
    EXPECT_GT(r.end_radius_m, s.edge_radius_m);
    EXPECT_EQ(r.reference_radius_m, r.end_radius_m);
    const study::rims::FlatRimLevel& l = r.levels.back();
    expect_balance(r, l, s.normal_load_n);
    EXPECT_NEAR(l.far_peak_pa / l.far_line_hertz_pa, 1.0, 0.01) << angle_deg << " deg";
    EXPECT_GT(l.peak_pressure_pa, r.line_hertz_peak_pa) << angle_deg << " deg";
    EXPECT_LT(std::abs(r.window_change), s.tolerance) << angle_deg << " deg";
    EXPECT_LT(r.largest_slope, 0.1);
  }
}

// The surface flat-rim solves on, from the body's two circles, against the
// oracle's ruling (z = 0 on it, the sheet's radius R across it) and the
// rim's lean from the support directions (contact/rim_overhang.h): two
// independent computations of the same hull.
TEST(FlatRimContact, EndSurfaceIsTheHullNearTheLoopsEnd)
{
  for (const double angle_deg : {165.0, 175.0})
  {
    const study::rims::LoopEnd end = study::rims::body_loop_end(study::rims::FlatRimSettings{}.body, angle_deg * std::numbers::pi / 180);
    // The section along the ruling leaves the end at the lean's slope and
    // curves (it cuts the rim's ridge obliquely): the slope at the end by
    // Richardson extrapolation from 5 and 10 um beyond it.
    const auto slope = [&](double beyond) { return study::rims::end_hull_height(end, -beyond, 0) / beyond; };
    EXPECT_NEAR((2 * slope(5e-6) - slope(1e-5)) / std::tan(std::numbers::pi - end.interior_angle_rad), 1.0, 2e-3)
        << angle_deg << " deg";
    for (const double along : {1e-4, 1e-3})
    {
      const double radius = end.radius_m() + (end.other_radius_m() - end.radius_m()) * along / end.ruling.length_m;
      EXPECT_NEAR(study::rims::end_hull_height(end, along, 0), 0.0, 1e-10);
      const double across = 3e-3 * radius; // the sheet's cubic term cancels in the mean of +-y
      const double rise = study::rims::end_hull_height(end, along, across) + study::rims::end_hull_height(end, along, -across);
      EXPECT_NEAR(across * across / rise / radius, 1.0, 2e-3) << angle_deg << " deg, x' = " << along;
    }
  }
}

// A centre-line roller of r1 = 10 mm (the family's U optimum, theta 74.1
// deg, d = 0.757, rho = 1.071, unless given) on the steel block at its
// loop's end of this angle, the side walked backwards, with cells of b / 2
// and one level (each failure below is the same as at the loop's b / 4 and
// b / 8).
namespace
{
study::rims::FlatRimSettings centre_line_roller_settings(double interior_angle_deg,
                                                   geometry::RollerGenome genome = {74.1, 0.757, 1.071, 2})
{
  geometry::BodySpec roller;
  roller.body = "roller";
  roller.family = geometry::RollerFamily::centre_line;
  roller.genome = genome;
  roller.radius_m = 0.01;
  study::rims::FlatRimSettings s;
  s.body = roller;
  s.end_angle_rad = interior_angle_deg * std::numbers::pi / 180;
  s.loop_side = 1;
  s.steel_counter_face = true;
  s.cells_per_half_width = 2;
  s.levels = 1;
  return s;
}

study::rims::FlatRimContact centre_line_roller_on_steel(double interior_angle_deg,
                                                  geometry::RollerGenome genome = {74.1, 0.757, 1.071, 2})
{
  const study::rims::FlatRimSettings s = centre_line_roller_settings(interior_angle_deg, genome);
  const study::rims::FlatRimContact r = study::rims::flat_rim_contact(s);
  const study::rims::FlatRimLevel& l = r.levels.back();
  expect_balance(r, l, s.normal_load_n);
  EXPECT_NEAR(l.far_peak_pa / l.far_line_hertz_pa, 1.0, 0.01);
  EXPECT_LT(std::abs(r.window_change), s.tolerance);
  EXPECT_LT(r.largest_slope, 0.1);
  return r;
}
} // namespace

// At 176 deg the balance raises the line load beyond the window above the
// locus's, and the contact at the doubled window's far edge outgrows the
// width sized from the locus's load: it reached the border across until
// the window widened.
TEST(FlatRimContact, ContactWiderThanTheLocusSaysWidensTheWindow)
{
  const study::rims::FlatRimContact r = centre_line_roller_on_steel(176);
  EXPECT_GT(r.across_scale, 1.0);
  EXPECT_EQ(r.after_over_half_width, study::rims::FlatRimSettings{}.after_over_half_width);
}

// At 164 deg the doubled window of 200 b covers 72 % of the ruling (c =
// 0.235: the loaded 71 %): the rule beyond cannot balance the body with it
// until the window shortens.
TEST(FlatRimContact, ABodyThatCannotBalanceWithTheWindowShortensIt)
{
  const study::rims::FlatRimContact r = centre_line_roller_on_steel(164);
  EXPECT_LT(r.after_over_half_width, study::rims::FlatRimSettings{}.after_over_half_width);
  EXPECT_EQ(r.across_scale, 1.0);
}

// The whole loaded ruling in one grid, the fuller model of the window and
// the rule beyond it: its columns alone carry F through the centre of
// mass's foot, halfway along its contact it reads line Hertz, the contact
// ends inside it, and where the (shortened) window converges the two agree
// within that window's tolerance (164 deg).
TEST(FlatRimContact, WholeRulingBalancesTheBodyAndAgreesWithTheWindow)
{
  const study::rims::FlatRimContact window = centre_line_roller_on_steel(164);
  study::rims::FlatRimSettings s = centre_line_roller_settings(164);
  s.whole_ruling = true;
  const study::rims::FlatRimContact whole = study::rims::flat_rim_contact(s);
  const study::rims::FlatRimLevel& l = whole.levels.back();
  ASSERT_TRUE(whole.whole_ruling);
  expect_balance(whole, l, s.normal_load_n); // no rule beyond: the columns alone
  EXPECT_EQ(l.balanced_loaded_length_m, 0.0);
  EXPECT_NEAR(l.far_peak_pa / l.far_line_hertz_pa, 1.0, 0.01);
  EXPECT_EQ(l.station_load_n_per_m.back(), 0.0);
  EXPECT_NEAR(l.peak_pressure_pa / window.levels.back().peak_pressure_pa, 1.0, s.tolerance);
  EXPECT_FALSE(study::rims::needs_whole_ruling(s, whole));
}

// The FEM-SDS optimum's 160 deg end walked forwards (c = 0.273: the
// locus's load reaches past 0.8 of the ruling, the grid to r_e short of the
// far rim): the far rim is oblique, and 0.42 mm across the ruling, 0.4 r_e
// short of its end, lies outside the body's outline on the ground (no
// segment of the hull over it, from anywhere on the end's rim circle), where
// the rounding's margin once asked for the surface and refused the solve.
// The grid stops within the outline, short of r_e from the far rim, the
// contact ends inside it, and the peak agrees with the window's.
TEST(FlatRimContact, WholeRulingStopsWithinAnObliqueFarRim)
{
  study::rims::FlatRimSettings s = centre_line_roller_settings(160, {112.7, 1.000, 0.999, 2});
  s.loop_side = 0;
  const study::rims::LoopEnd end = study::rims::body_loop_end(s.body, s.end_angle_rad, s.loop_side);
  const double ruling = end.ruling.length_m;
  EXPECT_FALSE(std::isfinite(study::rims::end_hull_height(end, ruling - 0.4 * s.edge_radius_m, 4.2e-4)));
  EXPECT_TRUE(std::isfinite(study::rims::end_hull_height(end, ruling - 0.4 * s.edge_radius_m, 0)));
  const study::rims::FlatRimContact window = study::rims::flat_rim_contact(s);
  s.whole_ruling = true;
  const study::rims::FlatRimContact whole = study::rims::flat_rim_contact(s);
  const study::rims::FlatRimLevel& l = whole.levels.back();
  expect_balance(whole, l, s.normal_load_n);
  EXPECT_LT(l.station_m.back(), ruling - s.edge_radius_m);
  EXPECT_GT(l.station_m.back(), 0.9 * ruling);
  EXPECT_EQ(l.station_load_n_per_m.back(), 0.0);
  EXPECT_NEAR(l.peak_pressure_pa / window.levels.back().peak_pressure_pa, 1.0, s.tolerance);
}

// The loop's flat-rim table solves a side whole only where the balance
// shortened its window and the doubled window still moves the peak.
TEST(FlatRimContact, OnlyAShortenedWindowThatDoesNotConvergeNeedsTheWholeRuling)
{
  const study::rims::FlatRimSettings s;
  study::rims::FlatRimContact r;
  r.after_over_half_width = 0.5625 * s.after_over_half_width;
  r.window_change = 1.01 * s.tolerance;
  EXPECT_TRUE(study::rims::needs_whole_ruling(s, r));
  r.window_change = -1.01 * s.tolerance;
  EXPECT_TRUE(study::rims::needs_whole_ruling(s, r));
  r.window_change = 0.99 * s.tolerance;
  EXPECT_FALSE(study::rims::needs_whole_ruling(s, r));
  r.window_change = 1.01 * s.tolerance;
  r.after_over_half_width = s.after_over_half_width;
  EXPECT_FALSE(study::rims::needs_whole_ruling(s, r)); // a window the settings set: doubling is its check
}

// At 174 deg a step of the body's balance put a rule beyond the window
// that ends just past it, its q at the end extrapolated to 200 times the
// locus's and 150 times F on the window: the contact then spread to the
// window's corner. Such a step is halved back, and where halving does not
// help the window shortens.
TEST(FlatRimContact, ABalanceStepThatLoadsTheWindowBeyondFShortensIt)
{
  const study::rims::FlatRimContact r = centre_line_roller_on_steel(174);
  EXPECT_LT(r.after_over_half_width, study::rims::FlatRimSettings{}.after_over_half_width);
}

// The FEM-SDS template optimum (112.7, 1.000, 0.999) at its 160 deg end walked
// backwards: the hull beyond that end lies on segments from its rim circle
// more than 0.15 rad from the end, where the surface's search once stopped
// ("the hull's surface was not found over the window"), refusing rim
// --body's whole flat-rim table on steel.
TEST(FlatRimContact, TheHullIsFoundBeyondTheFemSdsOptimumsEnd)
{
  const study::rims::FlatRimContact r = centre_line_roller_on_steel(160, {112.7, 1.000, 0.999, 2});
  EXPECT_NEAR(r.interior_angle_rad * 180 / std::numbers::pi, 160.0, 1e-6);
}

// Extra levels are added only while the peak's last change is at least the
// tolerance: none once it is below (a tolerance of 1), up to the cap when it
// never is (a tolerance of 1e-12), each halving the cells again.
TEST(FlatRimContact, ExtraLevelsAreAddedOnlyWhileThePeakMoves)
{
  study::rims::FlatRimSettings s = straight_rim(170);
  s.cells_per_half_width = 2;
  s.after_over_half_width = 30; // short: the levels' logic is what is tested
  s.levels = 2;
  s.extra_levels = 1;
  s.tolerance = 1;
  EXPECT_EQ(study::rims::flat_rim_contact(s).levels.size(), 2u);
  s.tolerance = 1e-12;
  const study::rims::FlatRimContact moving = study::rims::flat_rim_contact(s);
  ASSERT_EQ(moving.levels.size(), 3u);
  EXPECT_FALSE(moving.converged);
  EXPECT_DOUBLE_EQ(moving.levels[2].cell_m, moving.levels[1].cell_m / 2);
}

TEST(FlatRimContact, RefusesBadInput)
{
  study::rims::FlatRimSettings s = straight_rim(120);
  EXPECT_THROW(study::rims::flat_rim_contact(s), InputError); // too steep for half-space theory
  s = straight_rim(170);
  s.edge_radius_m = -1e-4;
  EXPECT_THROW(study::rims::flat_rim_contact(s), InputError);
  s = straight_rim(170);
  s.load_n_per_m = std::nan("");
  EXPECT_THROW(study::rims::flat_rim_contact(s), InputError);
  s = straight_rim(170);
  s.extra_levels = -1;
  EXPECT_THROW(study::rims::flat_rim_contact(s), InputError);
  s = straight_rim(170);
  s.whole_ruling = true; // a straight rim's contact has no ruling to end it
  EXPECT_THROW(study::rims::flat_rim_contact(s), InputError);
  // A flat end (180 deg) lets the contact run on past the window's start:
  // refused, not truncated.
  s = straight_rim(180);
  s.before_over_half_width = 2;
  EXPECT_THROW(study::rims::flat_rim_contact(s), ComputationError);
  study::rims::FlatRimSettings oloid;
  oloid.end_angle_rad = 140 * std::numbers::pi / 180;
  EXPECT_THROW(study::rims::flat_rim_contact(oloid), InputError);
}
