#pragma once
// The one way rollcheck reads an input file (a mesh, a case file, a store's
// signature): whole into memory, and only if it is a regular file no larger
// than the caller's cap. A device (/dev/zero, /dev/urandom), a fifo, a socket,
// a directory, a symlink loop, a missing file or one that cannot be read (such
// as /proc/self/mem) is refused by name with an InputError before a byte is
// read, so no path can make a reader run without bound or block forever.
//
// The file is opened non-blocking and checked on the open descriptor (fstat),
// so what is checked is what is read. Files under /proc report size 0 and are
// read up to the cap all the same: the cap holds for every file.
#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>

namespace rollcheck::core
{
/// The bytes of the regular file `path`; InputError naming `what` and the path
/// ("mesh file 'x.obj': is a directory") for anything else, or if the file
/// holds more than `max_bytes` bytes.
std::string read_bounded_file(const std::filesystem::path& path, std::string_view what, std::size_t max_bytes);

/// InputError naming `what` unless `text` has at most `max_lines` lines
/// (newline characters) and no line longer than `max_line_bytes`.
void check_line_caps(std::string_view text, const std::filesystem::path& path, std::string_view what,
                     std::size_t max_lines, std::size_t max_line_bytes);
} // namespace rollcheck::core
