// The rim loop's ends by half-space theory (study/rims/loop_half_space_end.h):
// which ends take it, and that the record the loop reads is the half-space
// end's own result (study/rims/half_space_end.h) at the end model's q, R,
// edge, depth and tolerance, on its own two levels.
#include "contact/hertz.h"
#include "core/degree.h"
#include "study/rims/end_table.h"
#include "study/rims/loop_half_space_end.h"
#include <gtest/gtest.h>
#include <numbers>

using namespace rollcheck;

namespace
{
/// A rounded end of R = 4 mm, q = 10 kN/m on steel's rigid plane: b = 15.2 um,
/// r_e = 1 mm = 66 b, its block 20 b deep.
fem::RimEndSettings rounded_end(double angle_deg)
{
  fem::RimEndSettings end;
  end.radius_m = 0.004;
  end.load_n_per_m = 1e4;
  end.edge_radius_m = 1e-3;
  end.interior_angle_rad = angle_deg * rollcheck::degree;
  end.depth_over_half_width = 20;
  end.levels = 3; // the loop's FEM default; the half-space takes its own two
  end.tolerance = 0.03;
  return end;
}
} // namespace

TEST(LoopHalfSpaceEnd, TakesRoundedEndsFromTheAngleWithAFilletOfTwentyHalfWidths)
{
  const double from = 120 * rollcheck::degree;
  EXPECT_TRUE(study::rims::takes_half_space_end(rounded_end(120), from));
  EXPECT_FALSE(study::rims::takes_half_space_end(rounded_end(119.9), from));
  fem::RimEndSettings sharp = rounded_end(150);
  sharp.edge_radius_m = 0;
  EXPECT_FALSE(study::rims::takes_half_space_end(sharp, from));
  // r_e / b just above and below 20: b grows as sqrt(q).
  fem::RimEndSettings end = rounded_end(150);
  const double modulus = contact::effective_modulus_rigid_plane(end.youngs_modulus_pa, end.poisson_ratio);
  const double b = contact::line_contact(end.load_n_per_m, end.radius_m, modulus, end.poisson_ratio).half_width_m;
  const double twenty = end.edge_radius_m / (study::rims::smallest_half_space_edge_over_half_width * b);
  end.load_n_per_m *= twenty * twenty * 0.99;
  EXPECT_TRUE(study::rims::takes_half_space_end(end, from));
  end.load_n_per_m /= 0.98;
  EXPECT_FALSE(study::rims::takes_half_space_end(end, from));
  EXPECT_FALSE(study::rims::takes_half_space_end(rounded_end(179), std::numbers::pi)); // never
  // A block deeper than the half-space end holds (rollcheck rounded-end's --depth bound).
  fem::RimEndSettings deep = rounded_end(150);
  deep.depth_over_half_width = study::rims::largest_held_length_over_half_width * 1.01;
  EXPECT_FALSE(study::rims::takes_half_space_end(deep, from));
}

TEST(LoopHalfSpaceEnd, RecordIsTheHalfSpaceEndsResult)
{
  fem::RimEndSettings end = rounded_end(130);
  end.radius_m = end.edge_radius_m; // R = r_e: the coarsest grid
  const auto [record, half_space] = study::rims::half_space_end_model(end, 1);
  // Solved at the end model's q, R, edge, material, counter-face, depth and tolerance.
  const study::rims::HalfSpaceEndSettings& own = half_space.settings;
  EXPECT_EQ(own.sheet_radius_m, end.radius_m);
  EXPECT_EQ(own.load_n_per_m, end.load_n_per_m);
  EXPECT_EQ(own.edge_radius_m, end.edge_radius_m);
  EXPECT_EQ(own.youngs_modulus_pa, end.youngs_modulus_pa);
  EXPECT_EQ(own.poisson_ratio, end.poisson_ratio);
  EXPECT_FALSE(own.steel_counter_face);
  EXPECT_EQ(half_space.held_length_over_half_width, end.depth_over_half_width);
  EXPECT_EQ(own.tolerance, end.tolerance);
  ASSERT_EQ(half_space.levels.size(), 2U);
  // The record carries its result.
  ASSERT_TRUE(record.end_to_interior.has_value());
  EXPECT_EQ(*record.end_to_interior, half_space.end_to_interior());
  EXPECT_EQ(record.converged, half_space.converged);
  EXPECT_TRUE(record.resolved);
  EXPECT_FALSE(record.singular);
  EXPECT_EQ(record.half_width_m, half_space.half_width_m);
  EXPECT_EQ(record.hertz_peak_pa, half_space.line_hertz_p0_pa);
  ASSERT_EQ(record.levels.size(), 2U);
  // The loop takes an end's peak as its ratio times the far side.
  const fem::RimEndLevel& last = record.levels.back();
  EXPECT_NEAR(*record.end_to_interior * last.far_peak_pa / last.end_peak_pa, 1, 1e-12);
  EXPECT_NEAR(last.end_peak_pa, half_space.peak_pressure_pa(), 1e-9 * half_space.peak_pressure_pa());
  ASSERT_TRUE(record.end_change.has_value());
  EXPECT_LT(std::abs(*record.end_change), end.tolerance);
  // It solved no approach: a neighbour starting from it starts from the
  // estimate (its NaN stopped the preprint-scale loop at its second end).
  EXPECT_EQ(record.approach_over_estimate(), 1.0);
}
