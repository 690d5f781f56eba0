#pragma once
// Every result file is written whole or not at all: the writer fills a
// temporary file beside the target (`.STEM.tmpPID.EXT`), flushes it to the
// disk (fsync) and renames it over the target; every step is checked, so a
// full disk or a failed rename is an error naming the target (exit 1) and
// the previous file stays as it was. Output paths are checked before any
// computation (check_output_file, check_output_folder); what a folder output
// may remove is core/output_manifest.h's rule. Lives in core because every
// layer writes files.
#include "core/output_manifest.h"
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>

namespace rollcheck
{
/// Calls `fill(tmp)` with a temporary path in the target's directory, flushes
/// the file to the disk, then renames it to `target`. If `fill` throws, or
/// the flush or the rename fails (ComputationError naming `target`), the
/// temporary is removed and the target is left untouched. `fill` must report
/// its own write errors (write_file_atomically does).
void write_atomically(const std::filesystem::path& target,
                      const std::function<void(const std::filesystem::path&)>& fill);

/// Moves the finished file `from` (written beside `target` by a writer of
/// its own, as DOLFINx's XDMFFile) over `target`: flushed to the disk, then
/// renamed; ComputationError naming `target` if either fails.
void move_into_place(const std::filesystem::path& from, const std::filesystem::path& target);

/// Writes `bytes` to `target` through write_atomically, every write(2) and the
/// close checked: ComputationError naming `target` (with the system's reason,
/// "No space left on device") if any fails.
void write_file_atomically(const std::filesystem::path& target, std::string_view bytes);

/// Writes `bytes` to stdout and flushes it; ComputationError naming `what` if
/// stdout cannot take them (a closed pipe, /dev/full).
void write_stdout(std::string_view bytes, const std::string& what);

/// Checks, before any computation, that `target` can be written as a file:
/// its folder exists and is writable, and `target` is absent or a regular
/// file (never a folder, a device or a fifo, which the rename would replace).
/// InputError naming `origin` (the option or key) and the path otherwise.
void check_output_file(const std::filesystem::path& target, const std::string& origin);

/// Checks, before any computation, that the `--out` folder `folder` can be
/// written into: it is a writable folder, or it is absent and its parent is
/// one (rollcheck creates the --out folder, never its parents). InputError
/// naming `origin` and the path otherwise. What may be replaced inside is
/// the manifest's to say (check_output_entries).
void check_output_location(const std::filesystem::path& folder, const std::string& origin);

/// Checks, before any computation, that `folder` can be written as a whole
/// folder output: check_output_location, and it is new, empty, or holds
/// rollcheck's manifest. InputError naming `origin` and the path otherwise.
void check_output_folder(const std::filesystem::path& folder, const std::string& origin);

/// Fills the folder output `folder` (checked with check_output_folder):
/// `fill` writes into a temporary folder beside it, `.NAME.tmpPID/`. A new or
/// empty `folder` is then replaced by it in one rename; otherwise each entry
/// it made replaces its namesake, the entries the old manifest listed and
/// this run did not make are removed, and the user's files there stay as
/// they are (one of them where this run made an entry of that name:
/// InputError, nothing changed). If `fill` throws, the temporary folder is
/// removed and `folder` is left as it was. A temporary folder of a killed
/// run (its process gone, rollcheck's manifest inside) is removed first.
void write_folder_atomically(const std::filesystem::path& folder, const std::string& origin,
                             const std::function<void(const std::filesystem::path&)>& fill);
} // namespace rollcheck
