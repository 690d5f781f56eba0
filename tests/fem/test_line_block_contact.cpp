// The node-to-node penalty between two elastic bodies (fem/penalty_contact.h
// NodePair) on line Hertz between like steel bodies: b and p0 within 0.5 %
// of K. L. Johnson's (1985, sec. 4.2) with E* = E / (2 (1 - nu^2)). On the
// world communicator: under mpirun the twins lie on different processes
// (CTest runs it on 2 too: line_block_contact_2_ranks).
#include "fem/scenes/line_block_contact.h"
#include "fem/penalty_contact.h"
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <gtest/gtest.h>
#include <mpi.h>
#include <vector>

using namespace rollcheck;

TEST(LineBlockContact, TwoSteelBodiesMeetLineHertz)
{
  const rollcheck::fem::LineBlockResult r = rollcheck::fem::solve_line_block(MPI_COMM_WORLD, {});
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

// Twins are found by their place rounded to tol; a pair within tol of each
// other whose rounding falls either side of a cell's boundary (x / tol =
// 3.5 less and more a little) is still one pair, and nodes more than tol
// apart in neighbouring cells stay apart (the U optimum's 170 deg end on
// steel stopped with "1 interface nodes at one place" before).
TEST(InterfaceTwins, APairAcrossARoundingBoundaryIsOnePair)
{
  const double tol = 1e-9;
  const std::vector<double> nodes{
      3.5 * tol - 1e-3 * tol, 0.0, 7, 1e-10,  // the upper twin
      3.5 * tol + 1e-3 * tol, 0.0, 8, 0.0,    // the lower twin, rounded to the next cell
      10 * tol, 0.0, 9, 1e-10,                // a pair in one cell
      10 * tol, 0.0, 10, 0.0,
      20 * tol, 0.0, 11, 0.0,                 // lone nodes 1.2 tol apart in neighbouring cells
      21.2 * tol, 0.0, 12, 0.0};
  std::vector<std::vector<std::int64_t>> groups;
  for (const auto& twins : rollcheck::fem::interface_twins(nodes, tol))
  {
    std::vector<std::int64_t> ids;
    for (const auto& [id, area] : twins)
      ids.push_back(id);
    std::ranges::sort(ids);
    groups.push_back(ids);
  }
  std::ranges::sort(groups);
  EXPECT_EQ(groups, (std::vector<std::vector<std::int64_t>>{{7, 8}, {9, 10}, {11}, {12}}));
}
