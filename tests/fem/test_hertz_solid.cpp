// 3D penalty-contact FEM of the hemisphere (a quarter by symmetry) on a rigid
// plane, serial, at the default settings: a within 1 %, p0 within 2 %, the
// force within 1e-4, subsurface maxima within 3 %. The 2-rank run and its
// equality with this one are tests/cli/hertz_mpi.sh.
#include "fem/scenes/scenes.h"
#include <cmath>
#include <gtest/gtest.h>

using namespace rollcheck;

namespace
{
double error(double fem_value, double reference) { return std::abs(fem::relative_error(fem_value, reference)); }
} // namespace

TEST(HertzSolid, SteelHemisphereDefault)
{
  fem::HertzSettings s;
  s.model = fem::Model::solid;
  const fem::HertzResult r = fem::solve_hertz(MPI_COMM_WORLD, s);
  const fem::HertzReference& h = r.hertz;
  EXPECT_LT(error(r.contact_size_m, h.contact_size_m), 0.01);
  EXPECT_LT(error(r.peak_pressure_pa, h.peak_pressure_pa), 0.02);
  EXPECT_LT(error(r.load_reaction, h.load), 1e-4);
  EXPECT_LT(error(r.load_contact, r.load_reaction), 1e-6);
  EXPECT_LT(error(r.max_shear.value, h.max_shear_pa), 0.03);
  EXPECT_LT(error(r.max_shear.depth_m, h.max_shear_depth_m), 0.03);
  EXPECT_LT(error(r.max_von_mises.value, h.max_von_mises_pa), 0.03);
  EXPECT_LT(error(r.max_von_mises.depth_m, h.max_von_mises_depth_m), 0.03);
  EXPECT_TRUE(r.flags.empty());
  // Krylov: every linear solve converged (a diverged one would have thrown)
  // in a bounded number of AMG-preconditioned iterations.
  EXPECT_LT(r.krylov_iterations, 60 * r.newton_iterations);
}
