#include "study/body_scores/search_table.h"
#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <limits>
#include <vector>

namespace rollcheck::study::body_scores
{
namespace
{
std::string score_text(double v) { return std::isinf(v) ? "inf" : fmt::format("{:.4g}", v); }

double metric(const oracle::GenomeResult& r, const std::string& name)
{
  for (const auto& [key, value] : r.metrics)
    if (key == name)
      return value;
  return std::numeric_limits<double>::quiet_NaN();
}

std::string row(const std::string& rank, const oracle::GenomeResult& r, const oracle::GenomeResult& anchor)
{
  const std::string rigid
      = r.validated ? fmt::format("{:>11} {:>7.3f} {:>5} {:>11} {:>11} {:>11}", score_text(r.rigid_cds),
                                  r.rigid_cds / anchor.rigid_cds, r.rigid_rank > 0 ? std::to_string(r.rigid_rank) : "-",
                                  score_text(metric(r, "sds")), score_text(metric(r, "tds")),
                                  score_text(metric(r, "fds")))
                    : "";
  return fmt::format("{:>4} {:>6.1f} {:>5.2f} {:>5.2f} {:>2} {:>5} {:>7.3f} {:>11} {:>7.3f} {}\n", rank,
                     r.genome.theta_deg, r.genome.offset, r.genome.ratio, r.genome.n_circles, r.n_faces, r.area_m2,
                     score_text(r.approximate_cds), r.approximate_cds / anchor.approximate_cds, rigid);
}
} // namespace

std::string ranked_table(const oracle::SearchResult& result, std::size_t rows)
{
  const oracle::GenomeResult& anchor = result.anchor;
  std::string t = fmt::format(
      "{} grid: {} genomes, {} valid, {} revalidated; {} threads, {:.2f} s (approximate {:.2f} s, rigid-body "
      "{:.2f} s)\n",
      oracle::name_of(result.options.grid), result.genomes.size(),
      std::count_if(result.genomes.begin(), result.genomes.end(), [](const auto& r) { return r.valid; }),
      std::count_if(result.genomes.begin(), result.genomes.end(), [](const auto& r) { return r.validated; }),
      result.threads, result.wall_s, result.approximate_wall_s, result.rigid_wall_s);
  t += fmt::format("{:>4} {:>6} {:>5} {:>5} {:>2} {:>5} {:>7} {:>11} {:>7} {:>11} {:>7} {:>5} {:>11} {:>11} {:>11}\n",
                   "rank", "theta", "d", "rho", "n", "faces", "area", "approx CDS", "/anchor", "rigid CDS", "/anchor",
                   "rank", "SDS", "TDS", "FDS");
  t += row(fmt::format("{}pt", result.anchor_points).substr(0, 4), anchor, anchor);
  std::vector<const oracle::GenomeResult*> ranked;
  for (const auto& r : result.genomes)
    if (r.valid)
      ranked.push_back(&r);
  std::sort(ranked.begin(), ranked.end(), [](auto a, auto b) { return a->approximate_rank < b->approximate_rank; });
  for (std::size_t k = 0; k < std::min(rows, ranked.size()); ++k)
    t += row(std::to_string(ranked[k]->approximate_rank) + (ranked[k]->is_anchor_genome ? "*" : ""), *ranked[k],
             anchor);
  t += fmt::format("(first row: the anchor oloid at {} points per circle; * the grid's own (90, 1, 1) genome; ratios "
                   "against the anchor)\n",
                   result.anchor_points);
  return t;
}
} // namespace rollcheck::study::body_scores
