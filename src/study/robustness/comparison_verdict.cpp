#include "study/robustness/comparison_verdict.h"
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace rollcheck::study::robustness
{
std::vector<Cell> grid_cells(const std::vector<Choice>& grid)
{
  std::vector<Cell> cells{Cell(grid.size(), 0)};
  for (int c = static_cast<int>(grid.size()) - 1; c >= 0; --c)
  {
    std::vector<Cell> grown;
    for (const Cell& cell : cells)
      for (int v = 0; v < static_cast<int>(grid[c].values.size()); ++v)
      {
        Cell next = cell;
        next[c] = v;
        grown.push_back(next);
      }
    cells = std::move(grown);
  }
  std::sort(cells.begin(), cells.end());
  return cells;
}

Verdict judge_comparison(const std::vector<Choice>& grid, const std::function<std::optional<double>(const Cell&)>& ratio)
{
  Verdict v;
  std::map<Cell, double> value;
  v.ratio_min = std::numeric_limits<double>::infinity();
  v.ratio_max = -v.ratio_min;
  for (const Cell& cell : grid_cells(grid))
    if (const std::optional<double> r = ratio(cell); r && !std::isnan(*r))
    {
      value[cell] = *r;
      v.ratio_min = std::min(v.ratio_min, *r);
      v.ratio_max = std::max(v.ratio_max, *r);
    }
  v.cells = static_cast<int>(value.size());
  if (value.empty())
  {
    v.robust = false;
    v.text = "cannot be tested";
    return v;
  }
  auto rank = [](double r) { return r < 1 ? -1 : (r > 1 ? 1 : 0); };
  std::vector<bool> flips_on(grid.size(), false);
  for (const auto& [cell, r] : value)
    for (std::size_t c = 0; c < grid.size(); ++c)
    {
      // The next defined cell along choice c: a flip across undefined cells
      // between them is still a flip.
      Cell next = cell;
      auto it = value.end();
      while (it == value.end() && ++next[c] < static_cast<int>(grid[c].values.size()))
        it = value.find(next);
      if (it == value.end() || rank(r) == rank(it->second))
        continue;
      v.flips.push_back({static_cast<int>(c), cell[c], next[c], cell, std::nullopt});
      flips_on[c] = true;
    }
  v.robust = v.flips.empty();
  if (v.robust)
  {
    v.text = "robust";
    return v;
  }
  v.text = "depends on ";
  bool first = true;
  for (std::size_t c = 0; c < grid.size(); ++c)
    if (flips_on[c])
      v.text += (first ? "" : ", ") + grid[c].name, first = false;
  return v;
}
} // namespace rollcheck::study::robustness
