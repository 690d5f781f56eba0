#pragma once
// The nesting of a TOML text, measured before it is parsed: toml++ parses and
// frees nested tables and arrays by recursion, so a file of 50,000 nested
// tables ([a.a.a...]) or dotted keys would overflow the stack. The depth of a
// point is the number of brackets open there ([ and {, tables and arrays)
// plus the dots of the key being read; strings and comments do not count.
// A case file needs 2 ([[check]]); max_case_nesting leaves room.
#include <cstddef>
#include <filesystem>
#include <string_view>

namespace rollcheck::io
{
inline constexpr std::size_t max_case_nesting = 16;

/// InputError naming `path` and the line if the nesting of `text` exceeds `max_depth`.
void check_toml_nesting(std::string_view text, const std::filesystem::path& path, std::size_t max_depth);
} // namespace rollcheck::io
