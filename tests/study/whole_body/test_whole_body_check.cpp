// Issue 14's whole-body check (study/whole_body/whole_body_check.h) on the 10 mm
// cylinder and oloid: the whole body in 3D against the plane-strain slices
// along the ruling and the end models at its loaded ends, within 3 %. Label
// `long` (minutes): `ctest --test-dir build -L long -R WholeBody`; the
// WholeBodyCheckQuick suite (refusals, arithmetic) runs in the default suite.
#include "core/error.h"
#include "fem/petsc_session.h"
#include "study/whole_body/share_rules.h"
#include "study/whole_body/whole_body_check.h"
#include <cmath>
#include <gtest/gtest.h>
#include <mpi.h>
#include <string>
#include <string_view>
#include <tuple>
#include <utility>
#include <vector>

using namespace rollcheck;

namespace
{
/// The 10 mm oloid (L = 17.32 mm) at `direction_deg`, F = 100 N, steel.
study::whole_body::WholeBodyCheckSettings oloid_settings(double direction_deg)
{
  study::whole_body::WholeBodyCheckSettings s;
  s.body.body = "oloid";
  s.body.radius_m = 0.01;
  s.direction_deg = direction_deg;
  return s;
}

/// The oloid at --direction 67.5 (OloidAgreesWith...'s orientation) checked
/// under `rule`, with the settings it ran.
std::pair<study::whole_body::WholeBodyCheckSettings, study::whole_body::WholeBodyCheck> oloid_check_under(study::whole_body::ShareRule rule)
{
  fem::ensure_petsc();
  study::whole_body::WholeBodyCheckSettings s = oloid_settings(67.5);
  s.share_rule = rule;
  return {s, study::whole_body::run_whole_body_check(MPI_COMM_WORLD, s)};
}

/// The message of the InputError a check under `s` raises; a test failure
/// and "" when it raises none.
std::string input_error_message(const study::whole_body::WholeBodyCheckSettings& s)
{
  try
  {
    study::whole_body::run_whole_body_check(MPI_COMM_WORLD, s);
  }
  catch (const InputError& e)
  {
    return e.what();
  }
  ADD_FAILURE() << "no InputError";
  return "";
}
} // namespace

TEST(WholeBodyCheck, CylinderAgreesWithSlicesAndEndModelsWithinThreePercent)
{
  fem::ensure_petsc();
  study::whole_body::WholeBodyCheckSettings s; // r1 = 10 mm, L = 20 mm, F = 100 N, steel, tolerance 3 %
  ASSERT_EQ(s.body.body, "cylinder");
  ASSERT_DOUBLE_EQ(s.tolerance, 0.03);
  const study::whole_body::WholeBodyCheck check = study::whole_body::run_whole_body_check(MPI_COMM_WORLD, s);

  // The load the solver held: F along the vertical through the centre of mass.
  EXPECT_NEAR(check.fem.reaction_n, s.normal_load_n, 1e-3 * s.normal_load_n);
  EXPECT_NEAR(check.fem.force_n, s.normal_load_n, 1e-2 * s.normal_load_n);
  EXPECT_NEAR(check.fem.centre_of_pressure_m / check.orientation.ruling.length_m, 0.5, 1e-3);
  // b / L about 1e-3, as issue 14 asks.
  EXPECT_GT(check.half_width_m / check.orientation.ruling.length_m, 5e-4);
  EXPECT_LT(check.half_width_m / check.orientation.ruling.length_m, 2e-3);

  ASSERT_EQ(check.stations.size(), static_cast<std::size_t>(s.stations));
  for (const study::whole_body::StationComparison& st : check.stations)
    EXPECT_LE(std::abs(st.peak_difference()), s.tolerance) << "station at " << st.position_m << " m";
  ASSERT_EQ(check.ends.size(), 2u);
  for (const study::whole_body::EndComparison& end : check.ends)
  {
    EXPECT_FALSE(end.end_model.singular); // a square end on the rigid plane
    ASSERT_TRUE(end.difference.has_value()) << "end at " << end.position_m << " m: no converged end model";
    EXPECT_LE(std::abs(*end.difference), s.tolerance) << "end at " << end.position_m << " m";
  }
  EXPECT_LE(std::abs(check.largest_peak_difference), s.tolerance);
  EXPECT_TRUE(check.pass) << check.verdict;
}

// The oloid at r1 = 10 mm in the orientation whose ends are nearest square
// (--direction 67.5: c = 0.514, both ends loaded, R = 10.02 and 8.84 mm,
// interior angles 87.2 deg acute and 93.0 deg obtuse): its mapped whole-body
// mesh against the slices along the ruling and the end models at both ends
// (the acute end by its largest pressure within 2 b of the edge).
// The obtuse end is singular on the rigid plane: reported, never compared as
// a number, so the check as a whole does not pass: its outcome is singular
// ends, every comparison with a value being within the tolerance.
TEST(WholeBodyCheck, OloidAgreesWithSlicesAndItsAcuteEndWithinThreePercent)
{
  fem::ensure_petsc();
  study::whole_body::WholeBodyCheckSettings s = oloid_settings(67.5);
  ASSERT_DOUBLE_EQ(s.tolerance, 0.03);
  const study::whole_body::WholeBodyCheck check = study::whole_body::run_whole_body_check(MPI_COMM_WORLD, s);

  EXPECT_NEAR(check.fem.reaction_n, s.normal_load_n, 1e-3 * s.normal_load_n);
  EXPECT_NEAR(check.fem.force_n, s.normal_load_n, 1e-2 * s.normal_load_n);
  EXPECT_NEAR(check.fem.centre_of_pressure_m / check.orientation.ruling.length_m, check.orientation.centre_of_pressure, 1e-3);
  EXPECT_NEAR(check.orientation.ruling.length_m, std::sqrt(3.0) * s.body.radius_m, 1e-6); // every ruling of the oloid

  ASSERT_EQ(check.stations.size(), static_cast<std::size_t>(s.stations));
  for (const study::whole_body::StationComparison& st : check.stations)
    EXPECT_LE(std::abs(st.peak_difference()), s.tolerance) << "station at " << st.position_m << " m";
  ASSERT_EQ(check.ends.size(), 2u);
  const study::whole_body::EndComparison& acute = check.ends[0];
  const study::whole_body::EndComparison& obtuse = check.ends[1];
  EXPECT_LT(acute.interior_angle_deg, 90);
  EXPECT_FALSE(acute.end_model.singular);
  EXPECT_TRUE(acute.near_edge_peak); // its edge pressure falls to zero under refinement
  ASSERT_TRUE(acute.difference.has_value()) << "the acute end model's near-edge peak did not converge";
  EXPECT_LE(std::abs(*acute.difference), s.tolerance);
  EXPECT_GT(obtuse.interior_angle_deg, 90);
  EXPECT_TRUE(obtuse.end_model.singular);
  EXPECT_FALSE(obtuse.difference.has_value());
  EXPECT_TRUE(obtuse.matched_difference.has_value());
  // Its one end-model level sits at the body's end layer (the matched mesh).
  ASSERT_EQ(obtuse.end_model.levels.size(), 1u);
  EXPECT_NEAR(obtuse.end_model.levels[0].edge_element_m / check.sizes.end_layer_m, 1.0, 1e-9);
  // What the stations' misstated load costs fem-sds's peak of this orientation.
  EXPECT_LE(std::abs(check.largest_peak_difference), s.tolerance);
  EXPECT_FALSE(check.pass) << "a singular end never passes";
  EXPECT_EQ(check.outcome, study::whole_body::WholeBodyOutcome::singular_ends) << check.verdict;
}

TEST(WholeBodyCheckQuick, LargestPeakComparesTheLargestOfEachEvenAtDifferentStations)
{
  // The oloid's run at --direction 67.5 (docs/methods/whole-body.md): the slices'
  // largest peak is at 95 % of the ruling (221.32 MPa), the whole body's at
  // 83.75 % (216.5 MPa), where the locus overstates its own line load less.
  const double slice_mpa[] = {194.03, 197.21, 200.73, 204.09, 207.5, 210.84, 214.08, 217.85, 221.32};
  const double body_mpa[] = {184.4, 197.96, 204.63, 208.98, 212.2, 214.69, 216.34, 216.5, 213.09};
  std::vector<study::whole_body::StationComparison> stations(9);
  for (std::size_t k = 0; k < stations.size(); ++k)
  {
    stations[k].slice_peak_pa = 1e6 * slice_mpa[k];
    stations[k].body_peak_pa = 1e6 * body_mpa[k];
  }
  EXPECT_NEAR(study::whole_body::largest_peak_difference(stations), 216.5 / 221.32 - 1, 1e-12);
  EXPECT_DOUBLE_EQ(study::whole_body::largest_peak_difference({}), 0.0);
}

TEST(WholeBodyCheckQuick, OutcomeSetsSingularEndsApartFromFailures)
{
  // Ends as the oloid's at --direction 67.5: an acute end compared, an
  // obtuse end singular in its end model.
  std::vector<study::whole_body::EndComparison> ends(2);
  ends[0].difference = -0.0124;
  ends[1].end_model.singular = true;
  const double tolerance = 0.03;
  EXPECT_EQ(study::whole_body::check_outcome(0.0022, ends, tolerance), study::whole_body::WholeBodyOutcome::singular_ends);
  EXPECT_EQ(study::whole_body::check_outcome(0.0496, ends, tolerance), study::whole_body::WholeBodyOutcome::fail); // a station beyond
  ends[0].difference = 0.0421;
  EXPECT_EQ(study::whole_body::check_outcome(0.0022, ends, tolerance), study::whole_body::WholeBodyOutcome::fail); // the finite end beyond
  ends[0].difference = -0.0124;
  ends[1].end_model.singular = false; // no value and no singularity: its end model did not converge
  EXPECT_EQ(study::whole_body::check_outcome(0.0022, ends, tolerance), study::whole_body::WholeBodyOutcome::fail);
  ends[1].difference = 0.0164; // the cylinder's: both ends compared
  EXPECT_EQ(study::whole_body::check_outcome(0.0034, ends, tolerance), study::whole_body::WholeBodyOutcome::pass);
  EXPECT_EQ(study::whole_body::check_outcome(0.0034, {}, tolerance), study::whole_body::WholeBodyOutcome::fail); // no loaded end
  EXPECT_EQ(study::whole_body::check_outcome(NAN, ends, tolerance), study::whole_body::WholeBodyOutcome::fail);
  ends[1].difference = NAN;
  EXPECT_EQ(study::whole_body::check_outcome(0.0034, ends, tolerance), study::whole_body::WholeBodyOutcome::fail);
  EXPECT_EQ(study::whole_body::outcome_name(study::whole_body::WholeBodyOutcome::singular_ends), "SINGULAR ENDS");
}

TEST(WholeBodyCheckQuick, ScanOfTheCylinderIsEveryGeneratorUnderUniformLineHertz)
{
  study::whole_body::WholeBodyCheckSettings s; // the 10 mm cylinder, 20 mm long, F = 100 N, steel
  const auto scan = study::whole_body::scan_whole_body_orientations(s, 45);
  ASSERT_EQ(scan.size(), 8u);
  const double q = s.normal_load_n / s.body.height_m, E_star = s.youngs_modulus_pa / (1 - 0.09);
  const double b = std::sqrt(4 * q * s.body.radius_m / (M_PI * E_star)); // line Hertz
  for (const study::whole_body::WholeBodyOrientation& o : scan)
  {
    EXPECT_NEAR(o.ruling.length_m, s.body.height_m, 1e-9);
    EXPECT_NEAR(o.centre_of_pressure, 0.5, 1e-6);
    EXPECT_EQ(o.loaded_from, 0.0);
    EXPECT_EQ(o.loaded_to, 1.0);
    for (int end = 0; end < 2; ++end)
    {
      EXPECT_NEAR(o.radius_m(end), s.body.radius_m, 1e-6 * s.body.radius_m);
      EXPECT_NEAR(o.interior_angle_deg(end), 90, 1e-6);
      EXPECT_NEAR(o.end_load_n_per_m[static_cast<std::size_t>(end)], q, 1e-6 * q);
      EXPECT_NEAR(o.end_half_width_m[static_cast<std::size_t>(end)], b, 1e-6 * b);
    }
  }
  EXPECT_THROW(study::whole_body::scan_whole_body_orientations(s, 0), InputError);
}

// The oloid's c stays within [1/4, 3/4]; where it leaves [1/3, 2/3] only the
// nearer end is loaded, by the no-tension rule's triangle (2 F / (3 c L) at
// the end), else both (q_0 + q_1 = 2 F / L); the flattest loaded end of the
// scan is a vertex, 180 deg at c = 1/4 from that end (the flattest_loop_ends
// test's vertex, found here by another path: the contact curve's point
// nearest each direction).
TEST(WholeBodyCheckQuick, ScanOfTheOloidLoadsTheNearerEndAndReachesItsVertex)
{
  const study::whole_body::WholeBodyCheckSettings s = oloid_settings(0);
  const double F = s.normal_load_n;
  double flattest = 0, c_from_flattest_end = 0;
  for (const study::whole_body::WholeBodyOrientation& o : study::whole_body::scan_whole_body_orientations(s, 2.5))
  {
    const double c = o.centre_of_pressure, L = o.ruling.length_m;
    ASSERT_TRUE(o.in_equilibrium);
    EXPECT_NEAR(L, std::sqrt(3.0) * s.body.radius_m, 1e-6);
    EXPECT_GT(c, 0.25 - 1e-3);
    EXPECT_LT(c, 0.75 + 1e-3);
    const auto& q = o.end_load_n_per_m;
    if (c < 1.0 / 3)
    {
      EXPECT_NEAR(q[0], 2 * F / (3 * c * L), 1e-9 * q[0]);
      EXPECT_EQ(q[1], 0.0);
    }
    else if (c > 2.0 / 3)
    {
      EXPECT_EQ(q[0], 0.0);
      EXPECT_NEAR(q[1], 2 * F / (3 * (1 - c) * L), 1e-9 * q[1]);
    }
    else
      EXPECT_NEAR(q[0] + q[1], 2 * F / L, 1e-9 * F / L);
    for (int end = 0; end < 2; ++end)
      if (q[static_cast<std::size_t>(end)] > 0 && o.interior_angle_deg(end) > flattest)
      {
        flattest = o.interior_angle_deg(end);
        c_from_flattest_end = end == 0 ? c : 1 - c;
      }
  }
  EXPECT_GT(flattest, 179.9);
  EXPECT_NEAR(c_from_flattest_end, 0.25, 1e-3);
}

// The share rule is one strategy, chosen once by ShareRule: its name is the
// option's spelling (the JSON's share_rule), and the locus's q is the
// no-tension rule's: F / L along the cylinder, balanced at c = 1/2.
TEST(WholeBodyCheckQuick, EachShareRuleIsOneStrategyNamedAsItsOption)
{
  using study::whole_body::ShareRule;
  for (const auto& [rule, name, softens] :
       {std::tuple{ShareRule::locus, std::string_view("locus"), false},
        std::tuple{ShareRule::sections, std::string_view("sections"), true},
        std::tuple{ShareRule::coarse_body, std::string_view("coarse-body"), true}})
  {
    const study::whole_body::ShareRuleStrategy& strategy = study::whole_body::share_rule_strategy(rule);
    EXPECT_EQ(strategy.name, name);
    EXPECT_EQ(strategy.softens_ends, softens) << name;
    EXPECT_EQ(study::whole_body::softens_ends(rule), softens) << name;
  }
  fem::ensure_petsc();
  const study::whole_body::WholeBodyCheckSettings s; // the 10 mm cylinder, 20 mm long, F = 100 N
  study::whole_body::WholeBodyCheck check;
  check.orientation = study::whole_body::whole_body_orientation(s, 0);
  const study::whole_body::CheckContext context(MPI_COMM_WORLD, s, check.orientation);
  const study::whole_body::LineLoad q = study::whole_body::share_rule_strategy(ShareRule::locus).solve(context, check);
  for (const double f : {0.0, 0.25, 0.5, 1.0})
    EXPECT_NEAR(q(f), s.normal_load_n / s.body.height_m, 1e-6 * s.normal_load_n / s.body.height_m) << "f = " << f;
  EXPECT_FALSE(check.section_share.has_value());
  EXPECT_FALSE(check.coarse_body.has_value());
}

TEST(WholeBodyCheckQuick, ScanReportAndJsonNameTheBodyAndEveryOrientation)
{
  const study::whole_body::WholeBodyCheckSettings s; // the cylinder
  const auto scan = study::whole_body::scan_whole_body_orientations(s, 90);
  ASSERT_EQ(scan.size(), 4u);
  const nlohmann::json j = study::whole_body::scan_json(s, scan);
  EXPECT_EQ(j.at("body"), geometry::body_label(s.body));
  EXPECT_EQ(j.at("normal_load_n"), s.normal_load_n);
  ASSERT_EQ(j.at("orientations").size(), 4u);
  EXPECT_EQ(j.at("orientations")[1].at("direction_deg"), 90.0);
  const std::string report = study::whole_body::scan_report(s, scan);
  EXPECT_NE(report.find("orientations of " + geometry::body_label(s.body)), std::string::npos) << report;
  EXPECT_NE(report.find(study::whole_body::orientation_table(scan)), std::string::npos) << report;
}

TEST(WholeBodyCheckQuick, RefusesABodyWithoutAWholeBodyMesh)
{
  fem::ensure_petsc();
  study::whole_body::WholeBodyCheckSettings s;
  s.body.body = "sphere";
  EXPECT_THROW(study::whole_body::run_whole_body_check(MPI_COMM_WORLD, s), InputError);
}

TEST(WholeBodyCheckQuick, RefusesACoarseOloidHull)
{
  fem::ensure_petsc();
  study::whole_body::WholeBodyCheckSettings s = oloid_settings(0);
  s.body.points = 16;
  EXPECT_THROW(study::whole_body::run_whole_body_check(MPI_COMM_WORLD, s), InputError);
}

TEST(WholeBodyCheckQuick, RefusesBadCoarseBodyRuleSettings)
{
  fem::ensure_petsc();
  study::whole_body::WholeBodyCheckSettings s = oloid_settings(67.5);
  s.share_rule = study::whole_body::ShareRule::coarse_body;
  for (const auto& [elements, end_layer, setting] :
       {std::tuple{1, 0.5, "rule_contact_elements"}, std::tuple{2, 0.0, "rule_end_layer"},
        std::tuple{2, std::nan(""), "rule_end_layer"}})
  {
    s.rule_contact_elements = elements;
    s.rule_end_layer = end_layer;
    SCOPED_TRACE(setting);
    const std::string message = input_error_message(s);
    EXPECT_NE(message.find(setting), std::string::npos) << message;
  }
}

TEST(WholeBodyCheckQuick, RefusesTheEndSofteningRulesOnAPartlyLoadedRuling)
{
  // The oloid at 22.5 deg: c = 0.282, the no-tension rule loads 3c of the
  // ruling; the sections' and the coarse body's rules are matched to end
  // models at both rim ends of a ruling loaded end to end.
  fem::ensure_petsc();
  for (const auto& [rule, name] : {std::pair{study::whole_body::ShareRule::sections, "share_rule sections"},
                                   std::pair{study::whole_body::ShareRule::coarse_body, "share_rule coarse-body"}})
  {
    study::whole_body::WholeBodyCheckSettings s = oloid_settings(22.5);
    s.share_rule = rule;
    SCOPED_TRACE(name);
    const std::string message = input_error_message(s);
    EXPECT_NE(message.find(name), std::string::npos) << message;
    EXPECT_NE(message.find("loads only part of the ruling"), std::string::npos) << message;
  }
}

TEST(WholeBodyCheck, OloidSectionsRuleMeetsTheInteriorStationsWithinThreePercent)
{
  // The sections' rule (study/whole_body/section_share.h) at the orientation of
  // OloidAgreesWith...: away from the end zones the whole body's peaks meet
  // slices under the sections' q within the check's 3 %; at the stations 5 %
  // inside the ends the sections, without their neighbours' shear, are
  // softer than the whole body (docs/methods/whole-body.md), so those two are not
  // asserted.
  const auto [s, check] = oloid_check_under(study::whole_body::ShareRule::sections);
  ASSERT_TRUE(check.section_share.has_value());
  EXPECT_NEAR(check.section_share->force_n, s.normal_load_n, 1e-3 * s.normal_load_n);
  EXPECT_NEAR(check.section_share->centre_of_pressure_m / check.orientation.ruling.length_m, check.orientation.centre_of_pressure, 1e-3);
  ASSERT_EQ(check.stations.size(), static_cast<std::size_t>(s.stations));
  for (std::size_t k = 1; k + 1 < check.stations.size(); ++k)
    EXPECT_LE(std::abs(check.stations[k].peak_difference()), s.tolerance) << "station " << k;
  EXPECT_LE(std::abs(check.largest_peak_difference), s.tolerance);
}

TEST(WholeBodyCheck, OloidCoarseBodyRuleMeetsEveryStationAndTheAcuteEndWithinThreePercent)
{
  // The coarse body's load rule at the orientation of OloidAgreesWith...:
  // the whole body meshed at b/2 across the ruling gives the line load the
  // slices and end models take; the fine whole body is the reference. The
  // reduction itself is checked too: the coarse body's line load at every
  // station within 1 % of the fine body's.
  const auto [s, check] = oloid_check_under(study::whole_body::ShareRule::coarse_body);
  ASSERT_TRUE(check.coarse_body.has_value());
  EXPECT_NEAR(check.coarse_body->fem.reaction_n, s.normal_load_n, 1e-3 * s.normal_load_n);
  EXPECT_LT(check.coarse_body->fem.dofs, check.fem.dofs / 2);
  ASSERT_EQ(check.stations.size(), static_cast<std::size_t>(s.stations));
  for (const study::whole_body::StationComparison& st : check.stations)
  {
    EXPECT_LE(std::abs(st.load_difference()), 0.01) << "station at " << st.position_m << " m";
    EXPECT_LE(std::abs(st.peak_difference()), s.tolerance) << "station at " << st.position_m << " m";
  }
  ASSERT_EQ(check.ends.size(), 2u);
  const study::whole_body::EndComparison& acute = check.ends[0];
  EXPECT_TRUE(acute.near_edge_peak);
  ASSERT_TRUE(acute.rule_match_distance_m.has_value()) << "under a softening rule the end model meets it near the edge";
  ASSERT_TRUE(acute.difference.has_value()) << "the acute end model's near-edge peak did not converge";
  EXPECT_LE(std::abs(*acute.difference), s.tolerance);
  const study::whole_body::EndComparison& obtuse = check.ends[1];
  EXPECT_TRUE(obtuse.end_model.singular);
  // Its secondary reading's end model sits at the body's end layer, though
  // its b is the rule's at the match point, not the locus's.
  ASSERT_EQ(obtuse.end_model.levels.size(), 1u);
  EXPECT_NEAR(obtuse.end_model.levels[0].edge_element_m / check.sizes.end_layer_m, 1.0, 1e-9);
  EXPECT_EQ(check.outcome, study::whole_body::WholeBodyOutcome::singular_ends) << check.verdict;
}
