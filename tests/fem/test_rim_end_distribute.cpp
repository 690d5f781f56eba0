// The rim end's meshes distributed with the idle ranks asleep
// (fem/mesh/rim_end_distribute.h): the same mesh as distribute, and rank 0's
// failure raised on every rank with its kind and message.
#include "core/error.h"
#include "fem/mesh/rim_end_distribute.h"
#include "fem/petsc_session.h"
#include <dolfinx/common/IndexMap.h>
#include <gtest/gtest.h>
#include <mpi.h>
#include <string>

using namespace rollcheck;

namespace
{
/// The unit tetrahedron: 4 nodes, 1 cell.
fem::RawMesh unit_tetrahedron()
{
  return {{0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1}, {0, 1, 2, 3}};
}

std::int64_t global_cells(const fem::SceneMesh& scene)
{
  return scene.mesh->topology().index_map(3)->size_global();
}
} // namespace

TEST(RimEndDistribute, GivesTheMeshDistributeGives)
{
  fem::ensure_petsc(); // MPI too
  const fem::SceneMesh quiet = fem::scene_build::distribute_quietly(MPI_COMM_WORLD, 3, unit_tetrahedron);
  const fem::SceneMesh plain = fem::scene_build::distribute(MPI_COMM_WORLD, 3, unit_tetrahedron);
  EXPECT_EQ(global_cells(quiet), 1);
  EXPECT_EQ(global_cells(quiet), global_cells(plain));
  EXPECT_EQ(quiet.mesh->geometry().index_map()->size_global(), 4);
}

TEST(RimEndDistribute, RankZerosFailureIsRaisedOnEveryRank)
{
  fem::ensure_petsc();
  auto fails_with = [](auto error) {
    return [error]() -> fem::RawMesh { throw error; };
  };
  try
  {
    fem::scene_build::distribute_quietly(MPI_COMM_WORLD, 3, fails_with(InputError("bad fillet")));
    ADD_FAILURE() << "no InputError";
  }
  catch (const InputError& e)
  {
    EXPECT_NE(std::string(e.what()).find("bad fillet"), std::string::npos) << e.what();
  }
  EXPECT_THROW(fem::scene_build::distribute_quietly(MPI_COMM_WORLD, 3, fails_with(ComputationError("gmsh failed"))),
               ComputationError);
}
