#include "core/atomic_file.h"
#include "core/error.h"
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <fmt/format.h>
#include <regex>
#include <unistd.h>

namespace rollcheck
{
namespace
{
namespace fs = std::filesystem;

ComputationError write_error(const fs::path& target, const std::string& reason)
{
  return ComputationError(fmt::format("cannot write '{}': {}", target.string(), reason));
}

/// fsync of a file or a folder: the data reach the disk before the rename
/// makes them the target (a full disk with delayed allocation fails here).
void flush_to_disk(const fs::path& path, const fs::path& target)
{
  const int fd = open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0)
    throw write_error(target, strerror(errno));
  const int synced = fsync(fd), error = errno;
  close(fd);
  // A folder that cannot be synced (some file systems refuse) loses nothing.
  if (synced != 0 && !(fs::is_directory(path) && (error == EINVAL || error == EROFS)))
    throw write_error(target, strerror(error));
}

void rename_checked(const fs::path& from, const fs::path& to)
{
  if (std::rename(from.c_str(), to.c_str()) != 0)
    throw write_error(to, fmt::format("rename from '{}' failed: {}", from.string(), strerror(errno)));
}

void check_parent_writable(const fs::path& target, const std::string& origin)
{
  fs::path path = fs::absolute(target).lexically_normal();
  if (!path.has_filename()) // "out/"
    path = path.parent_path();
  const fs::path parent = path.parent_path();
  if (!fs::is_directory(parent))
    throw InputError(fmt::format("{}: folder '{}' does not exist (create it first)", origin, parent.string()));
  if (access(parent.c_str(), W_OK) != 0)
    throw InputError(fmt::format("{}: folder '{}' is not writable", origin, parent.string()));
}

/// `.NAME.tmpPID/` beside `target` left by a killed run: its process gone and
/// rollcheck's manifest inside (written first, so a drawing always has one).
void remove_stale_drawings(const fs::path& target)
{
  const std::regex drawing("^\\." + std::regex_replace(target.filename().string(), std::regex(R"([.^$|()\[\]{}*+?\\])"),
                                                       R"(\$&)") + R"(\.tmp([0-9]{1,9})$)");
  std::error_code ec;
  for (const fs::directory_entry& entry : fs::directory_iterator(target.parent_path(), ec))
  {
    const std::string name = entry.path().filename().string();
    std::smatch m;
    if (std::regex_match(name, m, drawing) && entry.is_directory(ec) && fs::is_regular_file(entry.path() / output_marker, ec)
        && !process_running(std::stol(m[1].str())))
      fs::remove_all(entry.path(), ec);
  }
}

/// The entries a run made in its temporary folder.
OutputManifest entries_made(const fs::path& drawing)
{
  OutputManifest made;
  for (const fs::directory_entry& entry : fs::directory_iterator(drawing))
    if (entry.path().filename() != output_marker)
      made.entries.insert(entry.path().filename().string());
  return made;
}

/// Moves what `drawing` holds into the existing folder output `target`,
/// removing what the old manifest listed and this run did not make.
void merge_into(const fs::path& drawing, const fs::path& target, const std::string& origin)
{
  const OutputManifest made = entries_made(drawing);
  const OutputManifest old = read_output_manifest(target).value_or(OutputManifest{});
  for (const std::string& entry : made.entries)
    if (fs::exists(fs::symlink_status(target / entry)) && !old.lists(entry))
      throw InputError(fmt::format("{}: '{}' exists and rollcheck did not write it; it is left as it is and "
                                   "nothing of this run was written there",
                                   origin, (target / entry).string()));
  // Every entry of the old and the new run is listed while they change places.
  OutputManifest both = old;
  both.entries.insert(made.entries.begin(), made.entries.end());
  write_output_manifest(target, both);
  for (const std::string& entry : made.entries)
  {
    fs::remove_all(target / entry);
    rename_checked(drawing / entry, target / entry);
  }
  for (const std::string& entry : old.entries)
    if (!made.entries.contains(entry))
      fs::remove_all(target / entry);
  write_output_manifest(target, made);
  flush_to_disk(target, target);
  fs::remove_all(drawing);
}
} // namespace

void write_atomically(const fs::path& target, const std::function<void(const fs::path&)>& fill)
{
  const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
  if (!fs::is_directory(dir))
    throw InputError(fmt::format("output '{}': directory '{}' does not exist", target.string(), dir.string()));
  if (target.filename().empty() || fs::is_directory(target))
    throw InputError(fmt::format("output '{}': is a folder, not a file", target.string()));
  // The suffix keeps the extension last, so writers that choose a format by
  // extension (gmsh, HDF5) still see it.
  const fs::path tmp = dir / fmt::format(".{}.tmp{}{}", target.stem().string(), getpid(), target.extension().string());
  try
  {
    fill(tmp);
    flush_to_disk(tmp, target);
    rename_checked(tmp, target);
  }
  catch (...)
  {
    std::error_code ignored;
    fs::remove_all(tmp, ignored); // a writer may have made a folder of it
    throw;
  }
  // The rename itself reaches the disk with the folder's entry.
  if (const int fd = open(dir.c_str(), O_RDONLY | O_CLOEXEC); fd >= 0)
    fsync(fd), close(fd);
}

void move_into_place(const fs::path& from, const fs::path& target)
{
  flush_to_disk(from, target);
  rename_checked(from, target);
}

void write_file_atomically(const fs::path& target, std::string_view bytes)
{
  write_atomically(target, [&](const fs::path& tmp) {
    const int fd = open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
    if (fd < 0)
      throw write_error(target, strerror(errno));
    std::size_t written = 0;
    while (written < bytes.size())
    {
      const ssize_t n = write(fd, bytes.data() + written, bytes.size() - written);
      if (n < 0 && errno == EINTR)
        continue;
      if (n <= 0)
      {
        const int error = n < 0 ? errno : ENOSPC;
        close(fd);
        throw write_error(target, strerror(error));
      }
      written += static_cast<std::size_t>(n);
    }
    if (close(fd) != 0)
      throw write_error(target, strerror(errno));
  });
}

void write_stdout(std::string_view bytes, const std::string& what)
{
  if (std::fwrite(bytes.data(), 1, bytes.size(), stdout) != bytes.size() || std::fflush(stdout) != 0)
    throw ComputationError(fmt::format("cannot write {} to stdout: {}", what, strerror(errno)));
}

void check_output_file(const fs::path& target, const std::string& origin)
{
  if (target.empty())
    throw InputError(fmt::format("{}: the file is an empty path", origin));
  std::error_code ec;
  const fs::file_status status = fs::status(target, ec);
  if (fs::is_directory(status) || target.filename().empty())
    throw InputError(fmt::format("{}: '{}' is a folder, not a file", origin, target.string()));
  if (fs::exists(status) && !fs::is_regular_file(status))
    throw InputError(fmt::format("{}: '{}' is not a regular file (a device, a fifo or a socket); rollcheck "
                                 "replaces the file it writes, so name a regular file ('-' for stdout)",
                                 origin, target.string()));
  check_parent_writable(target, origin);
}

void check_output_location(const fs::path& folder, const std::string& origin)
{
  if (folder.empty())
    throw InputError(fmt::format("{}: the folder is an empty path", origin));
  if (fs::exists(folder) && !fs::is_directory(folder))
    throw InputError(fmt::format("{}: '{}' is a file, not a folder; rollcheck does not replace it", origin,
                                 folder.string()));
  if (fs::is_directory(folder) && access(folder.c_str(), W_OK) != 0)
    throw InputError(fmt::format("{}: folder '{}' is not writable", origin, folder.string()));
  check_parent_writable(folder, origin);
}

void check_output_folder(const fs::path& folder, const std::string& origin)
{
  check_output_location(folder, origin);
  if (fs::is_directory(folder) && !fs::is_empty(folder) && !fs::exists(folder / output_marker))
    throw InputError(fmt::format("{}: folder '{}' holds files rollcheck did not write (no {}); choose a new "
                                 "folder: rollcheck never removes a file it did not write",
                                 origin, folder.string(), output_marker));
}

void write_folder_atomically(const fs::path& folder, const std::string& origin,
                             const std::function<void(const fs::path&)>& fill)
{
  check_output_folder(folder, origin);
  fs::path target = fs::absolute(folder).lexically_normal();
  if (!target.has_filename()) // "out/"
    target = target.parent_path();
  remove_stale_drawings(target);
  const fs::path drawing = target.parent_path() / fmt::format(".{}.tmp{}", target.filename().string(), getpid());
  fs::remove_all(drawing);
  fs::create_directories(drawing);
  try
  {
    write_output_manifest(drawing, {});
    fill(drawing);
    // Checked again: the folder may have changed while `fill` ran.
    check_output_folder(folder, origin);
    if (!fs::exists(target) || fs::is_empty(target))
    {
      write_output_manifest(drawing, entries_made(drawing));
      flush_to_disk(drawing, target);
      rename_checked(drawing, target);
      return;
    }
    merge_into(drawing, target, origin);
  }
  catch (...)
  {
    std::error_code ignored;
    fs::remove_all(drawing, ignored);
    throw;
  }
}
} // namespace rollcheck
