// Independent problems shared out over ranks (fem/share_out.h).
#include "fem/share_out.h"
#include "core/error.h"
#include <algorithm>
#include <fmt/format.h>

namespace rollcheck::fem
{
std::vector<double> share_out(MPI_Comm comm, std::size_t count, std::size_t packed_size,
                              const std::function<std::vector<double>(std::size_t)>& solve,
                              const std::function<std::string(std::size_t)>& describe, const std::string& what,
                              const std::function<bool(std::size_t)>& skip)
{
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  std::vector<double> packed(count * packed_size, 0.0);
  std::string failure;
  for (std::size_t i = rank; i < count && failure.empty(); i += size)
  {
    if (skip && skip(i))
      continue;
    try
    {
      const std::vector<double> values = solve(i);
      if (values.size() != packed_size)
        throw ComputationError(fmt::format("{} values packed, {} expected", values.size(), packed_size));
      std::copy(values.begin(), values.end(), packed.begin() + i * packed_size);
    }
    catch (const std::exception& e)
    {
      failure = fmt::format("{} on rank {}: {}", describe(i), rank, e.what());
    }
  }
  int failed = failure.empty() ? 0 : 1;
  MPI_Allreduce(MPI_IN_PLACE, &failed, 1, MPI_INT, MPI_MAX, comm);
  if (failed)
    throw ComputationError(failure.empty() ? what + " failed on another rank" : what + " failed: " + failure);
  MPI_Allreduce(MPI_IN_PLACE, packed.data(), static_cast<int>(packed.size()), MPI_DOUBLE, MPI_SUM, comm);
  return packed;
}
} // namespace rollcheck::fem
