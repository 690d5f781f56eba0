// FEM-SDS at library level (study/fem_sds.h): the steps of the method against
// hand computations (where the slices go, the line-load Hertz peak, the peaks
// mapped onto faces, the score template on a tiny input), and a cheap run on
// the cylinder whose slice FEM meets the closed form of its uniformly loaded
// generator, p0 = sqrt((F / L) E* / (pi R)) (K. L. Johnson, "Contact
// Mechanics", 1985, eq. 4.45), to the accuracy of tests/test_slice_contact.cpp.
#include "core/error.h"
#include "study/fem_sds.h"
#include <cmath>
#include <gtest/gtest.h>
#include <limits>
#include <numbers>

using namespace rollcheck;

TEST(FemSdsSteps, SlicesStayClearOfTheCreasesAndMappingPointsSplitTheLoadedPart)
{
  const std::vector<double> slices = study::slice_fractions(0.0, 1.0, 0.05, 3);
  ASSERT_EQ(slices.size(), 3u);
  EXPECT_DOUBLE_EQ(slices[0], 0.05);
  EXPECT_DOUBLE_EQ(slices[1], 0.5);
  EXPECT_DOUBLE_EQ(slices[2], 0.95);
  const std::vector<double> along = study::mapping_fractions(0.2, 0.6, 4);
  const std::vector<double> midpoints{0.25, 0.35, 0.45, 0.55};
  ASSERT_EQ(along.size(), midpoints.size());
  for (std::size_t k = 0; k < along.size(); ++k)
    EXPECT_NEAR(along[k], midpoints[k], 1e-15);
}

TEST(FemSdsSteps, LineHertzPeakFollowsTheNoTensionLineLoad)
{
  oracle::Ruling ruling;
  ruling.length_m = 2.0;
  ruling.start_radius_m = 0.5;
  ruling.end_radius_m = 1.5;
  const double F = 100, e_star = 200e9 / (1 - 0.09);
  // c = 1/2: uniform q = F / L; R(0.25) = 0.75.
  EXPECT_NEAR(study::line_hertz_peak(F, 0.5, ruling, e_star, 0.25) / std::sqrt(50 * e_star / (std::numbers::pi * 0.75)),
              1.0, 1e-12);
  // c = 0.2: a triangle over the first 3c = 0.6 of the ruling, q(0) = 2 F / (0.6 L),
  // half of it at 0.3 where R = 0.8; nothing beyond 0.6.
  EXPECT_NEAR(study::line_hertz_peak(F, 0.2, ruling, e_star, 0.3)
                  / std::sqrt(F / (0.6 * 2.0) * e_star / (std::numbers::pi * 0.8)),
              1.0, 1e-12);
  EXPECT_EQ(study::line_hertz_peak(F, 0.2, ruling, e_star, 0.7), 0.0);
}

TEST(FemSdsSteps, PeaksMapOntoFacesAsTheirLargestInterpolatedValue)
{
  // Slices at 0.1, 0.5, 0.9 with peaks 1, 3, 2; five points on three faces.
  const std::vector<double> fractions{0.1, 0.5, 0.9}, peaks{1, 3, 2};
  const std::vector<double> along{0.05, 0.3, 0.5, 0.7, 0.95};
  const std::vector<int> faces{4, 4, 7, 9, 9};
  // By hand: 0.05 held at 1; 0.3 halfway, 2; 0.5 is 3; 0.7 halfway, 2.5; 0.95 held at 2.
  const auto mapped = study::peaks_per_face(faces, along, fractions, peaks);
  ASSERT_EQ(mapped.size(), 3u);
  const std::vector<std::pair<int, double>> expected{{4, 2.0}, {7, 3.0}, {9, 2.5}};
  for (std::size_t k = 0; k < expected.size(); ++k)
  {
    EXPECT_EQ(mapped[k].first, expected[k].first);
    EXPECT_NEAR(mapped[k].second, expected[k].second, 1e-12);
  }
}

namespace
{
/// The preprint's template, written out: (1/A) sum_i a_i (x_i / sum x - a_i / A)^2.
double template_score(const std::vector<double>& x, const std::vector<double>& a)
{
  double sum_x = 0, total = 0, score = 0;
  for (std::size_t i = 0; i < x.size(); ++i)
  {
    sum_x += x[i];
    total += a[i];
  }
  for (std::size_t i = 0; i < x.size(); ++i)
    score += a[i] * std::pow(x[i] / sum_x - a[i] / total, 2);
  return score / total;
}
} // namespace

TEST(FemSdsScores, AccumulateOverTheOrientationsIntoTheTemplate)
{
  const Eigen::VectorXd areas = (Eigen::VectorXd(4) << 1, 2, 1, 4).finished();
  const Eigen::VectorXd pressure = (Eigen::VectorXd(4) << 10, 20, 30, 40).finished();
  study::FemSdsOrientation solved, unsolved;
  solved.solved = true;
  solved.locus.oracle_faces = {0, 1};
  solved.fem_faces = {{1, 5.0}, {2, 7.0}};
  solved.line_faces = {{1, 4.0}, {3, 1.0}};
  unsolved.locus.oracle_faces = {2, 3};
  const std::vector<double> a{1, 2, 1, 4};

  const study::FemSdsScores both = study::fem_sds_scores(std::vector{solved, unsolved}, pressure, areas);
  ASSERT_TRUE(both.analytic && both.analytic_all_orientations && both.fem && both.line_hertz);
  EXPECT_NEAR(*both.analytic, template_score({10, 20, 0, 0}, a), 1e-15);
  EXPECT_NEAR(*both.analytic_all_orientations, template_score({10, 20, 30, 40}, a), 1e-15);
  EXPECT_NEAR(*both.fem, template_score({0, 5, 7, 0}, a), 1e-15);
  EXPECT_NEAR(*both.line_hertz, template_score({0, 4, 0, 1}, a), 1e-15);

  // Nothing solved: only the preprint's count over every orientation has a score.
  const study::FemSdsScores none = study::fem_sds_scores(std::vector{unsolved}, pressure, areas);
  EXPECT_FALSE(none.analytic || none.fem || none.line_hertz);
  ASSERT_TRUE(none.analytic_all_orientations);
  EXPECT_NEAR(*none.analytic_all_orientations, template_score({0, 0, 30, 40}, a), 1e-15);
  // Solved, yet no FEM peak on any face: no distribution, +infinity.
  solved.fem_faces.clear();
  EXPECT_EQ(*study::fem_sds_scores(std::vector{solved}, pressure, areas).fem, std::numeric_limits<double>::infinity());
}

TEST(FemSds, OnlyTheExactHullsOfCirclesAreInputs)
{
  study::FemSdsSettings settings;
  settings.body.mesh_file = "oloid.obj";
  EXPECT_THROW(study::run_fem_sds(MPI_COMM_WORLD, settings), InputError);
  settings.body.mesh_file.clear();
  settings.body.body = "sphere";
  EXPECT_THROW(study::run_fem_sds(MPI_COMM_WORLD, settings), InputError);
}

TEST(FemSds, CylinderSlicesMeetLineHertzOfItsUniformGenerator)
{
  study::FemSdsSettings settings; // rolling oracle, r = 1 m, height 2 m, steel, F = 100 N
  settings.body.body = "cylinder";
  settings.orientations = 3;
  settings.fem_slices = 3;
  const study::FemSdsResult result = study::run_fem_sds(MPI_COMM_WORLD, settings);
  const double L = settings.body.height_m, R = settings.body.radius_m;
  const double e_star = settings.youngs_modulus_pa / (1 - settings.poisson_ratio * settings.poisson_ratio);
  const double p0 = std::sqrt(settings.normal_load_n / L * e_star / (std::numbers::pi * R));
  EXPECT_NEAR(result.effective_modulus_pa / e_star, 1.0, 1e-15);
  ASSERT_EQ(result.orientations.size(), 3u);
  EXPECT_EQ(result.fem_solved, 3u);
  EXPECT_EQ(result.reaching_crease, 3u); // the generator runs rim to rim
  for (const study::FemSdsOrientation& r : result.orientations)
  {
    ASSERT_TRUE(r.solved);
    EXPECT_NEAR(r.locus.centre_of_pressure, 0.5, 1e-6);
    ASSERT_EQ(r.slices.size(), 3u);
    EXPECT_NEAR(r.line_hertz_peak_pa / p0, 1.0, 1e-9);
    EXPECT_NEAR(r.fem_peak_pa / p0, 1.0, 5e-3);
    EXPECT_LT(std::abs(r.fem_peak_refined_pa / r.fem_peak_pa - 1), 3e-2);
    EXPECT_NEAR(r.contact_length_m, L, 1e-9);
    EXPECT_FALSE(r.fem_faces.empty());
  }
  // Uniform pressure along the generator: FEM-SDS equals line-Hertz SDS to the FEM's accuracy.
  ASSERT_TRUE(result.sds.fem && result.sds.line_hertz);
  EXPECT_NEAR(*result.sds.fem / *result.sds.line_hertz, 1.0, 5e-3);

  const nlohmann::json j = study::to_json(result);
  EXPECT_EQ(j.at("fem_sds").get<double>(), *result.sds.fem);
  EXPECT_EQ(j.at("oracle"), "rolling");
  EXPECT_EQ(j.at("per_orientation").at(1).at("index"), 1);
  EXPECT_EQ(j.at("per_orientation").at(1).at("fem_peak_pa").get<double>(), result.orientations[1].fem_peak_pa);
  EXPECT_EQ(j.at("per_orientation").at(0).at("slices").size(), 3u);
}
