// The 3D slab of a contact ruling (fem/scenes/slab_contact.h) against the plane-strain
// slices it generalises, on a cylinder R = 10 mm, L = 20 mm under the
// preprint's 100 N (steel on a rigid plane): in the middle of the ruling the
// slab must reproduce the slices (plane strain holds there, b / L ~ 1e-3) and
// the closed-form line Hertz p0 = sqrt(q E* / (pi R)) (K. L. Johnson,
// "Contact Mechanics", 1985, eq. 4.45). At the ends the curved surface meets
// the flat end faces at a right angle; mirrored in the rigid frictionless
// plane that corner is a straight free boundary, not a singular wedge, and
// the free end face is more compliant than the plane-strain middle: the end
// pressure must stay below the middle's at both levels (a singular edge
// would exceed it and grow). End faces that overhang make obtuse edges, which
// are singular: there the end peak must exceed the middle's and grow.
#include "fem/scenes/slab_contact.h"
#include "fem/scenes/slice_contact.h"
#include "core/error.h"
#include <cmath>
#include <cstdio>
#include <gtest/gtest.h>
#include <numbers>

using namespace rollcheck;

namespace
{
constexpr double radius = 0.01, length = 0.02, force = 100.0;

std::vector<fem::SliceFem> cylinder_slices()
{
  const std::vector<fem::SliceLoad> loads{
      {0.25 * length, radius, force / length}, {0.5 * length, radius, force / length}, {0.75 * length, radius, force / length}};
  return fem::solve_slices(MPI_COMM_WORLD, loads, {});
}
} // namespace

TEST(SlabContact, MiddleMatchesTheSlicesAndTheSquareEndIsNotSingular)
{
  const std::vector<fem::SliceFem> slices = cylinder_slices();
  fem::SlabSettings settings;
  settings.refine = 0;
  const double e_star = settings.youngs_modulus_pa / (1 - settings.poisson_ratio * settings.poisson_ratio);
  const double p0 = std::sqrt(force / length * e_star / (std::numbers::pi * radius));

  const fem::SlabFem coarse = fem::solve_slab(MPI_COMM_WORLD, {length, radius, radius, force}, slices, settings);
  fem::SlabSettings finer = settings;
  finer.refine = coarse.refine + 1;
  const fem::SlabFem fine = fem::solve_slab(MPI_COMM_WORLD, {length, radius, radius, force}, slices, finer);
  for (const fem::SlabFem* slab : {&coarse, &fine})
  {
    EXPECT_NEAR(slab->force_n / force, 1.0, 1e-3);
    EXPECT_NEAR(slab->centre_of_pressure, 0.5, 1e-3);
    // Same top profile and force as the slices: plane strain holds in the middle.
    EXPECT_NEAR(slab->approach_factor, 1.0, 0.02);
    EXPECT_NEAR(slab->slice_peak_pressure_pa[1] / slices[1].peak_pressure_pa, 1.0, 0.02);
    EXPECT_NEAR(slab->slice_peak_pressure_pa[1] / p0, 1.0, 0.02);
    for (double end : slab->end_peak_pressure_pa)
      EXPECT_LT(end, 0.8 * slab->slice_peak_pressure_pa[1]);
  }
  EXPECT_GT(fine.dofs, coarse.dofs);
  EXPECT_LT(fine.end_layer_m, coarse.end_layer_m);
  EXPECT_NEAR(fine.slice_peak_pressure_pa[1] / coarse.slice_peak_pressure_pa[1], 1.0, 0.02);
  std::printf("slab middle %.5g / %.5g Pa (slice %.5g, Hertz %.5g), ends %.4g %.4g / %.4g %.4g Pa, approach %.4f %.4f\n",
              coarse.slice_peak_pressure_pa[1], fine.slice_peak_pressure_pa[1], slices[1].peak_pressure_pa, p0,
              coarse.end_peak_pressure_pa[0], coarse.end_peak_pressure_pa[1], fine.end_peak_pressure_pa[0],
              fine.end_peak_pressure_pa[1], coarse.approach_factor, fine.approach_factor);
}

TEST(SlabContact, AnOverhangingEndIsSingular)
{
  // End faces leaning out by 30 deg: edges of 120 deg, mirrored a re-entrant
  // 240 deg free-free wedge, singular as r^-0.385 (Williams' eigenvalue 0.615):
  // the end peak exceeds the middle's and grows under refinement.
  const std::vector<fem::SliceFem> slices = cylinder_slices();
  const fem::SlabBody body{length, radius, radius, force, {std::numbers::pi / 6, std::numbers::pi / 6}};
  fem::SlabSettings settings;
  settings.refine = 0;
  const fem::SlabFem coarse = fem::solve_slab(MPI_COMM_WORLD, body, slices, settings);
  settings.refine = 1;
  const fem::SlabFem fine = fem::solve_slab(MPI_COMM_WORLD, body, slices, settings);
  std::printf("overhang: middle %.5g / %.5g Pa, ends %.5g %.5g / %.5g %.5g Pa\n", coarse.slice_peak_pressure_pa[1],
              fine.slice_peak_pressure_pa[1], coarse.end_peak_pressure_pa[0], coarse.end_peak_pressure_pa[1],
              fine.end_peak_pressure_pa[0], fine.end_peak_pressure_pa[1]);
  EXPECT_NEAR(coarse.force_n / force, 1.0, 1e-3);
  EXPECT_NEAR(fine.slice_peak_pressure_pa[1] / slices[1].peak_pressure_pa, 1.0, 0.02);
  // Per level the singular peak should grow by sqrt(2)^0.385 = 1.14; the
  // tetrahedra at the two ends are split differently, so single ends scatter
  // (measured: +14 % and +3 %) and the test takes their mean.
  double growth = 0;
  for (int end = 0; end < 2; ++end)
  {
    EXPECT_GT(coarse.end_peak_pressure_pa[end], 3 * coarse.slice_peak_pressure_pa[1]) << "end " << end;
    EXPECT_GT(fine.end_peak_pressure_pa[end], coarse.end_peak_pressure_pa[end]) << "end " << end;
    growth += 0.5 * (fine.end_peak_pressure_pa[end] / coarse.end_peak_pressure_pa[end] - 1);
  }
  EXPECT_GT(growth, 0.05);
}

TEST(SlabContact, BadInputIsRejected)
{
  std::vector<fem::SliceFem> unloaded(1);
  unloaded[0].load = {0.01, radius, 0.0};
  EXPECT_THROW(fem::solve_slab(MPI_COMM_WORLD, {length, radius, radius, force}, unloaded, {}), InputError);
  EXPECT_THROW(fem::solve_slab(MPI_COMM_WORLD, {-length, radius, radius, force}, unloaded, {}), InputError);
  EXPECT_THROW(fem::solve_slab(MPI_COMM_WORLD, {length, radius, NAN, force}, unloaded, {}), InputError);
  // b / R varying 3-fold along the ruling: one extruded section cannot serve it.
  std::vector<fem::SliceFem> uneven(2);
  uneven[0].load = {0.005, radius, 100.0};
  uneven[0].hertz_half_width_m = 1e-3 * radius;
  uneven[1].load = {0.015, radius, 900.0};
  uneven[1].hertz_half_width_m = 3e-3 * radius;
  EXPECT_FALSE(fem::slab_feasible(uneven));
  EXPECT_TRUE(fem::slab_feasible(std::span(uneven).first(1)));
  EXPECT_THROW(fem::solve_slab(MPI_COMM_WORLD, {length, radius, radius, force}, uneven, {}), InputError);
}
