#pragma once
// Named, typed, unit-carrying parameters of a scene. One Schema serves both
// the subcommand's options (--flag) and the case file's keys ([scene] table,
// `--set key=value`), so the two cannot drift apart.
#include <cstdint>
#include "io/case_checks.h"
#include <filesystem>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <variant>
#include <vector>

namespace CLI
{
class App;
class Option;
}

namespace rollcheck::io
{
using Value = std::variant<bool, std::int64_t, double, std::string>;

/// Valid range of a number (an integer's too): lower <= x <= upper, or strict
/// where the end is open. Checked in Parameters::set, the one place for it.
struct Bounds
{
  double lower = -std::numeric_limits<double>::infinity();
  double upper = std::numeric_limits<double>::infinity();
  bool lower_open = false;
  bool upper_open = false;
  bool or_zero = false; ///< 0 is valid too ("0: one per core", "0: off")
  bool contains(double x) const;
  bool contains_integer(std::int64_t n) const; ///< exact for every int64

  std::string describe() const; ///< "> 0", "in [0, 1]", ...
};

struct Parameter
{
  std::string key;     ///< case-file key, snake_case with its unit: radius_m
  std::string flag;    ///< command-line option: --radius
  Value default_value; ///< its type is the parameter's type
  std::string unit;    ///< SI unit, or "" for a pure number
  std::string help;    ///< what it is and where the default comes from
  std::vector<std::string> choices = {}; ///< allowed strings, if restricted
  Bounds bounds = {};                    ///< valid range of a number
  /// A file path: relative in a case file, it is taken from the case file's folder.
  bool is_path = false;
  /// The key this parameter had before keys followed case_key(); a case file
  /// that still uses it is refused with a message naming the key to use.
  std::string former_key = {};
};

/// The one rule for case keys: the option's long name in snake_case, with the
/// unit's suffix where it has a unit (--load [N] -> load_n, --load-per-length
/// [N/m] -> load_per_length_n_per_m, --dt [s] -> dt_s), and `_file` for a path
/// (--mesh -> mesh_file). std::logic_error for a unit without a suffix here.
std::string case_key(const std::string& flag, const std::string& unit, bool is_path);

/// A cap on the work two parameters multiply: numerator / denominator <= max
/// (time steps = duration / dt). Checked once every value is set (BoundSchema::bind).
struct RatioCap
{
  std::string numerator;   ///< a key of the schema
  std::string denominator; ///< a key of the schema
  double max = 0;
  std::string what; ///< what the ratio counts: "rigid-body time steps"
};

struct Schema
{
  std::string kind;    ///< the scene's name, the [scene] kind of a case file
  std::vector<Parameter> parameters;
  std::vector<RatioCap> ratio_caps = {};
  const Parameter& find(const std::string& key, const std::string& origin) const;
  /// The message for a key no parameter has: "unknown key", or the key that
  /// replaced a former one.
  std::string unknown_key(const std::string& key) const;
};

class Parameters
{
public:
  explicit Parameters(const Schema& schema);
  /// Sets `key` from text, parsed by the parameter's type; `origin` names
  /// where the text came from for the error message.
  void set_text(const std::string& key, const std::string& text, const std::string& origin);
  void set(const std::string& key, const Value& value, const std::string& origin);
  double real(const std::string& key) const;
  std::int64_t integer(const std::string& key) const;
  bool flag(const std::string& key) const;
  const std::string& text(const std::string& key) const;
  /// The value of `key`; std::logic_error naming it if the schema has no such key.
  const Value& value(const std::string& key) const;
  const Schema& schema() const { return *schema_; }
  nlohmann::json to_json() const;
  /// InputError naming both keys if a RatioCap of the schema does not hold.
  void check_ratio_caps() const;

private:
  const Schema* schema_;
  std::map<std::string, Value> values_;
};

/// Adds one option per parameter to `sub`; after parsing, call apply().
class SchemaOptions
{
public:
  SchemaOptions(CLI::App* sub, const Schema& schema);
  /// Parameters from the defaults overridden by the options given.
  Parameters apply() const;

private:
  const Schema* schema_;
  std::map<std::string, std::string> given_;
  std::map<std::string, bool> switches_;
  std::map<std::string, CLI::Option*> options_;
};

/// Reads the [scene] table of a case file: its kind, and its keys as overrides
/// of the defaults, then `overrides` ("key=value", the `--set` options).
/// Unknown keys, wrong types and bad values raise one InputError naming the
/// file and every bad key. The file is read by core::read_bounded_file (a
/// regular file of at most max_case_file_bytes, max_case_file_lines lines of at
/// most max_case_line_bytes) and its nesting checked (io/toml_nesting.h)
/// before the TOML parser sees it: the largest case file of cases/ is under
/// 4 kB, so these bounds only refuse what is not a case file.
struct CaseFile
{
  std::string kind;
  std::map<std::string, Value> values;
  std::vector<CaseCheck> checks; ///< the [[check]] tables (io/case_checks.h)
  std::filesystem::path folder;  ///< where the file is: relative paths in it start there
};
inline constexpr std::size_t max_case_file_bytes = std::size_t{1} << 20;
inline constexpr std::size_t max_case_file_lines = 10000;
inline constexpr std::size_t max_case_line_bytes = 4096;
CaseFile read_case_file(const std::filesystem::path& path);
Parameters resolve_case(const CaseFile& file, const Schema& schema, const std::vector<std::string>& overrides,
                        const std::string& origin);
} // namespace rollcheck::io
