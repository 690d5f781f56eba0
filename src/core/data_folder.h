#pragma once
// Where rollcheck's own files are (the default cases, the post-processing
// scripts, the reference meshes): beside an installed executable,
// PREFIX/share/rollcheck (cmake --install, the .deb), else the source tree
// the executable was built from. So `P/bin/rollcheck validate` works from
// anywhere, and so does build/src/cli/rollcheck.
#include <filesystem>

namespace rollcheck
{
/// PREFIX/share/rollcheck when the executable runs from PREFIX/bin and that
/// folder holds cases/; otherwise the source tree (ROLLCHECK_SOURCE_DIR).
std::filesystem::path data_folder();
} // namespace rollcheck
