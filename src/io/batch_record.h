#pragma once
// A batch's results on disk, one folder per case keyed by its hash, so that
// a batch killed at any moment keeps every case that finished and a re-run
// knows what is done:
//
//   DIR/cases/<hash>/        a finished case: result.json (its record), log.txt
//                            (the case process's output), and any file it wrote
//   DIR/cases/<hash>.part/   a case being computed; it becomes DIR/cases/<hash>
//                            by one rename when the case ends, and is deleted
//                            by the next batch if this one was killed
//   DIR/.lock                held (flock) while a batch writes to DIR
//   DIR/results.h5           the results store of the last batch
//   DIR/.rollcheck-output    the manifest (core/output_manifest.h): results.h5
//                            and cases/<hash> of every case a batch ran; a
//                            batch removes or replaces nothing else, so the
//                            folder may hold the user's files
//
// A record (result.json) is a JSON object: status ("ok" or "failed"), message
// (failed), case_file, kind, hash, rollcheck_version, mpi_ranks, wall_s,
// finished_utc, host, rank, exit, parameters (resolved), summary (the scene's
// JSON, ok only), files (written by the case, relative to DIR).
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace rollcheck::io
{
std::filesystem::path case_folder(const std::filesystem::path& out, const std::string& hash);
std::filesystem::path case_work_folder(const std::filesystem::path& out, const std::string& hash);

/// The record of a finished case, or nullopt if there is none (or it cannot
/// be parsed, which a re-run then replaces).
std::optional<nlohmann::json> read_case_record(const std::filesystem::path& out, const std::string& hash);

/// A fresh, empty work folder for the case.
std::filesystem::path start_case_work(const std::filesystem::path& out, const std::string& hash);

/// Writes `record` into the work folder (with `files` filled in from what is
/// there) and moves the folder into place, replacing an earlier result.
/// A failed case keeps only its log, so that no half-written output remains.
nlohmann::json commit_case_work(const std::filesystem::path& out, const std::string& hash, nlohmann::json record);

void discard_case_work(const std::filesystem::path& out, const std::string& hash);

/// The results store's name in DIR.
inline constexpr const char* results_store_file = "results.h5";

/// Deletes what a killed batch left, as the manifest of `out` tells it
/// (core/output_manifest.h is_stale_work): work folders and half-replaced
/// results of listed cases, temporary files of the store.
void remove_stale_work(const std::filesystem::path& out);

/// What a batch of these case hashes writes in DIR: results.h5 and
/// cases/<hash> each. Checked against the manifest before anything is
/// computed (check_output_entries) and listed in it before anything is
/// written (claim_outputs), so that the work of a batch killed at any moment
/// is recognised as rollcheck's and nothing else is ever touched.
std::vector<std::string> batch_outputs(const std::vector<std::string>& hashes);

/// An exclusive lock on DIR for the lifetime of the object; InputError if
/// another batch holds it.
class OutputLock
{
public:
  explicit OutputLock(const std::filesystem::path& out);
  OutputLock(const OutputLock&) = delete;
  OutputLock& operator=(const OutputLock&) = delete;
  ~OutputLock();

private:
  int fd_;
};

/// The current time as ISO 8601 UTC, "2025-01-31T12:00:00Z".
std::string utc_now();
} // namespace rollcheck::io
