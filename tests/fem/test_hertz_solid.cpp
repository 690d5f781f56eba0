// 3D penalty-contact FEM of the hemisphere (a quarter by symmetry) on a rigid
// plane, serial, at the default settings: a within 1 %, p0 within 2 %, the
// force within 1e-4, subsurface maxima within 3 %. The 2-rank run and its
// equality with this one are tests/cli/hertz_mpi.sh.
#include "fem/hertz_expectations.h"
#include "fem/scenes/scenes.h"
#include <cmath>
#include <gtest/gtest.h>

using namespace rollcheck;

namespace
{
using test::error;
} // namespace

TEST(HertzSolid, SteelHemisphereDefault)
{
  fem::HertzSettings s;
  s.model = fem::Model::solid;
  const fem::HertzResult r = fem::solve_hertz(MPI_COMM_WORLD, s);
  const fem::HertzReference& h = r.hertz;
  EXPECT_LT(error(r.contact_size_m, h.contact_size_m), 0.01);
  EXPECT_LT(error(r.peak_pressure_pa, h.peak_pressure_pa), 0.02);
  test::expect_balanced_with_hertz_subsurface(r, h.max_shear_pa, h.max_shear_depth_m, h.max_von_mises_pa,
                                              h.max_von_mises_depth_m);
  // Krylov: every linear solve converged (a diverged one would have thrown)
  // in a bounded number of AMG-preconditioned iterations.
  EXPECT_LT(r.krylov_iterations, 60 * r.newton_iterations);
}
