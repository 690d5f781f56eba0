#include "oracle/search_grid.h"
#include "core/error.h"
#include <cmath>
#include <fmt/format.h>

namespace rollcheck::oracle
{
SearchGrid parse_search_grid(std::string_view name, std::string_view origin)
{
  if (name == "quick")
    return SearchGrid::quick;
  if (name == "standard")
    return SearchGrid::standard;
  if (name == "deep")
    return SearchGrid::deep;
  throw InputError(fmt::format("{}: unknown grid '{}' (quick, standard or deep)", origin, name));
}

std::string_view name_of(SearchGrid grid)
{
  return grid == SearchGrid::quick ? "quick" : grid == SearchGrid::standard ? "standard" : "deep";
}

bool is_oloid_anchor(const geometry::RollerGenome& g)
{
  return std::abs(g.theta_deg - 90) < 1e-6 && std::abs(g.offset - 1.0) < 1e-6 && std::abs(g.ratio - 1.0) < 1e-6
         && g.n_circles == 2;
}

std::vector<geometry::RollerGenome> search_grid(SearchGrid grid)
{
  std::vector<double> thetas, offsets, ratios;
  bool three_circles = true;
  switch (grid)
  {
  case SearchGrid::quick:
    thetas = {60, 75, 90, 105, 120};
    offsets = {0.7, 1.0, 1.3};
    ratios = {0.8, 1.0, 1.2};
    three_circles = false;
    break;
  case SearchGrid::standard:
    thetas = {55, 65, 75, 80, 85, 90, 95, 100, 105, 115, 125};
    offsets = {0.5, 0.7, 0.85, 1.0, 1.15, 1.3, 1.5};
    ratios = {0.6, 0.8, 0.9, 1.0, 1.1, 1.2, 1.5};
    break;
  case SearchGrid::deep:
    thetas = {45, 55, 65, 75, 80, 85, 90, 95, 100, 105, 115, 125, 135};
    offsets = {0.4, 0.6, 0.7, 0.8, 0.9, 1.0, 1.1, 1.2, 1.3, 1.5};
    ratios = {0.5, 0.65, 0.8, 0.9, 1.0, 1.1, 1.2, 1.4, 1.7, 2.0};
    break;
  }
  std::vector<geometry::RollerGenome> genomes;
  for (double t : thetas)
    for (double d : offsets)
      for (double r : ratios)
        genomes.push_back({t, d, r, 2});
  if (three_circles)
    for (double t : thetas)
      for (double d : offsets)
        genomes.push_back({t, d, 1.0, 3});
  bool has_anchor = false;
  for (const auto& g : genomes)
    has_anchor = has_anchor || is_oloid_anchor(g);
  if (!has_anchor)
    genomes.insert(genomes.begin(), {90.0, 1.0, 1.0, 2});
  std::vector<geometry::RollerGenome> unique;
  for (const auto& g : genomes)
  {
    bool seen = false;
    for (const auto& u : unique)
      seen = seen || (u.theta_deg == g.theta_deg && u.offset == g.offset && u.ratio == g.ratio && u.n_circles == g.n_circles);
    if (!seen)
      unique.push_back(g);
  }
  return unique;
}

long reference_search_steps(SearchGrid grid) { return grid == SearchGrid::quick ? 200 : 300; }
} // namespace rollcheck::oracle
