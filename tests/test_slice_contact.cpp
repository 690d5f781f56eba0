// Plane-strain slices of a line contact (fem/slice_contact.h) against the
// closed-form line-contact Hertz of each slice, K. L. Johnson, "Contact
// Mechanics", 1985, eq. 4.43-4.45: b = sqrt(4 q R / (pi E*)),
// p0 = sqrt(q E* / (pi R)), E* = E / (1 - nu^2) on a rigid plane.
#include "fem/petsc_session.h"
#include "fem/slice_contact.h"
#include "core/error.h"
#include <cmath>
#include <gtest/gtest.h>
#include <numbers>

using namespace rollcheck;

TEST(SliceContact, EverySliceMeetsLineHertzAndTheFinerLevelAgrees)
{
  // Slices of the oloid's size (R ~ 0.3 to 1.5 m, q ~ 10 to 100 N/m) and an unloaded one.
  const std::vector<fem::SliceLoad> loads{{0.1, 0.3, 80.0}, {0.5, 1.5, 12.0}, {0.9, 0.8, 0.0}};
  const fem::SliceSettings settings;
  const std::vector<fem::SliceFem> slices = fem::solve_slices(MPI_COMM_WORLD, loads, settings);
  ASSERT_EQ(slices.size(), 3u);
  const double e_star = settings.youngs_modulus_pa / (1 - settings.poisson_ratio * settings.poisson_ratio);
  for (int k = 0; k < 2; ++k)
  {
    const fem::SliceFem& s = slices[static_cast<std::size_t>(k)];
    const double q = loads[k].load_n_per_m, R = loads[k].radius_m;
    const double p0 = std::sqrt(q * e_star / (std::numbers::pi * R));
    const double b = std::sqrt(4 * q * R / (std::numbers::pi * e_star));
    EXPECT_NEAR(s.hertz_peak_pressure_pa / p0, 1.0, 1e-12);
    EXPECT_NEAR(s.hertz_half_width_m / b, 1.0, 1e-12);
    // The Hertz plane-strain verification's accuracy (README "Hertz FEM": p0 within 0.1 %, b within 0.1 %).
    EXPECT_NEAR(s.peak_pressure_pa / p0, 1.0, 5e-3) << "slice " << k;
    EXPECT_NEAR(s.half_width_m / b, 1.0, 5e-3) << "slice " << k;
    EXPECT_LT(std::abs(s.refinement_change()), 3e-3) << "slice " << k;
    EXPECT_GT(s.refined_dofs, s.dofs);
    EXPECT_GT(s.newton_iterations, 0);
  }
  EXPECT_EQ(slices[2].peak_pressure_pa, 0.0);
  EXPECT_EQ(slices[2].dofs, 0);
}

TEST(SliceContact, ANonFiniteRadiusIsRejected)
{
  const std::vector<fem::SliceLoad> loads{{0.0, -1.0, 10.0}};
  EXPECT_THROW(fem::solve_slices(MPI_COMM_WORLD, loads, {}), ComputationError);
}
