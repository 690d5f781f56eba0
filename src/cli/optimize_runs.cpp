#include "cli/optimize_runs.h"
#include "cli/cli.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "io/case_hash.h"
#include <spdlog/spdlog.h>
#include <string>
#include <vector>

namespace rollcheck::cli
{
namespace
{
/// The parameters that steer the search but change no run's value (a run is
/// one genome and replicate): a rerun that changes only these reuses the runs.
const std::vector<std::string> search_only_keys{"method",       "max_evaluations", "replicates", "pilot_step",
                                                "derivatives",  "sweep_points",    "threads",    "out",
                                                "python"};

/// What a run (genome, replicate) computes beyond the parameters: the genome a
/// replicate moves to (study::optimize::replicate_genome) and the mesh it gets under
/// matched face count. Hashed with the parameters, so that runs saved when
/// the rigid replicates nudged the initial spins, or when matched ties went
/// to the fewer points alone, are not recalled.
constexpr const char* run_definition
    = "replicates move the genome by resolution; matched ties keep points; FEM-SDS replicates add 2, -2, 4 points";

/// case_hash of the parameters a run's value depends on (the version included).
std::string run_settings_hash(const io::Parameters& params)
{
  nlohmann::json resolved = params.to_json();
  for (const std::string& key : search_only_keys)
    resolved.erase(key);
  resolved["run_definition"] = run_definition;
  return io::case_hash(resolved);
}
} // namespace

std::shared_ptr<io::EvaluationCache> keep_runs(const std::filesystem::path& out, const io::Parameters& params,
                                               study::optimize::FamilySearchSettings& settings)
{
  const bool saves = process_rank() == 0;
  if (saves && !std::filesystem::exists(out / output_marker))
    write_folder_atomically(out, "option --out", [](const std::filesystem::path&) {});
  // Saved during the search, before the folder's final write lists it.
  if (saves)
    claim_outputs(out, {evaluations_file});
  auto cache = std::make_shared<io::EvaluationCache>(out / evaluations_file, run_settings_hash(params));
  if (cache->size() > 0)
    spdlog::info("optimize: {} finished runs of the same settings in {}", cache->size(),
                 (out / evaluations_file).string());
  settings.run_store.recall = [cache](std::span<const double> x, int replicate) { return cache->recall(x, replicate); };
  settings.run_store.record = [cache, saves](std::span<const study::optimize::OracleRun> runs) {
    for (const study::optimize::OracleRun& run : runs)
      cache->add(run.x, run.replicate, run.value);
    // Rank 0 alone saves, between collective evaluations: its failure (a
    // full disk) must end every rank here, not leave them in the next one.
    std::string failure;
    if (saves)
      try
      {
        cache->save();
      }
      catch (const std::exception& e)
      {
        failure = e.what();
      }
    if (const auto [code, error] = shared_outcome(failure.empty() ? 0 : 1, failure); code != 0)
      throw ComputationError(error);
  };
  return cache;
}
} // namespace rollcheck::cli
