#pragma once
// Wing of the study layer (study/robustness): whether a comparison of two
// bodies survives the modelling choices behind it.
//
// A grid of modelling choices (each a name and its values, in an order where
// neighbours are comparable: rolling energies ascending, margins ascending)
// and a ratio r(cell) = score(A) / score(B) of two bodies at each cell
// (lower scores are more uniform, so r < 1 ranks A first). The comparison is
// robust when every defined cell ranks the bodies alike; otherwise it depends
// on the choices along which a neighbouring pair of defined cells (undefined
// cells between them skipped) ranks them
// differently, and each such pair is a flip: the choice, the two values it
// lies between and the other choices' values there.
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace rollcheck::study::robustness
{
struct Choice
{
  std::string name;                ///< e.g. "rolling_energy"
  std::vector<std::string> values; ///< as written in the JSON, e.g. "0.36", "uniform_rate"
};

/// One value index per choice.
using Cell = std::vector<int>;

/// Every cell of the grid, the last choice varying fastest.
std::vector<Cell> grid_cells(const std::vector<Choice>& grid);

struct Flip
{
  int choice = 0;
  int from = 0, to = 0; ///< value indices of the neighbouring defined cells (to = from + 1 unless undefined cells lie between)
  Cell cell;            ///< the cell at `from`
  std::optional<double> value; ///< where the ranking changes, when the caller refines it
};

struct Verdict
{
  bool robust = true;
  std::string text;    ///< "robust", "depends on CHOICE[, CHOICE]", or "cannot be tested" (no cell defined)
  double ratio_min = 0, ratio_max = 0;
  int cells = 0;       ///< cells where the ratio is defined
  std::vector<Flip> flips;
};

/// The verdict of `ratio` over the grid; cells where it is nullopt (a model
/// that does not apply there) are left out.
Verdict judge_comparison(const std::vector<Choice>& grid, const std::function<std::optional<double>(const Cell&)>& ratio);
} // namespace rollcheck::study::robustness
