#include "io/results_store_check.h"
#include "core/error.h"
#include "io/hdf5_handle.h"
#include <fmt/format.h>
#include <hdf5.h>
#include <string>
#include <sys/stat.h>

namespace rollcheck::io
{
void require_results_store(const std::filesystem::path& path, std::string_view what)
{
  auto refuse = [&](std::string_view why) {
    return InputError(fmt::format("{} '{}': {}", what, path.string(), why));
  };
  struct stat st{};
  if (::stat(path.c_str(), &st) != 0)
    throw refuse("does not exist");
  if (!S_ISREG(st.st_mode))
    throw refuse("is not a regular file (a results store is DIR/results.h5 of `rollcheck batch`)");
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  if (H5Fis_hdf5(path.c_str()) <= 0)
    throw refuse("is not an HDF5 file (no HDF5 signature)");
  const hid_t id = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (id < 0)
    throw refuse("cannot be opened by HDF5");
  const hdf5::Handle file(id, H5Fclose, "close the store");
  if (H5Aexists(file, "layout") <= 0)
    throw refuse("is an HDF5 file but not a rollcheck results store (no 'layout' attribute)");
  if (H5Lexists(file, "cases", H5P_DEFAULT) <= 0)
    throw refuse("is a results store without a /cases group");
  const hdf5::Handle cases(H5Gopen2(file, "cases", H5P_DEFAULT), H5Gclose, "open /cases");
  H5G_info_t info{};
  if (H5Gget_info(cases, &info) < 0 || info.nlinks == 0)
    throw refuse("is an empty results store: it holds no case (run `rollcheck batch` first)");
}
} // namespace rollcheck::io
