#pragma once
// Every result file is written whole or not at all: the writer fills a
// temporary file beside the target, which is renamed over it only on success.
// Lives in core because every layer writes files.
#include <filesystem>
#include <functional>
#include <string>

namespace rollcheck
{
/// Calls `fill(tmp)` with a temporary path in the target's directory, then
/// renames it to `target`. If `fill` throws, the temporary is removed and the
/// target is left untouched.
void write_atomically(const std::filesystem::path& target,
                      const std::function<void(const std::filesystem::path&)>& fill);

/// The marker file in every folder rollcheck writes: a folder that holds
/// anything else and no marker belongs to the user and is never replaced.
inline constexpr const char* output_marker = ".rollcheck-output";

/// Checks, before any computation, that `target` can be written as a file:
/// its folder exists and is writable, and `target` is not a folder.
/// InputError naming `origin` (the option or key) and the path otherwise.
void check_output_file(const std::filesystem::path& target, const std::string& origin);

/// Checks, before any computation, that `folder` can be written whole: it is
/// new, empty, or a folder rollcheck wrote (it holds the marker); its parent
/// exists and is writable. InputError naming `origin` and the path otherwise:
/// a user's file there is never removed.
void check_output_folder(const std::filesystem::path& folder, const std::string& origin);

/// Fills `folder` whole or not at all: `fill` writes into a temporary folder
/// beside it, which receives the marker and then replaces `folder` (checked
/// with check_output_folder first). If `fill` throws, the temporary folder is
/// removed and `folder` is left as it was.
void write_folder_atomically(const std::filesystem::path& folder, const std::string& origin,
                             const std::function<void(const std::filesystem::path&)>& fill);
} // namespace rollcheck
