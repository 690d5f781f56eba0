// The rim end on a block of the body's own steel (fem/rim_end_contact.h,
// counter-face block): the square end, not singular on the rigid plane, is
// singular against the elastic block, growing with the exponent of the
// elastic wedge on the half-plane (contact/edge_on_elastic_block_exponent.h:
// -0.226 for like materials). Measured: -0.222 over four levels (about 100 s
// on one process; label long). On the world communicator: CTest runs it on 1
// and on 2 processes (test_rim_block_contact_2_ranks), where the pairs' twins
// lie on different ranks.
#include "contact/edge_on_elastic_block_exponent.h"
#include "fem/rim_end_contact.h"
#include <cstdio>
#include <gtest/gtest.h>
#include <mpi.h>
#include <numbers>

using namespace rollcheck;

TEST(RimBlockContact, SquareEndOnSteelIsSingularAsTheElasticWedge)
{
  fem::RimEndSettings s;
  s.counter_face = fem::CounterFace::block;
  s.levels = 4;
  const fem::RimEndStudy study = fem::solve_rim_end(MPI_COMM_WORLD, s);
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank == 0)
  {
    for (const fem::RimEndLevel& l : study.levels)
      std::printf("h_e/b %.4f dofs %ld edge/far %.4f wall %.1f s\n", l.edge_element_m / study.half_width_m,
                  static_cast<long>(l.dofs), l.edge_pressure_pa / l.far_peak_pa, l.wall_s);
    std::printf("measured exponent %.4f, wedge %.4f\n", study.measured_exponent.value_or(0.0), study.wedge_exponent);
  }
  EXPECT_TRUE(study.singular);
  EXPECT_NEAR(study.wedge_exponent,
              contact::edge_on_elastic_block_exponent(std::numbers::pi / 2, 200e9, 0.3, 200e9, 0.3), 1e-12);
  ASSERT_TRUE(study.measured_exponent.has_value());
  EXPECT_NEAR(*study.measured_exponent / study.wedge_exponent, 1.0, 0.1);
  // The far side carries line Hertz between the two bodies (E* halved).
  EXPECT_LT(study.plane_strain_change, 3 * study.plane_strain_noise);
}
