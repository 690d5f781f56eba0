#pragma once
// What `rollcheck report --from` may read: a regular file that HDF5 itself
// recognises by its signature (H5Fis_hdf5), with the layout attribute of a
// rollcheck results store (io/results_store.h) and at least one case under
// /cases. Checked before the report's Python scripts start, so that a wrong
// file is refused by name with exit 2 instead of ending in a traceback.
#include <filesystem>
#include <string_view>

namespace rollcheck::io
{
/// InputError naming `what` and the path unless `path` is a results store holding a case.
void require_results_store(const std::filesystem::path& path, std::string_view what);
} // namespace rollcheck::io
