#pragma once
// Every result file is written whole or not at all: the writer fills a
// temporary file beside the target, which is renamed over it only on success.
// Lives in core because every layer writes files.
#include <filesystem>
#include <functional>

namespace rollcheck
{
/// Calls `fill(tmp)` with a temporary path in the target's directory, then
/// renames it to `target`. If `fill` throws, the temporary is removed and the
/// target is left untouched.
void write_atomically(const std::filesystem::path& target,
                      const std::function<void(const std::filesystem::path&)>& fill);
} // namespace rollcheck
