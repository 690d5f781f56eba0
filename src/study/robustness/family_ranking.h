#pragma once
// Wing of the study layer (study/robustness): whether a family's best bodies
// stay its best over the grid of modelling choices.
//
// A genome (theta, d, rho) and its mirror (180 deg - theta, d, rho) are one
// body reflected (the same area, volume, inertia and scores): the ranking
// keeps one of each pair (distinct_bodies), so "the best" are distinct bodies
// and a pair is never split between "the best" and "the rest".
//
// Each genome of a search grid is scored at every cell of the grid (NaN where
// it has no whole loop there: a rim lifts, or it cannot roll over its
// barrier). Its best `count` bodies are those with the lowest scores at the
// reference cell. At a cell where each of them is scored, the ranking's ratio
//     r = max over the best of score / min over the others of score
// is below 1 exactly when the same bodies are the `count` best there (lower
// is more uniform), so the comparison of "the best" against "the rest" is
// judged like a comparison of two bodies (comparison_verdict.h).
#include "geometry/two_circle_roller.h"
#include "study/robustness/comparison_verdict.h"
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace rollcheck::study::robustness
{
struct FamilyGenome
{
  geometry::RollerGenome genome;
  std::vector<double> values; ///< the ranking's score over grid_cells(grid); NaN where not scored
};

struct FamilyRanking
{
  std::string grid;                ///< the search grid's name, e.g. "quick"
  std::string score;               ///< a key of score_names()
  std::size_t reference_cell = 0;  ///< index into grid_cells(grid)
  std::vector<FamilyGenome> genomes;
  std::vector<std::size_t> best;   ///< indices of the best genomes at the reference cell, best first
  std::size_t mirrors_merged = 0;  ///< genomes of the grid left out as the mirror of one kept
};

/// The genomes of `grid` with each mirror pair (theta, d, rho), (180 deg -
/// theta, d, rho) kept once, at theta <= 90 deg.
std::vector<geometry::RollerGenome> distinct_bodies(const std::vector<geometry::RollerGenome>& grid);

/// The `count` genomes with the lowest finite values at `cell`, best first.
std::vector<std::size_t> best_genomes(const std::vector<FamilyGenome>& genomes, std::size_t cell, std::size_t count);

/// The ratio r above at `cell`; none where one of the best is not scored or
/// no other genome is.
std::optional<double> best_against_rest(const FamilyRanking& ranking, std::size_t cell);

/// "(theta, d, rho)" with the grid's digits.
std::string genome_label(const geometry::RollerGenome& genome);

/// {"grid", "score", "reference_cell": {choice: value}, "best": [labels],
///  "genomes": [{theta_deg, offset, ratio, "reference_value"}], "mirrors_merged"}.
nlohmann::json to_json(const FamilyRanking& ranking, const std::vector<Choice>& grid);
} // namespace rollcheck::study::robustness
