#pragma once
// A text result beside a subcommand's JSON (a Markdown table), written
// atomically by one rank.
#include "cli/cli.h"
#include <functional>
#include <string>
#include <utility>

namespace rollcheck::cli
{
/// Writes `text` to `path` when it is non-empty, atomically, on rank 0
/// (core/atomic_file.h: a failed write names the file and keeps the old one).
void write_text_output(const std::string& path, const std::string& text);

/// A study that also makes a Markdown table: checks `markdown_path` (option
/// --markdown; none when empty) before `run`, then prints the table
/// (print_summary), writes it on rank 0 and returns `run`'s JSON as the
/// command's summary.
CommandResult run_with_markdown(const std::string& markdown_path,
                                const std::function<std::pair<nlohmann::json, std::string>()>& run);
} // namespace rollcheck::cli
