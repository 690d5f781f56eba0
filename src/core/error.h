#pragma once
// Layer: core. Owns what every layer shares and nothing else: the error types
// (error.h), the atomic writer and output-path checks (atomic_file.h), the JSON
// number convention (json_number.h) and the child-process runner
// (child_process.h). Depends on the standard library, fmt, spdlog and nlohmann_json.
// The two failure kinds every layer raises; the CLI maps them to exit codes
// (InputError -> 2, ComputationError -> 1).
#include <stdexcept>
#include <string>

namespace rollcheck
{
/// Bad input: a file, option or body that cannot be used. The message names it.
struct InputError : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

/// A computation that failed: a diverged solve, an unresolved contact.
struct ComputationError : std::runtime_error
{
  using std::runtime_error::runtime_error;
};
} // namespace rollcheck
