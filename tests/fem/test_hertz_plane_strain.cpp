// Plane-strain penalty-contact FEM of a cylinder on a rigid plane against
// Hertz line contact: b and p0 within 0.5 % (Hertz from the reaction force
// per unit length), subsurface maxima and depths within 3 %, at the defaults
// and for another body and load without retuning.
#include "contact/hertz.h"
#include "fem/hertz_expectations.h"
#include "fem/scenes/scenes.h"
#include <cmath>
#include <gtest/gtest.h>

using namespace rollcheck;

namespace
{
using test::error;

void expect_verified(const fem::HertzResult& r)
{
  // Hertz at the force per length the FEM actually carries (reaction), not
  // at the prescribed approach, which line contact does not determine.
  const contact::LineHertz h = contact::line_contact(r.load_reaction, r.setup.radius_m, r.hertz.effective_modulus_pa,
                                                     r.setup.poisson_ratio);
  EXPECT_LT(error(r.contact_size_m, h.half_width_m), 0.005);
  EXPECT_LT(error(r.peak_pressure_pa, h.peak_pressure_pa), 0.005);
  test::expect_balanced_with_hertz_subsurface(r, h.max_shear_pa, h.max_shear_depth_m, h.max_von_mises_pa,
                                              h.max_von_mises_depth_m);
}

fem::HertzSettings cylinder()
{
  fem::HertzSettings s;
  s.model = fem::Model::plane_strain;
  return s;
}
} // namespace

TEST(HertzPlaneStrain, SteelRollerDefaultP1) { expect_verified(fem::solve_hertz(MPI_COMM_WORLD, cylinder())); }

TEST(HertzPlaneStrain, SteelRollerDefaultP2)
{
  fem::HertzSettings s = cylinder();
  s.degree = 2;
  expect_verified(fem::solve_hertz(MPI_COMM_WORLD, s));
}

TEST(HertzPlaneStrain, AnotherRollerAndLoadWithTheSameDefaults)
{
  fem::HertzSettings s = cylinder();
  s.radius_m = 0.04;
  s.youngs_modulus_pa = 110e9; // bronze-like
  s.poisson_ratio = 0.34;
  s.force_n = 3000;
  s.length_m = 0.05;
  expect_verified(fem::solve_hertz(MPI_COMM_WORLD, s));
}
