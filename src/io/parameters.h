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
  bool contains(double x) const;
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
};

struct Schema
{
  std::string kind;    ///< the scene's name, the [scene] kind of a case file
  std::vector<Parameter> parameters;
  const Parameter& find(const std::string& key, const std::string& origin) const;
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
};

/// Reads the [scene] table of a case file: its kind, and its keys as overrides
/// of the defaults, then `overrides` ("key=value", the `--set` options).
/// Unknown keys, wrong types and bad values raise InputError naming the file.
struct CaseFile
{
  std::string kind;
  std::map<std::string, Value> values;
  std::vector<CaseCheck> checks; ///< the [[check]] tables (io/case_checks.h)
  std::filesystem::path folder;  ///< where the file is: relative paths in it start there
};
CaseFile read_case_file(const std::filesystem::path& path);
Parameters resolve_case(const CaseFile& file, const Schema& schema, const std::vector<std::string>& overrides,
                        const std::string& origin);
} // namespace rollcheck::io
