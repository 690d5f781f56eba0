#pragma once
// Independent small problems shared out over the ranks of a communicator:
// rank r solves items r, r + size, ... on its own (MPI_COMM_SELF), and every
// rank gets every item's result, packed as a fixed number of doubles (the
// plane-strain slices, fem/scenes/slice_contact.h; the body's sections,
// fem/scenes/section_contact.h).
#include <cstddef>
#include <functional>
#include <mpi.h>
#include <string>
#include <vector>

namespace rollcheck::fem
{
/// Item i's packed result at [i * packed_size, (i + 1) * packed_size) (zeros
/// where `solve` is not called: items `skip` says yes to). A failure on any
/// rank is a ComputationError on every rank, naming the item
/// (`describe(i)`) and the problem (`what`).
std::vector<double> share_out(MPI_Comm comm, std::size_t count, std::size_t packed_size,
                              const std::function<std::vector<double>(std::size_t)>& solve,
                              const std::function<std::string(std::size_t)>& describe, const std::string& what,
                              const std::function<bool(std::size_t)>& skip = {});
} // namespace rollcheck::fem
