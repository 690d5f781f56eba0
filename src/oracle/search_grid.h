#pragma once
// The reference code's parametric-search grids (parametric_search.
// build_search_grid) over the paper family of rollers R(theta, d, rho), in its
// order: every (theta, d, rho) with two circles, then, for standard and deep,
// every (theta, d) with three circles and rho = 1; the oloid anchor
// (90, 1, 1, 2) first if missing; duplicates dropped.
//   quick    theta {60, 75, 90, 105, 120}, d {0.7, 1.0, 1.3}, rho {0.8, 1.0, 1.2}: 45 genomes
//   standard theta {55, 65, 75, 80, 85, 90, 95, 100, 105, 115, 125},
//            d {0.5, 0.7, 0.85, 1.0, 1.15, 1.3, 1.5}, rho {0.6, 0.8, 0.9, 1.0, 1.1, 1.2, 1.5}: 616
//   deep     theta {45, 55, 65, 75, 80, 85, 90, 95, 100, 105, 115, 125, 135},
//            d {0.4, 0.6, 0.7, 0.8, 0.9, 1.0, 1.1, 1.2, 1.3, 1.5},
//            rho {0.5, 0.65, 0.8, 0.9, 1.0, 1.1, 1.2, 1.4, 1.7, 2.0}: 1430
#include "geometry/two_circle_roller.h"
#include <string_view>
#include <vector>

namespace rollcheck::oracle
{
enum class SearchGrid
{
  quick,
  standard,
  deep
};

/// InputError naming `origin` unless `name` is quick, standard or deep.
SearchGrid parse_search_grid(std::string_view name, std::string_view origin);
std::string_view name_of(SearchGrid grid);

std::vector<geometry::RollerGenome> search_grid(SearchGrid grid);

/// Approximate-oracle steps of the reference's search: 200 (quick), 300 (others).
long reference_search_steps(SearchGrid grid);

bool is_oloid_anchor(const geometry::RollerGenome& genome);
} // namespace rollcheck::oracle
