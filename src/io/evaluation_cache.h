#pragma once
// The finished runs of a search, kept in a file so that rerunning the same
// command after an interruption reuses them (`rollcheck optimize --out DIR`
// keeps DIR/evaluations.json; docs/methods/optimize.md "Resuming"). Each run is
// (genome, replicate) -> value, and the file holds the hash of the settings
// the values depend on (case_hash): a file written under another hash is not
// read, and the next save replaces it. The file is rewritten whole after each
// batch of runs (write_atomically), so an interruption loses at most the
// batch under way and never leaves a torn file.
//
//   {"layout": "rollcheck-evaluations-1", "settings_hash": "...",
//    "runs": [{"x": [theta_deg, offset, ratio], "replicate": 0, "value": 1.9e-06}, ...]}
//
// Values follow json_number ("inf" for an infinite score); genomes and values
// are written in shortest round-trip form, so a recalled run is bit-identical.
#include <filesystem>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace rollcheck::io
{
class EvaluationCache
{
public:
  /// The runs `file` holds under `settings_hash`, or none if the file is
  /// absent or was written under another hash. InputError naming the file if
  /// it is not an evaluation cache.
  EvaluationCache(std::filesystem::path file, std::string settings_hash);

  /// The value of run (x, replicate), if the cache holds it.
  std::optional<double> recall(std::span<const double> x, int replicate) const;
  /// Adds (or replaces) one run; save() writes it.
  void add(std::span<const double> x, int replicate, double value);
  /// Writes every run to the cache's file, atomically.
  void save() const { save(file_); }
  /// Writes every run to `file` (a copy beside other results), atomically.
  void save(const std::filesystem::path& file) const;
  /// The runs held.
  std::size_t size() const { return values_.size(); }

private:
  std::filesystem::path file_;
  std::string settings_hash_;
  std::map<std::pair<std::vector<double>, int>, double> values_;
};
} // namespace rollcheck::io
