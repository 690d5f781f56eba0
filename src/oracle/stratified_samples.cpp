#include "oracle/stratified_samples.h"
#include "core/error.h"
#include <fmt/format.h>
#include <random>

namespace rollcheck::oracle
{
std::vector<std::size_t> stratified_samples(std::size_t n, std::size_t k, std::uint64_t seed)
{
  if (k < 1 || k > n)
    throw InputError(fmt::format("stratified sampling: {} orientations asked of a trajectory of {} samples "
                                 "(need 1 <= orientations <= samples)",
                                 k, n));
  std::mt19937_64 engine(seed);
  std::vector<std::size_t> picks(k);
  for (std::size_t j = 0; j < k; ++j)
  {
    // Stratum j is [floor(j n / k), floor((j + 1) n / k)), never empty as k <= n.
    const std::size_t first = j * n / k, width = (j + 1) * n / k - first;
    // A 53-bit uniform in [0, 1) scaled to the stratum.
    const double u = static_cast<double>(engine() >> 11) * 0x1.0p-53;
    picks[j] = first + std::min(width - 1, static_cast<std::size_t>(u * static_cast<double>(width)));
  }
  return picks;
}
} // namespace rollcheck::oracle
