#include "core/data_folder.h"
#include "core/child_process.h"
#include "rollcheck_version.h"

namespace rollcheck
{
std::filesystem::path data_folder()
{
  namespace fs = std::filesystem;
  std::error_code ignored;
  const fs::path installed = process::own_executable().parent_path().parent_path() / "share" / "rollcheck";
  if (fs::is_directory(installed / "cases", ignored))
    return installed;
  return ROLLCHECK_SOURCE_DIR;
}
} // namespace rollcheck
