// What `rollcheck optimize --score fem-sds` and `fem-sds-template` minimise
// (study/loop_scores/fem_sds_family.h fem_sds_scorer, FemSdsValue): the
// continuum value is the body's, not its mesh's: a genome meshed with twice
// the points per circle keeps it within 1 %, while the per-face template
// falls with the face count (about faces^-2), which at fixed points per
// circle moves with the genome.
#include "fem/petsc_session.h"
#include "study/loop_scores/fem_sds_family.h"
#include <cmath>
#include <cstdio>
#include <gtest/gtest.h>
#include <mpi.h>

using namespace rollcheck;
using study::loop_scores::FemSdsValue;

TEST(FemSdsScoreValue, ContinuumHoldsWhenTheMeshDoublesAndTheTemplateFalls)
{
  fem::ensure_petsc();
  const study::loop_scores::FemSdsSettings base;
  auto continuum = study::loop_scores::fem_sds_scorer(MPI_COMM_WORLD, base, FemSdsValue::continuum);
  auto face_template = study::loop_scores::fem_sds_scorer(MPI_COMM_WORLD, base, FemSdsValue::face_template);
  geometry::BodySpec body;
  body.body = "roller";
  body.family = geometry::RollerFamily::centre_line;
  body.genome = {112.7, 1.0, 1.0, 2};
  double value[2][2];
  for (int k = 0; k < 2; ++k)
  {
    body.points = 60 * (k + 1);
    value[0][k] = continuum(body);
    value[1][k] = face_template(body);
  }
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank == 0)
    std::printf("continuum %.6g -> %.6g, template %.6g -> %.6g (60 -> 120 points per circle)\n", value[0][0],
                value[0][1], value[1][0], value[1][1]);
  ASSERT_TRUE(std::isfinite(value[0][0]) && std::isfinite(value[1][0]));
  EXPECT_LT(std::abs(value[0][1] / value[0][0] - 1), 0.01);
  EXPECT_LT(value[1][1] / value[1][0], 0.5); // about (1 / 2)^2
}
