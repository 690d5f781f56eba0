#include "cli/cli.h"
#include "core/atomic_file.h"

namespace rollcheck::cli
{
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
} // namespace rollcheck::cli
