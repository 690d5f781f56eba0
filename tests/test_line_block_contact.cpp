// The node-to-node penalty between two elastic bodies (fem/penalty_contact.h
// NodePair) on line Hertz between like steel bodies: b and p0 within 0.5 %
// of K. L. Johnson's (1985, sec. 4.2) with E* = E / (2 (1 - nu^2)). On the
// world communicator: under mpirun the twins lie on different processes
// (CTest runs it on 2 too: line_block_contact_2_ranks).
#include "fem/line_block_contact.h"
#include <cstdio>
#include <gtest/gtest.h>
#include <mpi.h>

using namespace rollcheck;

TEST(LineBlockContact, TwoSteelBodiesMeetLineHertz)
{
  const fem::LineBlockResult r = fem::solve_line_block(MPI_COMM_WORLD, {});
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank == 0)
    std::printf("pairs %d dofs %ld b/b_H %.5f p0/p0_H %.5f q %.6g %.1f s\n", r.pairs, static_cast<long>(r.dofs),
                r.half_width_m / r.hertz_half_width_m, r.peak_pressure_pa / r.hertz_peak_pressure_pa,
                r.force_n_per_m, r.wall_s);
  EXPECT_NEAR(r.force_n_per_m / 1e4, 1.0, 1e-5);
  EXPECT_NEAR(r.half_width_m / r.hertz_half_width_m, 1.0, 0.005);
  EXPECT_NEAR(r.peak_pressure_pa / r.hertz_peak_pressure_pa, 1.0, 0.005);
}
