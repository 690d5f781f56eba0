// The rim end's meshes distributed with the other ranks asleep
// (fem/mesh/rim_end_distribute.h).
#include "fem/mesh/rim_end_distribute.h"
#include <chrono>
#include <exception>
#include <thread>

namespace rollcheck::fem::scene_build
{
SceneMesh distribute_quietly(MPI_Comm comm, int gdim, const std::function<RawMesh()>& make_raw)
{
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  RawMesh raw;
  std::exception_ptr failure;
  if (rank == 0)
  {
    try
    {
      raw = make_raw();
    }
    catch (...)
    {
      failure = std::current_exception(); // raised again inside distribute, which tells every rank
    }
  }
  MPI_Request meshed;
  MPI_Ibarrier(comm, &meshed);
  for (int done = 0;;)
  {
    MPI_Test(&meshed, &done, MPI_STATUS_IGNORE);
    if (done)
      break;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return distribute(comm, gdim, [&] {
    if (failure)
      std::rethrow_exception(failure);
    return std::move(raw);
  });
}
} // namespace rollcheck::fem::scene_build
