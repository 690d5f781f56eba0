#include "audit/search_grid.h"
#include "audit/cell_values.h"
#include "core/error.h"
#include <algorithm>
#include <cmath>
#include <fmt/format.h>

namespace rollcheck::audit
{
std::string genome_pointer(const CommandOutput& search, const Genome& g)
{
  const nlohmann::json& genomes = search.at("/genomes");
  for (std::size_t i = 0; i < genomes.size(); ++i)
    if (std::abs(genomes[i]["theta_deg"].get<double>() - g.theta_deg) < 1e-9 &&
        std::abs(genomes[i]["offset"].get<double>() - g.offset) < 1e-9 &&
        std::abs(genomes[i]["ratio"].get<double>() - g.ratio) < 1e-9)
      return fmt::format("/genomes/{}", i);
  throw ComputationError(fmt::format("`{}` has no genome {}", search.command(), genome_text(g)));
}

Genome genome_at(const CommandOutput& search, const std::string& pointer)
{
  return {search.at(pointer + "/theta_deg").get<double>(), search.at(pointer + "/offset").get<double>(),
          search.at(pointer + "/ratio").get<double>()};
}

std::vector<std::pair<double, std::string>> revalidated_by_cds(CommandOutput& search)
{
  std::vector<std::pair<double, std::string>> ranked;
  for (std::size_t g = 0; g < search.at("/genomes").size(); ++g)
  {
    const std::string genome = fmt::format("/genomes/{}", g);
    if (search.at(genome + "/validated").get<bool>() && !search.at(genome + "/is_anchor_genome").get<bool>())
      ranked.emplace_back(search.number(genome + "/rigid/cds"), genome);
  }
  std::sort(ranked.begin(), ranked.end());
  return ranked;
}
} // namespace rollcheck::audit
