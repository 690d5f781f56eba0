// The rules that read `rollcheck search` (the quick grid: its approximate
// screen and rigid-body revalidation) and `rollcheck optimize` outputs.
#include "audit/cell_values.h"
#include "audit/rules.h"
#include "audit/search_grid.h"
#include "core/error.h"
#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <limits>

namespace rollcheck::audit::rules
{
namespace
{
/// A revalidated genome as the cell lists it: "(120, 1.30, 0.80) 8.7e-07 (1.06x)".
std::string revalidated_text(const Genome& g, double cds, double oloid_cds)
{
  return fmt::format("{} {} ({:.2f}x)", genome_text(g), sci(cds), cds / oloid_cds);
}
} // namespace

Rule no_candidate_beats_anchor()
{
  return [](const std::vector<CommandOutput*>& out) {
    CommandOutput& search = *out[0];
    const double anchor = search.number("/anchor/rigid/cds");
    const auto ranked = revalidated_by_cds(search);
    const auto better = std::count_if(ranked.begin(), ranked.end(), [&](const auto& r) { return r.first < anchor; });
    const double best = ranked.empty() ? std::numeric_limits<double>::infinity() : ranked.front().first;
    const std::string best_name = ranked.empty() ? "-" : genome_text(genome_at(search, ranked.front().second));
    CellResult cell{fmt::format("anchor {}; {} of {} better, best {} {:.3f}x", sci(anchor), better, ranked.size(),
                                best_name, best / anchor),
                    better == 0};
    // Where the anchor is meshed apart from the candidates, its CDS on their
    // mesh (a second search's anchor) says how much of a difference the
    // meshes alone make: CDS falls as N^-2, a shift, not a symmetric noise.
    if (out.size() > 1)
      cell.value += fmt::format(" (the anchor's own CDS is {:+.0f} % on the candidates' mesh: the meshes, not the "
                                "shapes, decide a difference this small)",
                                100 * (out[1]->number("/anchor/rigid/cds") / anchor - 1));
    return cell;
  };
}

Rule approximate_screen(int beaten, double oloid_cds, Genome top, double top_cds, double tolerance)
{
  return [=](const std::vector<CommandOutput*>& out) {
    CommandOutput& search = *out[0];
    const std::size_t n = search.at("/genomes").size();
    std::string oloid_genome;
    for (std::size_t g = 0; g < n; ++g)
      if (search.at(fmt::format("/genomes/{}/is_anchor_genome", g)).get<bool>())
        oloid_genome = fmt::format("/genomes/{}", g);
    if (oloid_genome.empty())
      throw ComputationError(fmt::format("`{}` has no genome with is_anchor_genome", search.command()));
    const double oloid = search.number(oloid_genome + "/approximate/cds");
    int below_oloid = 0;
    double best = std::numeric_limits<double>::infinity();
    std::string best_genome;
    for (std::size_t g = 0; g < n; ++g)
    {
      const std::string genome = fmt::format("/genomes/{}", g);
      const double v = search.number(genome + "/approximate/cds");
      below_oloid += v < oloid;
      if (v < best)
        best = v, best_genome = genome;
    }
    const Genome found = genome_at(search, best_genome);
    const bool holds = within(below_oloid, beaten, tolerance) && within(oloid, oloid_cds, tolerance) &&
                       within(best, top_cds, tolerance) && genome_text(found) == genome_text(top);
    return CellResult{fmt::format("{} of {} below the oloid genome's {}; top {} {}, {:.0f} % better", below_oloid, n,
                                  sci(oloid), genome_text(found), sci(best), 100 * (1 - best / oloid)),
                      holds};
  };
}

Rule revalidated(std::vector<std::pair<Genome, std::pair<double, double>>> paper, double tolerance)
{
  return [=](const std::vector<CommandOutput*>& out) {
    CommandOutput& search = *out[0];
    const double oloid = out[1]->number("/cds");
    CellResult cell{"", true};
    std::vector<std::string> listed;
    for (const auto& [genome, cds_ratio] : paper)
    {
      const std::string g = genome_pointer(search, genome);
      listed.push_back(g);
      if (!search.at(g + "/validated").get<bool>())
      {
        cell.holds = false;
        append_listed(cell.value, genome_text(genome) + " not revalidated");
        continue;
      }
      const double cds = search.number(g + "/rigid/cds");
      cell.holds = cell.holds && within(cds, cds_ratio.first, tolerance) &&
                   within(cds / oloid, cds_ratio.second, tolerance);
      append_listed(cell.value, revalidated_text(genome, cds, oloid));
    }
    std::string others;
    for (const auto& [cds, g] : revalidated_by_cds(search))
      if (std::find(listed.begin(), listed.end(), g) == listed.end())
        append_listed(others, revalidated_text(genome_at(search, g), cds, oloid));
    cell.value += fmt::format("; also revalidated, not in the table: {}", others.empty() ? "none" : others);
    return cell;
  };
}

Rule improvement_direction()
{
  return [](const std::vector<CommandOutput*>& out) {
    CommandOutput& search = *out[0];
    const auto ranked = revalidated_by_cds(search);
    std::string top;
    int small_ratio = 0, small_offset = 0, n = 0;
    for (std::size_t i = 0; i < std::min<std::size_t>(3, ranked.size()); ++i, ++n)
    {
      const Genome g = genome_at(search, ranked[i].second);
      small_ratio += g.ratio < 1;
      small_offset += g.offset < 1;
      append_listed(top, genome_text(g));
    }
    return CellResult{fmt::format("rigid-body best {}: {}; ρ < 1 in {}, d < 1 in {}", n, top, small_ratio,
                                  small_offset),
                      n == 3 && small_ratio == 3 && small_offset == 3};
  };
}

Rule approximate_scores(std::vector<std::pair<Genome, double>> paper, double tolerance)
{
  return [=](const std::vector<CommandOutput*>& out) {
    CommandOutput& search = *out[0];
    std::vector<Checked> numbers;
    for (const auto& [genome, value] : paper)
    {
      const double v = search.number(genome_pointer(search, genome) + "/approximate/cds");
      numbers.push_back({genome_text(genome) + " " + sci(v), v, value, 3});
    }
    return each_checked(numbers, tolerance);
  };
}

Rule start_is_local_optimum(bool resolution_free)
{
  return [=](const std::vector<CommandOutput*>& out) {
    CommandOutput& o = *out[0];
    const double start = o.number("/start_value"), best = o.number("/optimum/value");
    const double threshold = o.number("/optimum/significance_threshold");
    const bool beaten = o.at("/optimum/beats_start").get<bool>();
    const nlohmann::json& verdict = o.at("/verdict_at_start");
    const std::string at_start = verdict.is_string() ? verdict.get<std::string>() : "no derivatives";
    const nlohmann::json& x = o.at("/optimum/x");
    CellResult cell{fmt::format("{}; best ({:.1f}, {:.3f}, {:.3f}) {} against {} at the start ({:+.1f} %, noise "
                                "threshold {:.2g}); at the start: {}",
                                beaten ? "beaten" : "not beaten", x[0].get<double>(), x[1].get<double>(),
                                x[2].get<double>(), sci(best), sci(start), 100 * (best / start - 1), threshold,
                                at_start),
                    !beaten && at_start == "local minimum"};
    // A per-face score moves with the face count by as much as the gains:
    // neither a win nor a loss is decided by it.
    if (!resolution_free)
    {
      cell.holds = false;
      cell.undecided = "cannot be decided at this resolution: a per-face score moves with the genome's face count "
                       "by as much as the gains and the gradients measured";
    }
    return cell;
  };
}
} // namespace rollcheck::audit::rules
