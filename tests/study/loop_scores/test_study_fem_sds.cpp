// FEM-SDS at library level (study/loop_scores/fem_sds.h, study/loop_scores/loop_sds.h): the steps of
// the method against hand computations (where the slices go, the
// line-load Hertz peak; where the mapped pressures are held:
// tests/contact/test_ruling_load.cpp), the table of the
// orientations with its slab check, and the whole loop of
// the cylinder against the value its geometry implies. A cylinder rolling
// without slipping carries the same line load along every generator, so over
// a loop each side face collects the same pressure sum and the end discs
// none: the template then gives, with side faces a_s (n_s of them), cap
// faces a_c and A the total area,
//     SDS = (1/A) [sum_side a_s (1 / n_s - a_s / A)^2 + sum_caps a_c (a_c / A)^2],
// an exact check of the loop sampling and of the face mapping. Its slices
// meet the closed form of the uniformly loaded generator,
// p0 = sqrt((F / L) E* / (pi R)) (K. L. Johnson, "Contact Mechanics", 1985,
// eq. 4.45), to the accuracy of tests/fem/test_slice_contact.cpp.
#include "contact/hertz.h"
#include "fem/scenes/rim_end_contact.h"
#include "fem/scenes/slice_scaling.h"
#include "core/error.h"
#include "geometry/body.h"
#include "geometry/face_areas.h"
#include "study/loop_scores/fem_sds.h"
#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <limits>
#include <numbers>

using namespace rollcheck;

TEST(FemSdsSteps, SlicesStayClearOfTheCreasesAndMappingPointsSplitTheLoadedPart)
{
  const std::vector<double> slices = study::loop_scores::slice_fractions(0.0, 1.0, 0.05, 3);
  ASSERT_EQ(slices.size(), 3u);
  EXPECT_DOUBLE_EQ(slices[0], 0.05);
  EXPECT_DOUBLE_EQ(slices[1], 0.5);
  EXPECT_DOUBLE_EQ(slices[2], 0.95);
  const std::vector<double> along = study::loop_scores::mapping_fractions(0.2, 0.6, 4);
  const std::vector<double> midpoints{0.25, 0.35, 0.45, 0.55};
  ASSERT_EQ(along.size(), midpoints.size());
  for (std::size_t k = 0; k < along.size(); ++k)
    EXPECT_NEAR(along[k], midpoints[k], 1e-15);
}

TEST(FemSdsSteps, TheTableHasARowPerOrientationAndTheSlabCheckWhereItRan)
{
  study::loop_scores::FemSdsResult result;
  result.body = "cylinder";
  result.source = "a made-up loop";
  result.loop.samples = 16;
  result.orientations.resize(2);
  study::loop_scores::FemSdsOrientation& solved = result.orientations[1];
  solved.index = 1;
  solved.solved = true;
  solved.locus.ruling = oracle::Ruling{};
  solved.locus.centre_of_pressure = 0.5;
  solved.fem_peak_pa = solved.fem_peak_refined_pa = solved.line_hertz_peak_pa = 2e6;
  std::string table = study::loop_scores::markdown_table(result);
  EXPECT_EQ(std::count(table.begin(), table.end(), '\n'), 4); // head, rule and a row each
  EXPECT_NE(table.find("| 0 | 0 | point | - | 0 | 0 | - | - |"), std::string::npos) << table;
  EXPECT_NE(table.find("| 1 | 0 | point | 0.500 | 0 | 0 | 2 | 2 | 2 | +0.00 % | +0.00 % |"), std::string::npos)
      << table;
  EXPECT_EQ(table.find("3D slab"), std::string::npos);
  fem::SlabFem slab;
  slab.slice_peak_pressure_pa = {2.02e6};
  solved.slab.push_back(slab);
  result.slab_checked = 1;
  table = study::loop_scores::markdown_table(result);
  EXPECT_NE(table.find("3D slab of the whole ruling against the slices"), std::string::npos) << table;
  EXPECT_NE(table.find("| +1.00 % |"), std::string::npos) << table;
  const std::string report = study::loop_scores::report(result);
  EXPECT_TRUE(report.starts_with("\nfem-sds cylinder (a made-up loop):\n\n" + table)) << report;
  EXPECT_NE(report.find("over the 16 samples of the loop"), std::string::npos) << report;
}

TEST(FemSdsSteps, LineHertzPeakFollowsTheNoTensionLineLoad)
{
  oracle::Ruling ruling;
  ruling.length_m = 2.0;
  ruling.start_radius_m = 0.5;
  ruling.end_radius_m = 1.5;
  const double F = 100, e_star = 200e9 / (1 - 0.09);
  // c = 1/2: uniform q = F / L; R(0.25) = 0.75.
  EXPECT_NEAR(study::loop_scores::line_hertz_peak(F, 0.5, ruling, e_star, 0.25) / std::sqrt(50 * e_star / (std::numbers::pi * 0.75)),
              1.0, 1e-12);
  // c = 0.2: a triangle over the first 3c = 0.6 of the ruling, q(0) = 2 F / (0.6 L),
  // half of it at 0.3 where R = 0.8; nothing beyond 0.6.
  EXPECT_NEAR(study::loop_scores::line_hertz_peak(F, 0.2, ruling, e_star, 0.3)
                  / std::sqrt(F / (0.6 * 2.0) * e_star / (std::numbers::pi * 0.8)),
              1.0, 1e-12);
  EXPECT_EQ(study::loop_scores::line_hertz_peak(F, 0.2, ruling, e_star, 0.7), 0.0);
}

TEST(FemSds, OnlyTheExactHullsOfCirclesAreInputs)
{
  study::loop_scores::FemSdsSettings settings;
  settings.body.mesh_file = "oloid.obj";
  EXPECT_THROW(study::loop_scores::run_fem_sds(MPI_COMM_WORLD, settings), InputError);
  settings.body.mesh_file.clear();
  settings.body.body = "sphere";
  EXPECT_THROW(study::loop_scores::run_fem_sds(MPI_COMM_WORLD, settings), InputError);
}

namespace
{
/// The cylinder's SDS for even contact of its side over a loop (header).
double even_side_sds(const geometry::BodySpec& cylinder)
{
  const geometry::SurfaceMesh mesh = geometry::make_body(cylinder);
  const Eigen::VectorXd areas = geometry::face_areas(mesh);
  const double total = areas.sum(), half_height = cylinder.height_m / 2;
  std::vector<double> side, caps;
  for (Eigen::Index f = 0; f < mesh.faces.rows(); ++f)
  {
    const bool on_a_cap = std::abs(std::abs(mesh.vertices(mesh.faces(f, 0), 2)) - half_height) < 1e-12
                          && std::abs(mesh.vertices(mesh.faces(f, 1), 2) - mesh.vertices(mesh.faces(f, 0), 2)) < 1e-12
                          && std::abs(mesh.vertices(mesh.faces(f, 2), 2) - mesh.vertices(mesh.faces(f, 0), 2)) < 1e-12;
    (on_a_cap ? caps : side).push_back(areas[f]);
  }
  double score = 0;
  for (const double a : side)
    score += a * std::pow(1.0 / static_cast<double>(side.size()) - a / total, 2);
  for (const double a : caps)
    score += a * std::pow(a / total, 2);
  return score / total;
}
} // namespace

TEST(FemSds, CylinderLoopMeetsEvenContactOfItsSideAndItsSlicesMeetLineHertz)
{
  study::loop_scores::FemSdsSettings settings; // rolling oracle, r = 1 m, height 2 m, steel, F = 100 N
  settings.body.body = "cylinder";
  settings.orientations = 2;
  settings.fem_slices = 3;
  const study::loop_scores::FemSdsResult result = study::loop_scores::run_fem_sds(MPI_COMM_WORLD, settings);
  const double L = settings.body.height_m, R = settings.body.radius_m;
  const double e_star = settings.youngs_modulus_pa / (1 - settings.poisson_ratio * settings.poisson_ratio);
  const double p0 = std::sqrt(settings.normal_load_n / L * e_star / (std::numbers::pi * R));

  // The whole loop: every sample on a generator, the scores at the even-side value.
  const study::loop_scores::LoopSds& loop = result.loop;
  EXPECT_EQ(loop.samples, static_cast<std::size_t>(settings.samples_per_loop));
  EXPECT_EQ(loop.singular_samples, 0u);
  const double exact = even_side_sds(settings.body);
  ASSERT_TRUE(loop.fem.value && loop.line_hertz.value && loop.point_hertz.value);
  EXPECT_NEAR(*loop.fem.value / exact, 1.0, 1e-3) << "FEM-SDS " << *loop.fem.value << ", even side " << exact;
  EXPECT_NEAR(*loop.line_hertz.value / exact, 1.0, 1e-3);
  EXPECT_TRUE(loop.converged());
  // One line load, one lambda; the table's g there against the slices solved
  // directly: within the FEM's accuracy against Hertz (0.3 %, test_slice_contact).
  EXPECT_NEAR(loop.load_ratio_min / loop.load_ratio_max, 1.0, 1e-9);
  EXPECT_LT(result.table_vs_direct_worst, 3e-3);

  EXPECT_NEAR(result.effective_modulus_pa / e_star, 1.0, 1e-15);
  ASSERT_EQ(result.orientations.size(), 2u);
  EXPECT_EQ(result.fem_solved, 2u);
  EXPECT_EQ(result.reaching_crease, 2u); // the generator runs rim to rim
  for (const study::loop_scores::FemSdsOrientation& r : result.orientations)
  {
    ASSERT_TRUE(r.solved);
    EXPECT_NEAR(r.locus.centre_of_pressure, 0.5, 1e-6);
    ASSERT_EQ(r.slices.size(), 3u);
    EXPECT_NEAR(r.line_hertz_peak_pa / p0, 1.0, 1e-9);
    EXPECT_NEAR(r.fem_peak_pa / p0, 1.0, 5e-3);
    EXPECT_LT(std::abs(r.fem_peak_refined_pa / r.fem_peak_pa - 1), 3e-2);
    EXPECT_NEAR(r.contact_length_m, L, 1e-9);
  }

  const nlohmann::json j = to_json(result);
  EXPECT_EQ(j.at("fem_sds").get<double>(), *loop.fem.value);
  EXPECT_EQ(j.at("oracle"), "rolling");
  EXPECT_EQ(j.at("per_orientation").at(1).at("index"), 1);
  EXPECT_EQ(j.at("per_orientation").at(1).at("fem_peak_pa").get<double>(), result.orientations[1].fem_peak_pa);
  EXPECT_EQ(j.at("per_orientation").at(0).at("slices").size(), 3u);
  EXPECT_EQ(j.at("fem_solves").get<std::size_t>(), loop.fem_solves);
}

TEST(FemSds, CylinderEndAwareScoresFollowTheEndFactor)
{
  study::loop_scores::FemSdsSettings settings; // rolling oracle, r = 1 m, height 2 m, steel
  settings.body.body = "cylinder";
  settings.samples_per_loop = 512;
  settings.orientations = 1;
  settings.fem_slices = 2;
  // p0 = 0.84 GPa: stress amplitudes p / 2 above the endurance limit (250 MPa), so FEM-FDS is finite.
  settings.normal_load_n = 2e7;
  fem::SliceScaling table(study::loop_scores::slice_settings(settings), settings.table_nodes_per_decade);
  const std::vector<study::loop_scores::EndFactor> factors = {
      [](const study::loop_scores::LoadedEnd&) { return std::optional<double>(0.27); }, // about the square end's on the rigid plane
      [](const study::loop_scores::LoadedEnd&) { return std::optional<double>(1.0); },
      [](const study::loop_scores::LoadedEnd&) { return std::optional<double>(2.0); },
      [](const study::loop_scores::LoadedEnd&) { return std::optional<double>(); }};   // singular
  study::loop_scores::FemSdsResult result = study::loop_scores::run_fem_sds(MPI_COMM_WORLD, settings, table);
  study::loop_scores::LoopSds& loop = result.loop;
  loop.end_aware = study::loop_scores::end_aware_scores(MPI_COMM_WORLD, result.loop_samples, table, study::loop_scores::loop_settings(settings),
                                           factors, 0.0);

  // Every sample stands on a generator running rim to rim: two square ends.
  EXPECT_EQ(loop.loaded_end_samples, loop.samples);
  EXPECT_EQ(loop.loaded_ends, 2 * loop.samples);
  EXPECT_NEAR(loop.loaded_end_angle_min_rad, std::numbers::pi / 2, 1e-9);
  EXPECT_NEAR(loop.loaded_end_angle_max_rad, std::numbers::pi / 2, 1e-9);

  // One pressure along every generator: each face's damage is d(p) times
  // its contacts, its pressure p times them, so FEM-FDS equals FEM-SDS.
  ASSERT_TRUE(loop.fem_rulings.value && loop.fem_fds_rulings.value);
  EXPECT_NEAR(*loop.fem_fds_rulings.value / *loop.fem_rulings.value, 1.0, 1e-12);
  // So with ends at the interior's pressure (a factor 1); the face at a rim
  // adds its sample even where no mapping point fell on it.
  ASSERT_EQ(loop.end_aware.size(), 4u);
  ASSERT_TRUE(loop.end_aware[1].sds.value && loop.end_aware[1].fds.value);
  EXPECT_NEAR(*loop.end_aware[1].fds.value / *loop.end_aware[1].sds.value, 1.0, 1e-12);
  // The largest end pressure is the factor times the interior's.
  for (const auto& [k, factor] : {std::pair{0, 0.27}, std::pair{1, 1.0}, std::pair{2, 2.0}})
  {
    EXPECT_NEAR(loop.end_aware[k].peak_pa / loop.fem_peak_pa, factor, 1e-9);
    EXPECT_EQ(loop.end_aware[k].singular_ends, 0u);
  }
  // Each side quad's two triangles hold the two ends of every generator
  // crossing it, so ends at twice the interior's pressure give every face 2 p
  // in each of its samples: the scores of a factor 1, and the peak doubled.
  ASSERT_TRUE(loop.end_aware[2].sds.value);
  EXPECT_NEAR(*loop.end_aware[2].sds.value / *loop.end_aware[1].sds.value, 1.0, 1e-12);
  // Singular ends: no scores, every loaded end counted.
  EXPECT_FALSE(loop.end_aware[3].sds.value.has_value());
  EXPECT_FALSE(loop.end_aware[3].fds.value.has_value());
  EXPECT_EQ(loop.end_aware[3].singular_ends, loop.loaded_ends);
  EXPECT_EQ(loop.end_aware[3].peak_pa, 0.0);
  EXPECT_EQ(loop.end_aware[1].outside_model_ends, 0u);

  // An end near its sheet's apex (R -> 0): line contact holds while b / R,
  // from line Hertz itself, stays below fem::largest_half_width_over_radius.
  const double e_star = result.effective_modulus_pa, radius = 1.0;
  auto half_width_over_radius = [&](double load_ratio) {
    return contact::line_contact(load_ratio * e_star * radius, radius, e_star, settings.poisson_ratio).half_width_m
           / radius;
  };
  const double limit = std::numbers::pi / 4 * std::pow(fem::largest_half_width_over_radius, 2);
  ASSERT_LT(half_width_over_radius(0.999 * limit), fem::largest_half_width_over_radius);
  ASSERT_GT(half_width_over_radius(1.001 * limit), fem::largest_half_width_over_radius);
  study::loop_scores::LoadedEnd& end = result.loop_samples.rulings.at(0).ends.at(0);
  const std::vector<study::loop_scores::EndFactor> unit = {factors[1]};
  // Inside, but above half the limit, at three times the others' line-Hertz
  // pressure (an end towards a sheet's apex): scored, the loop's largest end
  // pressure, and absent from the peak within half the limit.
  end.load_ratio = 0.999 * limit;
  end.line_hertz_pa *= 3;
  const study::loop_scores::EndAwareScores inside
      = study::loop_scores::end_aware_scores(MPI_COMM_WORLD, result.loop_samples, table, study::loop_scores::loop_settings(settings), unit, 0.0)[0];
  EXPECT_EQ(inside.outside_model_ends, 0u);
  EXPECT_TRUE(inside.sds.value.has_value());
  EXPECT_NEAR(inside.peak_pa / loop.fem_peak_pa, 3.0, 1e-9);
  EXPECT_NEAR(inside.peak_within_half_limit_pa / loop.fem_peak_pa, 1.0, 1e-9);
  end.load_ratio = 1.001 * limit; // outside: no pressure, scores undefined, the others' peak kept
  const study::loop_scores::EndAwareScores outside
      = study::loop_scores::end_aware_scores(MPI_COMM_WORLD, result.loop_samples, table, study::loop_scores::loop_settings(settings), unit, 0.0)[0];
  EXPECT_EQ(outside.outside_model_ends, 1u);
  EXPECT_EQ(outside.outside_model_samples, 1u);
  EXPECT_EQ(outside.singular_ends, 0u);
  EXPECT_FALSE(outside.sds.value.has_value());
  EXPECT_FALSE(outside.fds.value.has_value());
  EXPECT_NEAR(outside.peak_pa / loop.fem_peak_pa, 1.0, 1e-9);
  EXPECT_EQ(outside.peak_within_half_limit_pa, outside.peak_pa);

  // A part finished with an edge radius r_e four times the end's R: the end
  // is taken at R = r_e, its load ratio a quarter (b / R half: back inside
  // the model), its line-Hertz pressure half (1.5 times the others').
  end.radius_m = 0.125;
  const study::loop_scores::EndAwareScores finished
      = study::loop_scores::end_aware_scores(MPI_COMM_WORLD, result.loop_samples, table, study::loop_scores::loop_settings(settings), unit, 0.5)[0];
  EXPECT_EQ(finished.finished_ends, 1u);
  EXPECT_EQ(finished.outside_model_ends, 0u);
  EXPECT_TRUE(finished.sds.value.has_value());
  EXPECT_NEAR(finished.peak_pa / loop.fem_peak_pa, 1.5, 1e-9);
  EXPECT_NEAR(finished.finished_peak_pa / loop.fem_peak_pa, 1.5, 1e-9);
  EXPECT_NEAR(finished.unfinished_peak_pa / loop.fem_peak_pa, 1.0, 1e-9);
  // An edge radius below the end's R leaves it as it was.
  const study::loop_scores::EndAwareScores sharper
      = study::loop_scores::end_aware_scores(MPI_COMM_WORLD, result.loop_samples, table, study::loop_scores::loop_settings(settings), unit, 0.1)[0];
  EXPECT_EQ(sharper.finished_ends, 0u);
  EXPECT_EQ(sharper.outside_model_ends, 1u);
  EXPECT_THROW(study::loop_scores::end_aware_scores(MPI_COMM_WORLD, result.loop_samples, table, study::loop_scores::loop_settings(settings), unit,
                                       -1.0),
               InputError);
}
