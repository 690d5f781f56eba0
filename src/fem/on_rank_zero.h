#pragma once
// Work that only rank 0 can do (gmsh is not parallel here), with its failure
// raised on every rank: the other ranks would otherwise wait in the next
// collective call for a rank that has thrown.
#include "core/error.h"
#include <exception>
#include <mpi.h>
#include <string>

namespace rollcheck::fem
{
/// make() on rank 0; T{} on the others. If it throws, every rank throws the
/// same kind (InputError stays InputError, anything else ComputationError)
/// with rank 0's message.
template <class T, class Make>
T on_rank_zero(MPI_Comm comm, const Make& make)
{
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  T value{};
  int failed = 0;
  std::string message;
  if (rank == 0)
  {
    try
    {
      value = make();
    }
    catch (const InputError& e)
    {
      failed = 2;
      message = e.what();
    }
    catch (const std::exception& e)
    {
      failed = 1;
      message = e.what();
    }
  }
  MPI_Bcast(&failed, 1, MPI_INT, 0, comm);
  if (failed)
  {
    int length = static_cast<int>(message.size());
    MPI_Bcast(&length, 1, MPI_INT, 0, comm);
    message.resize(static_cast<std::size_t>(length));
    MPI_Bcast(message.data(), length, MPI_CHAR, 0, comm);
    if (failed == 2)
      throw InputError(message);
    throw ComputationError(message);
  }
  return value;
}
} // namespace rollcheck::fem
