#pragma once
// A text result beside a subcommand's JSON (a Markdown table), written
// atomically by one rank.
#include <string>

namespace rollcheck::cli
{
/// Writes `text` to `path` when it is non-empty, atomically, on rank 0;
/// ComputationError naming `origin` if it cannot.
void write_text_output(const std::string& path, const std::string& text, const std::string& origin);
} // namespace rollcheck::cli
