// The rim end scene (fem/rim_end_contact.h) on the rigid plane: a square end
// is finite and converges, an obtuse sharp rim is singular with the growth
// exponent of Williams's mirrored wedge, a rounded obtuse rim converges.
#include "contact/wedge_exponent.h"
#include "fem/rim_end_contact.h"
#include <cmath>
#include <cstdio>
#include <gtest/gtest.h>
#include <mpi.h>
#include <numbers>

using namespace rollcheck;

namespace
{
constexpr double degree = std::numbers::pi / 180;

void print(const fem::RimEndStudy& study)
{
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank != 0)
    return;
  for (const fem::RimEndLevel& l : study.levels)
    std::printf("h_e/b %.4f dofs %ld far/p0 %.4f (scatter %.3f) mid/far %.4f end/far %.4f at x/b %.3f edge/far "
                "%.4f wall %.1f\n",
                l.edge_element_m / study.half_width_m, static_cast<long>(l.dofs), l.far_peak_pa / study.hertz_peak_pa,
                l.far_scatter, l.mid_peak_pa / l.far_peak_pa, l.end_peak_pa / l.far_peak_pa,
                l.end_peak_x_m / study.half_width_m, l.edge_pressure_pa / l.far_peak_pa, l.wall_s);
  std::printf("wedge %.4f measured %.4f\n", study.wedge_exponent, study.measured_exponent.value_or(std::nan("")));
}
} // namespace

TEST(RimEndContact, SquareEndIsFiniteAndConverges)
{
  fem::RimEndSettings s;
  const fem::RimEndStudy study = fem::solve_rim_end(MPI_COMM_WORLD, s);
  print(study);
  EXPECT_FALSE(study.singular);
  ASSERT_TRUE(study.end_peak_change.has_value());
  EXPECT_TRUE(study.converged) << *study.end_peak_change;
  EXPECT_LT(study.plane_strain_change, 0.01);
  // The free end lowers the pressure at the edge (0.26-0.30 of the far side's
  // measured) and refining does not make it grow, as a singular edge's would.
  ASSERT_TRUE(study.measured_exponent.has_value());
  EXPECT_GT(*study.measured_exponent, -0.05);
  EXPECT_LT(study.levels.back().edge_pressure_pa, study.levels.back().far_peak_pa);
}

TEST(RimEndContact, ObtuseSharpRimGrowsAsTheWedge)
{
  fem::RimEndSettings s;
  s.interior_angle_rad = 120 * degree;
  s.levels = 4;
  const fem::RimEndStudy study = fem::solve_rim_end(MPI_COMM_WORLD, s);
  print(study);
  EXPECT_TRUE(study.singular);
  ASSERT_TRUE(study.measured_exponent.has_value());
  EXPECT_NEAR(*study.measured_exponent / study.wedge_exponent, 1.0, 0.1);
}

TEST(RimEndContact, RoundedObtuseRimConverges)
{
  fem::RimEndSettings s;
  s.interior_angle_rad = 120 * degree;
  const fem::RimEndStudy probe = fem::solve_rim_end(MPI_COMM_WORLD, {.levels = 1});
  s.edge_radius_m = 0.5 * probe.half_width_m;
  // The fillet (an arc of 60 deg, b / 4 long) gets 4 elements at the first level.
  s.edge_element_over_half_width = 1.0 / 16;
  const fem::RimEndStudy study = fem::solve_rim_end(MPI_COMM_WORLD, s);
  print(study);
  EXPECT_FALSE(study.singular);
  EXPECT_TRUE(study.converged) << study.end_peak_change.value_or(std::nan(""));
}
