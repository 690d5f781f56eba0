#pragma once
// The rim end's meshes distributed (fem/mesh/rim_end_mesh.h,
// rim_block_mesh.h) with the other ranks asleep while rank 0 runs gmsh.
//
// gmsh runs on rank 0 alone, and a deep rounded end's mesh takes minutes.
// In distribute's broadcast (fem/mesh/scene_parts.h) the other ranks would
// wait in Open MPI's progress loop, each spinning a core at 100 % (half the
// samples of a profile of two ranks: docs/methods/rims.md, "Where a rounded
// loop's time goes"), which on a machine shared with other jobs takes
// processor time from rank 0's mesher. Here they wait in a non-blocking
// barrier tested every 20 ms instead, and join the broadcast once rank 0
// has its mesh.
#include "fem/mesh/scene_parts.h"
#include <functional>
#include <mpi.h>

namespace rollcheck::fem::scene_build
{
/// distribute(comm, gdim, make_raw), the ranks other than 0 asleep while
/// rank 0 runs make_raw; its failure is raised on every rank as distribute
/// raises it.
SceneMesh distribute_quietly(MPI_Comm comm, int gdim, const std::function<RawMesh()>& make_raw);
} // namespace rollcheck::fem::scene_build
