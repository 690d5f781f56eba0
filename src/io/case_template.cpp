#include "io/case_template.h"
#include <cmath>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

namespace rollcheck::io
{
namespace
{
/// The value as TOML writes it: strings quoted, numbers in full precision.
std::string toml_value(const Value& value)
{
  if (const auto* text = std::get_if<std::string>(&value))
    return nlohmann::json(*text).dump();
  if (const auto* flag = std::get_if<bool>(&value))
    return *flag ? "true" : "false";
  if (const auto* x = std::get_if<double>(&value))
    // A whole number keeps its ".0", so that TOML reads it back as a float.
    return std::trunc(*x) == *x && std::abs(*x) < 1e15 ? fmt::format("{:.1f}", *x) : fmt::format("{}", *x);
  return fmt::format("{}", std::get<std::int64_t>(value));
}

/// The help as comment lines of at most about 100 characters.
std::string comment(const std::string& text)
{
  std::string out, line = "#";
  for (std::size_t at = 0; at < text.size();)
  {
    const std::size_t space = std::min(text.find(' ', at), text.size());
    const std::string word = text.substr(at, space - at);
    if (line.size() + 1 + word.size() > 100 && line != "#")
    {
      out += line + "\n";
      line = "#";
    }
    line += " " + word;
    at = space + 1;
  }
  return out + line + "\n";
}
} // namespace

std::string case_template(const Schema& schema)
{
  std::string out = comment(fmt::format("A '{}' case (`rollcheck {} --help`). Run it with `rollcheck run FILE.toml`; "
                                        "every key is at its default, uncomment a line to change it "
                                        "(docs/guide/case-files.md).",
                                        schema.kind, schema.kind));
  out += fmt::format("[scene]\nkind = \"{}\"\n", schema.kind);
  for (const Parameter& p : schema.parameters)
  {
    std::string what = p.help;
    if (!p.unit.empty())
      what += fmt::format(" [{}]", p.unit);
    if (std::isfinite(p.bounds.lower) || std::isfinite(p.bounds.upper) || p.bounds.or_zero)
      what += "; " + p.bounds.describe();
    if (!p.choices.empty())
      what += fmt::format("; one of {}", fmt::join(p.choices, ", "));
    if (p.is_path)
      what += "; a path, relative to this file's folder";
    out += "\n" + comment(fmt::format("{} (option {})", what, p.flag));
    out += fmt::format("# {} = {}\n", p.key, toml_value(p.default_value));
  }
  return out;
}
} // namespace rollcheck::io
