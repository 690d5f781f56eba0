#include "cli/cli.h"
#include "cli/text_output.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include <cstdio>
#include <fstream>
#include <fmt/format.h>
#include <iostream>
#include <spdlog/spdlog.h>

namespace rollcheck::cli
{
namespace
{
bool json_on_stdout = false;
} // namespace

void set_json_on_stdout(bool on_stdout) { json_on_stdout = on_stdout; }

std::FILE* summary_stream() { return json_on_stdout ? stderr : stdout; }

void print_summary(const std::string& text)
{
  if (process_rank() != 0)
    return;
  if (json_on_stdout)
    spdlog::info("\n{}", text);
  else
    fmt::print("{}{}", text, text.ends_with('\n') ? "" : "\n");
  std::fflush(stdout);
}

CLI::Option* add_json_option(CLI::App* sub, std::string& path)
{
  return sub->add_option("--json", path, "Write a machine-readable summary to PATH ('-' for stdout); keys are snake_case with units");
}

void emit_json(const std::string& path, const nlohmann::json& summary)
{
  if (path.empty())
    return;
  // Under mpirun every rank holds the same summary; one writes it.
  if (process_rank() != 0)
    return;
  // NaN has no JSON form; nlohmann writes it as null, which would hide a bug.
  const std::string text = summary.dump(2, ' ', false, nlohmann::json::error_handler_t::replace);
  if (path == "-")
    write_stdout(text + "\n", "the JSON summary (--json -)");
  else
    write_file_atomically(path, text + "\n");
}

void write_text_output(const std::string& path, const std::string& text)
{
  if (path.empty() || process_rank() != 0)
    return;
  write_file_atomically(path, text);
}

CommandResult run_with_markdown(const std::string& markdown_path,
                                const std::function<std::pair<nlohmann::json, std::string>()>& run)
{
  if (!markdown_path.empty())
    check_output_file(markdown_path, "option --markdown");
  auto [summary, table] = run();
  write_text_output(markdown_path, table);
  print_summary(table);
  if (process_rank() != 0)
    return {nlohmann::json(), 0};
  return {std::move(summary), 0};
}
} // namespace rollcheck::cli
