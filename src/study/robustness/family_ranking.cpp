#include "study/robustness/family_ranking.h"
#include "core/json_number.h"
#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <limits>

namespace rollcheck::study::robustness
{
std::vector<geometry::RollerGenome> distinct_bodies(const std::vector<geometry::RollerGenome>& grid)
{
  auto is_mirror = [](const geometry::RollerGenome& a, const geometry::RollerGenome& b) {
    return std::abs(a.theta_deg + b.theta_deg - 180) < 1e-9 && a.offset == b.offset && a.ratio == b.ratio;
  };
  std::vector<geometry::RollerGenome> kept;
  for (const geometry::RollerGenome& g : grid)
    if (g.theta_deg <= 90 || std::none_of(grid.begin(), grid.end(), [&](const auto& m) { return is_mirror(g, m); }))
      kept.push_back(g);
  return kept;
}

std::vector<std::size_t> best_genomes(const std::vector<FamilyGenome>& genomes, std::size_t cell, std::size_t count)
{
  std::vector<std::size_t> scored;
  for (std::size_t g = 0; g < genomes.size(); ++g)
    if (std::isfinite(genomes[g].values[cell]))
      scored.push_back(g);
  std::stable_sort(scored.begin(), scored.end(),
                   [&](std::size_t a, std::size_t b) { return genomes[a].values[cell] < genomes[b].values[cell]; });
  scored.resize(std::min(count, scored.size()));
  return scored;
}

std::optional<double> best_against_rest(const FamilyRanking& r, std::size_t cell)
{
  double worst_best = 0, best_rest = std::numeric_limits<double>::infinity();
  for (const std::size_t g : r.best)
  {
    const double v = r.genomes[g].values[cell];
    if (!std::isfinite(v))
      return std::nullopt;
    worst_best = std::max(worst_best, v);
  }
  for (std::size_t g = 0; g < r.genomes.size(); ++g)
    if (std::find(r.best.begin(), r.best.end(), g) == r.best.end() && std::isfinite(r.genomes[g].values[cell]))
      best_rest = std::min(best_rest, r.genomes[g].values[cell]);
  if (!std::isfinite(best_rest) || r.best.empty())
    return std::nullopt;
  return best_rest > 0 ? worst_best / best_rest : std::numeric_limits<double>::infinity();
}

std::string genome_label(const geometry::RollerGenome& g)
{
  return fmt::format("({:g}, {:g}, {:g})", g.theta_deg, g.offset, g.ratio);
}

nlohmann::json to_json(const FamilyRanking& r, const std::vector<Choice>& grid)
{
  const Cell reference = grid_cells(grid)[r.reference_cell];
  nlohmann::json cell = nlohmann::json::object(), best = nlohmann::json::array(), genomes = nlohmann::json::array();
  for (std::size_t c = 0; c < grid.size(); ++c)
    cell[grid[c].name] = grid[c].values[reference[c]];
  for (const std::size_t g : r.best)
    best.push_back(genome_label(r.genomes[g].genome));
  for (const FamilyGenome& g : r.genomes)
  {
    std::size_t scored = 0;
    for (const double v : g.values)
      scored += std::isfinite(v);
    genomes.push_back({{"theta_deg", g.genome.theta_deg},
                       {"offset", g.genome.offset},
                       {"ratio", g.genome.ratio},
                       {"reference_value", json_number_or_null(g.values[r.reference_cell])},
                       {"cells_scored", scored}});
  }
  return {{"grid", r.grid},       {"score", r.score},   {"reference_cell", cell},
          {"best", best},         {"genomes", genomes}, {"mirrors_merged", r.mirrors_merged}};
}
} // namespace rollcheck::study::robustness
