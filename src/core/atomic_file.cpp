#include "core/atomic_file.h"
#include "core/error.h"
#include <fmt/format.h>
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
    fs::remove(tmp, ignored);
    throw;
  }
}
} // namespace rollcheck
