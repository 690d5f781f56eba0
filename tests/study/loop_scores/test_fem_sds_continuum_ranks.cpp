// The continuum value integrated in parts across the ranks
// (study/loop_scores/fem_sds_continuum.h: each rank its part of the loop's
// samples, the parts' moments summed) against the whole loop integrated by
// one process: the same values to rounding. On one rank the two are one
// computation; the 2-rank run (test_fem_sds_continuum_ranks_2_ranks) is the check.
#include "fem/petsc_session.h"
#include "fem/scenes/slice_scaling.h"
#include "study/loop_scores/fem_sds.h"
#include "study/loop_scores/fem_sds_continuum.h"
#include <gtest/gtest.h>
#include <mpi.h>

using namespace rollcheck;

TEST(FemSdsContinuumRanks, PartsOnTheRanksAddUpToTheWholeLoop)
{
  fem::ensure_petsc();
  study::loop_scores::FemSdsSettings s;
  geometry::BodySpec spec;
  spec.body = "oloid";
  oracle::RollingStudyParameters p;
  p.samples_per_loop = 2000;
  const oracle::RealRolling run = oracle::real_rolling(spec, p);
  const contact::ContinuumLoopSettings settings = study::loop_scores::continuum_settings(s);
  fem::SliceScaling shared(study::loop_scores::slice_settings(s), s.table_nodes_per_decade);
  fem::SliceScaling own(study::loop_scores::slice_settings(s), s.table_nodes_per_decade);
  const study::loop_scores::ContinuumSds parts
      = study::loop_scores::continuum_sds(MPI_COMM_WORLD, run, settings, shared);
  const study::loop_scores::ContinuumSds whole = study::loop_scores::continuum_sds(MPI_COMM_SELF, run, settings, own);
  EXPECT_NEAR(parts.line_hertz / whole.line_hertz, 1.0, 1e-12);
  EXPECT_NEAR(parts.fem / whole.fem, 1.0, 1e-9); // the tables' FEM solves on 2 ranks and on 1
  EXPECT_NEAR(parts.fem_half_table / whole.fem_half_table, 1.0, 1e-9);
  EXPECT_NEAR(parts.fem_coarse / whole.fem_coarse, 1.0, 1e-9);
  EXPECT_EQ(parts.load_ratio_min, whole.load_ratio_min);
  EXPECT_EQ(parts.load_ratio_max, whole.load_ratio_max);
  EXPECT_EQ(parts.nodes_per_decade, whole.nodes_per_decade);
}
