#pragma once
// `optimize --out DIR`: the search's finished runs (genome, replicate) kept
// in DIR/evaluations.json (io/evaluation_cache.h) while it runs, so that the
// same command rerun after an interruption reuses them. A run is recalled
// only under the parameters its value depends on.
#include "io/evaluation_cache.h"
#include "io/parameters.h"
#include "study/optimize/optimize_family.h"
#include <filesystem>
#include <memory>

namespace rollcheck::cli
{
/// The runs' file, in the folder during the search and in the finished folder.
inline constexpr const char* evaluations_file = "evaluations.json";

/// The runs a previous search with the same parameters left in `out`, with
/// settings.run_store recalling them and adding each batch of finished runs,
/// saved at once by the first rank (under mpirun every rank of rollcheck-fem
/// runs the same search). The folder is made now (rollcheck's, with its
/// marker); the results replace it whole at the end.
std::shared_ptr<io::EvaluationCache> keep_runs(const std::filesystem::path& out, const io::Parameters& params,
                                               study::optimize::FamilySearchSettings& settings);
} // namespace rollcheck::cli
