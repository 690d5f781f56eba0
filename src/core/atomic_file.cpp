#include "core/atomic_file.h"
#include "core/error.h"
#include <fmt/format.h>
#include <fstream>
#include <unistd.h>

namespace rollcheck
{
void write_atomically(const std::filesystem::path& target,
                      const std::function<void(const std::filesystem::path&)>& fill)
{
  namespace fs = std::filesystem;
  const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
  if (!fs::is_directory(dir))
    throw InputError(fmt::format("output '{}': directory '{}' does not exist", target.string(), dir.string()));
  // The suffix keeps the extension last, so writers that choose a format by
  // extension (gmsh, HDF5) still see it.
  const fs::path tmp = dir / fmt::format(".{}.tmp{}{}", target.stem().string(), getpid(), target.extension().string());
  try
  {
    fill(tmp);
    fs::rename(tmp, target);
  }
  catch (...)
  {
    std::error_code ignored;
    fs::remove_all(tmp, ignored); // a writer may have made a folder of it
    throw;
  }
}

namespace
{
namespace fs = std::filesystem;

void check_parent_writable(const fs::path& target, const std::string& origin)
{
  const fs::path parent = fs::absolute(target).lexically_normal().parent_path();
  if (!fs::is_directory(parent))
    throw InputError(fmt::format("{}: folder '{}' does not exist (create it first)", origin, parent.string()));
  if (access(parent.c_str(), W_OK) != 0)
    throw InputError(fmt::format("{}: folder '{}' is not writable", origin, parent.string()));
}
} // namespace

void check_output_file(const fs::path& target, const std::string& origin)
{
  if (fs::is_directory(target))
    throw InputError(fmt::format("{}: '{}' is a folder, not a file", origin, target.string()));
  check_parent_writable(target, origin);
}

void check_output_folder(const fs::path& folder, const std::string& origin)
{
  if (fs::exists(folder) && !fs::is_directory(folder))
    throw InputError(fmt::format("{}: '{}' is a file, not a folder; rollcheck does not replace it", origin,
                                 folder.string()));
  if (fs::is_directory(folder) && !fs::is_empty(folder) && !fs::exists(folder / output_marker))
    throw InputError(fmt::format("{}: folder '{}' holds files rollcheck did not write (no {}); choose a new "
                                 "folder: rollcheck never removes a file it did not write",
                                 origin, folder.string(), output_marker));
  check_parent_writable(folder, origin);
}

void write_folder_atomically(const fs::path& folder, const std::string& origin,
                             const std::function<void(const fs::path&)>& fill)
{
  check_output_folder(folder, origin);
  const fs::path target = fs::absolute(folder).lexically_normal();
  const fs::path parent = target.parent_path();
  const std::string stem = target.filename().string();
  const fs::path drawing = parent / fmt::format(".{}.tmp{}", stem, getpid());
  const fs::path replaced = parent / fmt::format(".{}.old{}", stem, getpid());
  fs::remove_all(drawing);
  fs::create_directories(drawing);
  try
  {
    fill(drawing);
    std::ofstream(drawing / output_marker) << "written by rollcheck; the whole folder is replaced by its next run\n";
  }
  catch (...)
  {
    std::error_code ignored;
    fs::remove_all(drawing, ignored);
    throw;
  }
  // Checked again: the folder may have changed while `fill` ran.
  check_output_folder(folder, origin);
  if (fs::exists(target))
    fs::rename(target, replaced);
  fs::rename(drawing, target);
  fs::remove_all(replaced);
}
} // namespace rollcheck
