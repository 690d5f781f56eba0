// Resumable searches (io/evaluation_cache.h wired into study/optimize/optimize_family.h's
// RunStore as `rollcheck optimize --out` does): a rerun recalls every run and
// gives the same result with no new oracle run; a search interrupted part way
// resumes to the uninterrupted result; a cache of other settings is not read;
// values and genomes come back bit for bit.
#include "io/evaluation_cache.h"
#include "core/error.h"
#include "study/optimize/optimize_family.h"
#include <cmath>
#include <filesystem>
#include <fstream>
#include "study/optimize/family_search_fixture.h"
#include <gtest/gtest.h>
#include <limits>
#include <stdexcept>

using namespace rollcheck;
using namespace rollcheck::study::optimize;
namespace fs = std::filesystem;

namespace
{

/// A fresh file in the tests' scratch folder.
fs::path scratch_file(const std::string& name)
{
  const fs::path folder = fs::path(ROLLCHECK_TEST_TMP) / "evaluation_cache";
  fs::create_directories(folder);
  fs::remove(folder / name);
  return folder / name;
}

/// `settings` keeping its runs in `cache`, saved after each batch (as cli/optimize.cpp wires it).
FamilySearchSettings kept_in(FamilySearchSettings settings, io::EvaluationCache& cache)
{
  settings.run_store.recall = [&cache](std::span<const double> x, int replicate) {
    return cache.recall(x, replicate);
  };
  settings.run_store.record = [&cache](std::span<const OracleRun> runs) {
    for (const OracleRun& run : runs)
      cache.add(run.x, run.replicate, run.value);
    cache.save();
  };
  return settings;
}

/// The result without what depends on the run rather than the search: timing and where the runs came from.
nlohmann::json outcome(const FamilySearchResult& r)
{
  nlohmann::json j = to_json(r);
  for (const char* key : {"wall_s", "oracle_runs", "recalled_runs"})
    j.erase(key);
  return j;
}
} // namespace

TEST(EvaluationCache, ARerunRecallsEveryRunAndGivesTheSameResult)
{
  const fs::path file = scratch_file("rerun.json");
  io::EvaluationCache first_cache(file, "settings-a");
  const FamilySearchResult first = optimize_family(kept_in(cheap_family_search(), first_cache));
  EXPECT_EQ(first.recalled_runs, 0);
  ASSERT_GT(first.oracle_runs, 0);
  EXPECT_EQ(static_cast<long>(first_cache.size()), first.oracle_runs);

  io::EvaluationCache second_cache(file, "settings-a");
  EXPECT_EQ(second_cache.size(), first_cache.size());
  const FamilySearchResult second = optimize_family(kept_in(cheap_family_search(), second_cache));
  EXPECT_EQ(second.oracle_runs, 0);
  EXPECT_EQ(second.recalled_runs, first.oracle_runs);
  EXPECT_EQ(second.search.best_x, first.search.best_x);
  EXPECT_EQ(second.search.best_value, first.search.best_value);
  EXPECT_EQ(outcome(second), outcome(first));
}

TEST(EvaluationCache, AnInterruptedSearchResumesToTheSameResult)
{
  const FamilySearchResult whole = optimize_family(cheap_family_search());
  const fs::path file = scratch_file("interrupted.json");
  std::size_t kept = 0;
  {
    io::EvaluationCache cache(file, "settings-a");
    FamilySearchSettings interrupted = kept_in(cheap_family_search(), cache);
    int batches = 0;
    interrupted.run_store.record = [&batches, save = interrupted.run_store.record](
                                       std::span<const OracleRun> runs) {
      save(runs);
      if (++batches == 5)
        throw std::runtime_error("interrupted");
    };
    EXPECT_ANY_THROW(optimize_family(interrupted));
    kept = cache.size();
  }
  ASSERT_GT(kept, 0u);
  ASSERT_LT(static_cast<long>(kept), whole.oracle_runs) << "the interruption came after the last run";
  io::EvaluationCache cache(file, "settings-a");
  const FamilySearchResult resumed = optimize_family(kept_in(cheap_family_search(), cache));
  EXPECT_EQ(resumed.recalled_runs, static_cast<long>(kept));
  EXPECT_EQ(resumed.recalled_runs + resumed.oracle_runs, whole.oracle_runs);
  EXPECT_EQ(outcome(resumed), outcome(whole));
}

TEST(EvaluationCache, ACacheOfOtherSettingsIsNotReused)
{
  const fs::path file = scratch_file("other_settings.json");
  io::EvaluationCache points_100(file, "settings-a");
  const FamilySearchResult first = optimize_family(kept_in(cheap_family_search(), points_100));

  io::EvaluationCache other(file, "settings-b");
  EXPECT_EQ(other.size(), 0u);
  const FamilySearchResult second = optimize_family(kept_in(cheap_family_search(), other));
  EXPECT_EQ(second.recalled_runs, 0);
  EXPECT_EQ(second.oracle_runs, first.oracle_runs);
  // Its saves replaced the file: the first settings' runs are gone.
  EXPECT_EQ(io::EvaluationCache(file, "settings-a").size(), 0u);
  EXPECT_EQ(io::EvaluationCache(file, "settings-b").size(), other.size());
}

TEST(EvaluationCache, GenomesAndValuesComeBackBitForBit)
{
  const fs::path file = scratch_file("round_trip.json");
  const std::vector<double> x{0.1 + 0.2, 1.0 / 3, std::nextafter(1.0, 2.0)};
  const double value = std::sqrt(2.0) * 1e-7, infinite = std::numeric_limits<double>::infinity();
  io::EvaluationCache cache(file, "h");
  cache.add(x, 0, value);
  cache.add(x, 3, infinite);
  cache.save();
  const io::EvaluationCache read(file, "h");
  EXPECT_EQ(read.recall(x, 0), value);
  EXPECT_EQ(read.recall(x, 3), infinite);
  EXPECT_FALSE(read.recall(x, 1).has_value());
  const std::vector<double> neighbour{x[0], x[1], 1.0};
  EXPECT_FALSE(read.recall(neighbour, 0).has_value());
}

TEST(EvaluationCache, AFileThatIsNoCacheIsNamed)
{
  const fs::path file = scratch_file("not_a_cache.json");
  std::ofstream(file) << "{\"layout\": \"something else\"}\n";
  try
  {
    io::EvaluationCache cache(file, "h");
    FAIL() << "a foreign file was read as a cache";
  }
  catch (const InputError& e)
  {
    EXPECT_NE(std::string(e.what()).find(file.string()), std::string::npos) << e.what();
  }
}
