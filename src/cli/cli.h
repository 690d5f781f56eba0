#pragma once
// Layer: cli. Owns the `rollcheck` executable: one file per subcommand, each
// exposing add_<name>_command(). Subcommands parse options, call the layers
// below and write results; they hold no physics of their own.
#include <CLI/CLI.hpp>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>

namespace rollcheck::cli
{
/// Registers what runs when `sub` was the parsed subcommand. The runner returns
/// the exit code (0 success); it may throw InputError (exit 2) or
/// ComputationError (exit 1), which main() reports.
void on_run(CLI::App* sub, std::function<int()> runner);

/// Adds the shared `--json PATH` option ("-" for stdout) to a subcommand.
CLI::Option* add_json_option(CLI::App* sub, std::string& path);

/// Writes `summary` to `path` when it is non-empty ("-" is stdout), atomically.
void emit_json(const std::string& path, const nlohmann::json& summary);


void add_mesh_command(CLI::App& app);
void add_oracle_command(CLI::App& app);
void add_search_command(CLI::App& app);
void add_hertz_command(CLI::App& app);
void add_fem_sds_command(CLI::App& app);
void add_crease_command(CLI::App& app);
void add_run_command(CLI::App& app);
void add_batch_command(CLI::App& app);
void add_report_command(CLI::App& app);
void add_audit_command(CLI::App& app);
void add_validate_command(CLI::App& app);
} // namespace rollcheck::cli
