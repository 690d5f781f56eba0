#pragma once
// Where the processes of one job keep the FEM slice table's solved nodes
// (fem/scenes/slice_table_store.h): the folder named by the environment
// variable ROLLCHECK_SLICE_TABLE_DIR. The audit sets it for its commands
// (audit/runner.cpp), a folder of its own removed with its scratch; unset,
// every process solves its own table. Here in core because the audit, which
// sets it, does not link the FEM layer that reads it.
#include <cstdlib>
#include <filesystem>
#include <optional>

namespace rollcheck
{
inline constexpr const char* slice_table_folder_variable = "ROLLCHECK_SLICE_TABLE_DIR";

/// The folder the variable names, if it is set and not empty.
inline std::optional<std::filesystem::path> slice_table_folder()
{
  const char* folder = std::getenv(slice_table_folder_variable);
  if (!folder || !*folder)
    return std::nullopt;
  return std::filesystem::path(folder);
}
} // namespace rollcheck
