#include "io/batch_record.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/output_manifest.h"
#include <chrono>
#include <cstring>
#include <fcntl.h>
#include <fmt/chrono.h>
#include <fmt/format.h>
#include <fstream>
#include <sys/file.h>
#include <unistd.h>

namespace rollcheck::io
{
namespace fs = std::filesystem;

namespace
{
constexpr const char* record_file = "result.json";
constexpr const char* log_file = "log.txt";

fs::path replaced_folder(const fs::path& out, const std::string& hash) { return out / "cases" / (hash + ".old"); }
} // namespace

fs::path case_folder(const fs::path& out, const std::string& hash) { return out / "cases" / hash; }
fs::path case_work_folder(const fs::path& out, const std::string& hash) { return out / "cases" / (hash + ".part"); }

std::optional<nlohmann::json> read_case_record(const fs::path& out, const std::string& hash)
{
  std::ifstream in(case_folder(out, hash) / record_file);
  if (!in)
    return std::nullopt;
  nlohmann::json record = nlohmann::json::parse(in, nullptr, false);
  if (record.is_discarded() || !record.is_object() || record.value("hash", "") != hash)
    return std::nullopt;
  return record;
}

fs::path start_case_work(const fs::path& out, const std::string& hash)
{
  const fs::path work = case_work_folder(out, hash);
  fs::remove_all(work);
  fs::create_directories(work);
  return work;
}

nlohmann::json commit_case_work(const fs::path& out, const std::string& hash, nlohmann::json record)
{
  const fs::path work = case_work_folder(out, hash);
  const bool ok = record.value("status", "") == "ok";
  nlohmann::json files = nlohmann::json::array();
  std::vector<fs::path> entries;
  for (const fs::directory_entry& entry : fs::recursive_directory_iterator(work))
    if (entry.is_regular_file())
      entries.push_back(entry.path());
  std::sort(entries.begin(), entries.end());
  for (const fs::path& path : entries)
  {
    const fs::path inside = path.lexically_relative(work);
    if (inside == record_file || inside == log_file)
      continue;
    if (ok)
      files.push_back((fs::path("cases") / hash / inside).string());
    else
      fs::remove(path);
  }
  record["files"] = files;
  write_file_atomically(work / record_file, record.dump(1, ' ', false, nlohmann::json::error_handler_t::replace) + "\n");
  // A rename cannot replace a non-empty folder: the old result steps aside
  // first. Killed in between, the next batch finds no result and recomputes.
  const fs::path target = case_folder(out, hash), old = replaced_folder(out, hash);
  fs::remove_all(old);
  if (fs::exists(target))
    fs::rename(target, old);
  fs::rename(work, target);
  fs::remove_all(old);
  return record;
}

void discard_case_work(const fs::path& out, const std::string& hash)
{
  std::error_code ignored;
  fs::remove_all(case_work_folder(out, hash), ignored);
}

void remove_stale_work(const fs::path& out)
{
  const std::optional<OutputManifest> manifest = read_output_manifest(out);
  if (!manifest)
    return;
  std::vector<fs::path> stale;
  for (const fs::path& folder : {fs::path(), fs::path("cases")})
    if (fs::is_directory(out / folder))
      for (const fs::directory_entry& entry : fs::directory_iterator(out / folder))
        if (const fs::path inside = folder / entry.path().filename(); is_stale_work(*manifest, inside))
          stale.push_back(entry.path());
  for (const fs::path& path : stale)
    fs::remove_all(path);
}

std::vector<std::string> batch_outputs(const std::vector<std::string>& hashes)
{
  std::vector<std::string> entries{results_store_file};
  for (const std::string& hash : hashes)
    entries.push_back((fs::path("cases") / hash).generic_string());
  return entries;
}

OutputLock::OutputLock(const fs::path& out)
{
  const fs::path path = out / ".lock";
  fd_ = open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd_ < 0)
    throw InputError(fmt::format("batch --out '{}': cannot create '{}': {}", out.string(), path.string(),
                                 strerror(errno)));
  if (flock(fd_, LOCK_EX | LOCK_NB) != 0)
  {
    close(fd_);
    throw InputError(fmt::format("batch --out '{}': another batch is writing there (lock '{}')", out.string(),
                                 path.string()));
  }
}

OutputLock::~OutputLock() { close(fd_); }

std::string utc_now()
{
  return fmt::format("{:%Y-%m-%dT%H:%M:%SZ}", fmt::gmtime(std::chrono::system_clock::to_time_t(std::chrono::system_clock::now())));
}
} // namespace rollcheck::io
