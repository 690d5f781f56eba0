#pragma once
// Stratified sampling of an oracle run: the index range [0, n) is cut into k
// strata of equal width and one index is drawn uniformly in each, so that the
// k picks cover the whole trajectory (no two in one stratum) yet are not a
// fixed lattice that could alias with the motion's period (W. G. Cochran,
// "Sampling Techniques", 3rd ed., Wiley 1977, ch. 5). The draws come from
// std::mt19937_64 seeded with `seed` through an explicit integer map (not
// std::uniform_int_distribution, whose algorithm the standard leaves open), so
// a seed gives the same picks with every compiler and library.
#include <cstdint>
#include <vector>

namespace rollcheck::oracle
{
/// k increasing indices in [0, n); InputError when k < 1 or k > n.
std::vector<std::size_t> stratified_samples(std::size_t n, std::size_t k, std::uint64_t seed);
} // namespace rollcheck::oracle
