#include "core/output_manifest.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include <cerrno>
#include <fmt/format.h>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <signal.h>

namespace rollcheck
{
namespace fs = std::filesystem;

bool OutputManifest::lists(const fs::path& relative) const
{
  // A listed folder holds everything below it.
  for (fs::path p = relative.lexically_normal(); !p.empty() && p != "."; p = p.parent_path())
  {
    if (entries.contains(p.generic_string()))
      return true;
    if (!p.has_parent_path())
      break;
  }
  return false;
}

std::optional<OutputManifest> read_output_manifest(const fs::path& folder)
{
  const fs::path path = folder / output_marker;
  std::error_code ec;
  if (!fs::is_regular_file(path, ec))
    return std::nullopt;
  std::ifstream in(path);
  const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  if (!in.eof() && in.fail())
    throw ComputationError(fmt::format("cannot read the manifest '{}'", path.string()));
  OutputManifest manifest;
  const nlohmann::json j = nlohmann::json::parse(text, nullptr, false);
  if (j.is_object() && j.value("written_by", "") == "rollcheck" && j.contains("entries") && j["entries"].is_array())
  {
    for (const nlohmann::json& entry : j["entries"])
      if (entry.is_string())
        manifest.entries.insert(entry.get<std::string>());
    return manifest;
  }
  // The plain-text marker of a rollcheck before manifests names no files,
  // and a file's age cannot tell them from the user's (mv, cp -p and tar
  // keep old times): nothing in such a folder is taken for rollcheck's.
  return manifest;
}

void write_output_manifest(const fs::path& folder, const OutputManifest& manifest)
{
  const nlohmann::json j = {{"written_by", "rollcheck"},
                            {"about", "files and folders rollcheck wrote here; it removes or replaces only these"},
                            {"entries", manifest.entries}};
  write_file_atomically(folder / output_marker, j.dump(1) + "\n");
}

void claim_outputs(const fs::path& folder, const std::vector<std::string>& entries)
{
  OutputManifest manifest = read_output_manifest(folder).value_or(OutputManifest{});
  const std::size_t before = manifest.entries.size();
  for (const std::string& entry : entries)
    manifest.entries.insert(fs::path(entry).lexically_normal().generic_string());
  if (manifest.entries.size() != before || !fs::exists(folder / output_marker))
    write_output_manifest(folder, manifest);
}

void check_output_entries(const fs::path& folder, const std::vector<std::string>& entries, const std::string& origin)
{
  std::error_code ec;
  if (!fs::is_directory(folder, ec))
    return;
  const OutputManifest manifest = read_output_manifest(folder).value_or(OutputManifest{});
  for (const std::string& entry : entries)
    if (fs::exists(fs::symlink_status(folder / entry, ec)) && !manifest.lists(entry))
      throw InputError(fmt::format("{}: '{}' exists and rollcheck did not write it (its folder's {} does not list "
                                   "it); rollcheck never replaces a file it did not write: move it or choose another "
                                   "folder",
                                   origin, (folder / entry).string(), output_marker));
}

bool process_running(long pid)
{
  return pid > 0 && (kill(static_cast<pid_t>(pid), 0) == 0 || errno == EPERM);
}

bool is_stale_work(const OutputManifest& manifest, const fs::path& relative)
{
  const fs::path folder = relative.parent_path();
  const std::string name = relative.filename().string();
  for (const char* suffix : {".part", ".old"})
    if (name.size() > std::string_view(suffix).size() && name.ends_with(suffix)
        && manifest.lists(folder / name.substr(0, name.size() - std::string_view(suffix).size())))
      return true;
  // write_atomically's temporaries: .STEM.tmpPID followed by the extension.
  static const std::regex temporary(R"(^\.(.+)\.tmp([0-9]{1,9})(\..*)?$)");
  std::smatch m;
  if (!std::regex_match(name, m, temporary))
    return false;
  return manifest.lists(folder / (m[1].str() + m[3].str())) && !process_running(std::stol(m[2].str()));
}
} // namespace rollcheck
