// The family search in words (study/optimize/optimize_family.h): the log's
// line and the count of the FEM-SDS loops' convergence.
#include "study/optimize/optimize_family.h"
#include <fmt/format.h>

namespace rollcheck::study::optimize
{
std::string summary_line(const FamilySearchResult& result)
{
  // The values as the JSON writes them, so that the log and the JSON agree digit for digit.
  const nlohmann::json j = to_json(result);
  const nlohmann::json& best = j["optimum"];
  return fmt::format("optimize {} ({}): start {} -> {}, optimum {} -> {} ({} the start beyond the noise {}); at the "
                     "start: {}; hull faces {} at the start, {} at the optimum ({} points per circle); {} genomes, {} "
                     "oracle runs, {} recalled, {:.1f} s",
                     j["score"].get<std::string>(), j["oracle"].get<std::string>(), j["start"].dump(),
                     j["start_value"].dump(), best["x"].dump(), best["value"].dump(),
                     best["beats_start"].get<bool>() ? "beats" : "does not beat", j["noise"]["sigma"].dump(),
                     j["verdict_at_start"].dump(), result.start_mesh.faces, result.best_mesh.faces,
                     result.best_mesh.points, result.score_evaluations, result.oracle_runs, result.recalled_runs,
                     result.wall_s);
}

int LoopStatusCounts::not_converged() const
{
  const auto it = by_status.find("not converged");
  return it == by_status.end() ? 0 : it->second;
}

LoopStatusCounts count_loop_statuses(std::span<const std::string> statuses)
{
  LoopStatusCounts counts;
  counts.scored = statuses.size();
  for (const std::string& status : statuses)
    ++counts.by_status[status.starts_with("converged")       ? "converged"
                       : status.starts_with("not converged") ? "not converged"
                                                             : status];
  return counts;
}
} // namespace rollcheck::study::optimize
