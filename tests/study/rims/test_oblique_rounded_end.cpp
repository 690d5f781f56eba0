// The perpendicular reduction of a rounded rim end against the oblique model
// (study/rims/oblique_end.h with an edge radius): the oloid loop's most
// oblique end, filleted alike both ways, at a coarse but resolved size (a
// thick boundary layer, s / b = 2 r_e / (pi R) = 0.16: h_e = s / 4 is b / 25).
// Label long (tests/CMakeLists.txt): about 5 minutes on two loaded cores.
#include "fem/mesh/oblique_end_angle.h"
#include "study/rims/oblique_end.h"
#include <cmath>
#include <cstdio>
#include <gtest/gtest.h>
#include <mpi.h>
#include <string>
#include <vector>

using namespace rollcheck;

namespace
{
/// Where the level's end peak lies beyond the fillet's start, along the edge's normal (m).
double peak_beyond_fillet_start(const fem::RimEndStudy& study)
{
  const fem::RimEndLevel& last = study.levels.back();
  double normal_m = 0, across_m = 0;
  fem::oblique_edge_frame(study.setup.crossing_angle_rad, last.end_peak_x_m, last.end_peak_y_m, normal_m, across_m);
  return normal_m + study.fillet_start_m;
}
} // namespace

TEST(ObliqueRoundedEnd, ReductionAgreesWithinTheModelsTolerance)
{
  study::rims::ObliqueEndSettings s;
  s.body.radius_m = 0.01;
  s.samples = 512;
  s.end.radius_m = 1e-3;
  s.end.load_n_per_m = 1.726e6; // b = 0.1 mm = R / 10
  s.end.edge_radius_m = 2.5e-4; // 2.5 b; the block 10.5 r_e deep
  s.end.levels = 2;
  std::vector<std::string> started; // each model's levels as they start (the CLI's progress beat)
  s.on_model_level = [&](const char* model, int level, double) {
    started.push_back(std::string(model) + " " + std::to_string(level));
  };
  const study::rims::ObliqueEndStudy study = study::rims::oblique_end_study(MPI_COMM_WORLD, s);
  EXPECT_EQ(started, (std::vector<std::string>{"oblique 0", "oblique 1", "perpendicular 0", "perpendicular 1"}));
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank == 0)
    std::printf("%s", study::rims::report(study).c_str());
  ASSERT_TRUE(study.rounded);
  ASSERT_EQ(study.levels.size(), 2U);
  for (const fem::RimEndStudy* model : {&study.oblique, &study.perpendicular})
  {
    // Each model as the rim loop's ends: resolved, converged by its own tolerance.
    EXPECT_TRUE(model->resolved);
    EXPECT_TRUE(model->converged) << "change " << model->end_change.value_or(1);
    // The peak lies on the fillet's boundary layer: within the band of the
    // edge's elements about the fillet's start (+-2 s along the edge's
    // normal), to a node (h_e apart there).
    EXPECT_LE(std::abs(peak_beyond_fillet_start(*model)),
              2 * model->boundary_layer_m + model->levels.back().edge_element_m);
  }
  // Each converged ratio is known within its tolerance, so the two models
  // agree, if the reduction holds, within both tolerances.
  EXPECT_LE(std::abs(study.levels.back().ratio_difference), 2 * s.end.tolerance);
  EXPECT_TRUE(study.difference_bound.has_value()); // the verdict: both converged
}
