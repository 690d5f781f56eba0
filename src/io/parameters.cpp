#include "io/parameters.h"
#include "core/bounded_file.h"
#include "core/error.h"
#include "io/toml_nesting.h"
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <map>
#include <fmt/format.h>
#include <toml++/toml.h>

namespace rollcheck::io
{
namespace
{
std::string type_name(const Value& v)
{
  return std::visit(
      [](const auto& x) -> std::string {
        using T = std::decay_t<decltype(x)>;
        if constexpr (std::is_same_v<T, bool>) return "true or false";
        else if constexpr (std::is_same_v<T, std::int64_t>) return "an integer";
        else if constexpr (std::is_same_v<T, double>) return "a number";
        else return "a string";
      },
      v);
}

std::string to_text(const Value& v)
{
  return std::visit(
      [](const auto& x) -> std::string {
        using T = std::decay_t<decltype(x)>;
        if constexpr (std::is_same_v<T, bool>) return x ? "true" : "false";
        else if constexpr (std::is_same_v<T, std::string>) return x;
        else return fmt::format("{}", x);
      },
      v);
}
bool valid_utf8(const std::string& text)
{
  try
  {
    (void)nlohmann::json(text).dump();
    return true;
  }
  catch (const nlohmann::json::type_error&)
  {
    return false;
  }
}

/// The [[check]] tables of a case file (io/case_checks.h), each validated.
std::vector<CaseCheck> read_checks(const toml::table& table, const std::string& name)
{
  std::vector<CaseCheck> checks;
  const toml::node* node = table.get("check");
  if (!node)
    return checks;
  const toml::array* array = node->as_array();
  if (!array || !array->is_array_of_tables())
    throw InputError(fmt::format("case file '{}': 'check' must be an array of tables ([[check]])", name));
  for (std::size_t i = 0; i < array->size(); ++i)
  {
    const toml::table& t = *array->get(i)->as_table();
    const std::string where = fmt::format("case file '{}': check {}", name, i + 1);
    for (const auto& [key, value] : t)
      if (key.str() != "pointer" && key.str() != "reference" && key.str() != "max_abs" && key.str() != "value"
          && key.str() != "rel_tol" && key.str() != "expect")
        throw InputError(fmt::format("{}: unknown key '{}' (pointer, reference, max_abs, value, rel_tol, expect)",
                                     where, key.str()));
    CaseCheck c;
    c.pointer = t["pointer"].value_or(std::string());
    c.reference = t["reference"].value_or(std::string());
    if (c.pointer.empty() || c.pointer[0] != '/')
      throw InputError(fmt::format("{}: 'pointer' must be a JSON pointer such as \"/p0_error\"", where));
    if (c.reference.empty())
      throw InputError(fmt::format("{}: 'reference' must say what the value is compared with", where));
    c.max_abs = t["max_abs"].value<double>();
    c.value = t["value"].value<double>();
    c.rel_tol = t["rel_tol"].value_or(0.0);
    c.expect = t["expect"].value<bool>();
    const int criteria = c.max_abs.has_value() + c.value.has_value() + c.expect.has_value();
    if (criteria != 1)
      throw InputError(fmt::format("{}: give exactly one of max_abs, value (with rel_tol) or expect", where));
    auto finite_non_negative = [](double x) { return std::isfinite(x) && x >= 0; };
    if ((c.max_abs && !finite_non_negative(*c.max_abs)) || (c.value && (!std::isfinite(*c.value) || *c.value == 0))
        || !finite_non_negative(c.rel_tol) || (c.value && t["rel_tol"].value<double>() == std::nullopt))
      throw InputError(fmt::format("{}: max_abs and rel_tol must be finite and >= 0 (an infinite tolerance passes "
                                   "anything); value must be finite and non-zero, with its rel_tol",
                                   where));
    checks.push_back(std::move(c));
  }
  return checks;
}
} // namespace

std::string case_key(const std::string& flag, const std::string& unit, bool is_path)
{
  static const std::map<std::string, std::string> suffixes = {
      {"", ""},           {"m", "_m"},       {"N", "_n"},         {"Pa", "_pa"},    {"N/m", "_n_per_m"},
      {"deg", "_deg"},    {"rad", "_rad"},   {"s", "_s"},         {"kg", "_kg"},    {"m/s^2", "_m_s2"},
      {"rad/s", "_rad_s"}, {"N m s", "_n_m_s"}, {"1/m", "_per_m"}, {"m^2", "_m2"}, {"m^3", "_m3"}};
  const auto suffix = suffixes.find(unit);
  if (suffix == suffixes.end())
    throw std::logic_error(fmt::format("option {}: the unit '{}' has no case-key suffix", flag, unit));
  std::string name = flag.substr(flag.find_first_not_of('-'));
  std::ranges::replace(name, '-', '_');
  return name + (is_path ? "_file" : suffix->second);
}

std::string Schema::unknown_key(const std::string& key) const
{
  for (const Parameter& p : parameters)
    if (p.former_key == key)
      return fmt::format("key '{}' is now '{}' (a key is its option's name with its unit, {})", key, p.key, p.flag);
  return fmt::format("unknown key '{}'", key);
}

const Parameter& Schema::find(const std::string& key, const std::string& origin) const
{
  for (const Parameter& p : parameters)
    if (p.key == key)
      return p;
  std::string known;
  for (const Parameter& p : parameters)
    known += (known.empty() ? "" : ", ") + p.key;
  throw InputError(fmt::format("{}: {} for a '{}' scene (known: {})", origin, unknown_key(key), kind, known));
}

Parameters::Parameters(const Schema& schema) : schema_(&schema)
{
  for (const Parameter& p : schema.parameters)
    values_[p.key] = p.default_value;
}

void Parameters::set(const std::string& key, const Value& given, const std::string& origin)
{
  const Parameter& p = schema_->find(key, origin);
  Value value = given;
  // Integers are accepted where a number is expected.
  if (std::holds_alternative<double>(p.default_value) && std::holds_alternative<std::int64_t>(given))
    value = static_cast<double>(std::get<std::int64_t>(given));
  if (value.index() != p.default_value.index())
    throw InputError(fmt::format("{}: '{}' must be {}, got '{}'", origin, key, type_name(p.default_value),
                                 to_text(given)));
  // The default is valid as given, even where it lies outside the range or
  // the choices ("" for "none", -1 for "the model's"): a case file may state it.
  if (value == p.default_value)
  {
    values_[key] = value;
    return;
  }
  if (const double* x = std::get_if<double>(&value); x && !std::isfinite(*x))
    throw InputError(fmt::format("{}: '{}' must be finite, got {}", origin, key, *x));
  if (const double* x = std::get_if<double>(&value); x && !p.bounds.contains(*x))
    throw InputError(fmt::format("{}: '{}' must be {}{}, got {}", origin, key, p.bounds.describe(),
                                 p.unit.empty() ? "" : " " + p.unit, *x));
  if (const std::int64_t* n = std::get_if<std::int64_t>(&value); n && !p.bounds.contains_integer(*n))
    throw InputError(fmt::format("{}: '{}' must be an integer {}, got {}", origin, key, p.bounds.describe(), *n));
  if (const std::string* s = std::get_if<std::string>(&value); s && !valid_utf8(*s))
    throw InputError(fmt::format("{}: '{}' is not valid UTF-8 text", origin, key));
  if (const std::string* s = std::get_if<std::string>(&value); s && !p.choices.empty()
      && std::find(p.choices.begin(), p.choices.end(), *s) == p.choices.end())
    throw InputError(fmt::format("{}: '{}' must be one of {}, got '{}'", origin, key, fmt::join(p.choices, "|"), *s));
  values_[key] = value;
}

void Parameters::set_text(const std::string& key, const std::string& text, const std::string& origin)
{
  const Parameter& p = schema_->find(key, origin);
  Value value;
  try
  {
    std::size_t used = 0;
    if (std::holds_alternative<bool>(p.default_value))
    {
      if (text != "true" && text != "false")
        throw std::invalid_argument(text);
      value = text == "true";
      used = text.size();
    }
    else if (std::holds_alternative<std::int64_t>(p.default_value))
      value = static_cast<std::int64_t>(std::stoll(text, &used));
    else if (std::holds_alternative<double>(p.default_value))
      value = std::stod(text, &used);
    else
    {
      value = text;
      used = text.size();
    }
    if (used != text.size())
      throw std::invalid_argument(text);
  }
  catch (const std::logic_error&)
  {
    throw InputError(fmt::format("{}: '{}' must be {}, got '{}'", origin, key, type_name(p.default_value), text));
  }
  set(key, value, origin);
}

bool Bounds::contains(double x) const
{
  if (or_zero && x == 0)
    return true;
  return (lower_open ? x > lower : x >= lower) && (upper_open ? x < upper : x <= upper);
}

bool Bounds::contains_integer(std::int64_t n) const
{
  // long double holds every int64 exactly; a double would round 2^53 + 1 down
  // to 2^53 and let it pass an upper bound of 2^53.
  const long double x = static_cast<long double>(n);
  if (or_zero && n == 0)
    return true;
  return (lower_open ? x > lower : x >= lower) && (upper_open ? x < upper : x <= upper);
}

std::string Bounds::describe() const
{
  if (or_zero)
  {
    Bounds rest = *this;
    rest.or_zero = false;
    return "0 or " + rest.describe();
  }
  const bool has_lower = std::isfinite(lower), has_upper = std::isfinite(upper);
  if (has_lower && has_upper)
    return fmt::format("in {}{:g}, {:g}{}", lower_open ? "(" : "[", lower, upper, upper_open ? ")" : "]");
  if (has_lower)
    return fmt::format("{} {:g}", lower_open ? ">" : ">=", lower);
  if (has_upper)
    return fmt::format("{} {:g}", upper_open ? "<" : "<=", upper);
  return "finite";
}

const Value& Parameters::value(const std::string& key) const
{
  if (auto it = values_.find(key); it != values_.end())
    return it->second;
  throw std::logic_error(fmt::format("the '{}' scene has no parameter '{}'", schema_->kind, key));
}

void Parameters::check_ratio_caps() const
{
  auto number = [&](const std::string& key) {
    const Value& v = value(key);
    return std::holds_alternative<double>(v) ? std::get<double>(v) : static_cast<double>(std::get<std::int64_t>(v));
  };
  for (const RatioCap& cap : schema_->ratio_caps)
    if (const double ratio = number(cap.numerator) / number(cap.denominator); !(ratio <= cap.max))
      throw InputError(fmt::format("'{}' / '{}' asks for {:.3g} {}, more than the {:g} of the work budget "
                                   "(docs/guide/case-files.md#limits)",
                                   cap.numerator, cap.denominator, ratio, cap.what, cap.max));
}

double Parameters::real(const std::string& key) const { return std::get<double>(value(key)); }
std::int64_t Parameters::integer(const std::string& key) const { return std::get<std::int64_t>(value(key)); }
bool Parameters::flag(const std::string& key) const { return std::get<bool>(value(key)); }
const std::string& Parameters::text(const std::string& key) const { return std::get<std::string>(value(key)); }

nlohmann::json Parameters::to_json() const
{
  nlohmann::json j = nlohmann::json::object();
  j["kind"] = schema_->kind;
  for (const auto& entry : values_)
    std::visit([&](const auto& x) { j[entry.first] = x; }, entry.second);
  return j;
}

SchemaOptions::SchemaOptions(CLI::App* sub, const Schema& schema) : schema_(&schema)
{
  for (const Parameter& p : schema.parameters)
  {
    const std::string unit = p.unit.empty() ? "" : fmt::format(" [{}]", p.unit);
    const bool bounded = std::isfinite(p.bounds.lower) || std::isfinite(p.bounds.upper);
    const std::string help = fmt::format("{}{} (default: {}{})", p.help, unit, to_text(p.default_value),
                                         bounded ? "; " + p.bounds.describe() : "");
    if (std::holds_alternative<bool>(p.default_value))
    {
      switches_[p.key] = false;
      sub->add_flag(p.flag, switches_.at(p.key), help);
      continue;
    }
    CLI::Option* opt = sub->add_option(p.flag, given_[p.key], help);
    options_[p.key] = opt;
    opt->type_name(std::holds_alternative<std::int64_t>(p.default_value) ? "INT"
                   : std::holds_alternative<double>(p.default_value) ? "NUMBER"
                                                                    : "TEXT");
    if (!p.choices.empty())
      opt->check(CLI::IsMember(p.choices));
  }
  // add_option stored references into given_; no entry may be added later.
}

Parameters SchemaOptions::apply() const
{
  Parameters params(*schema_);
  for (const Parameter& p : schema_->parameters)
  {
    if (auto it = switches_.find(p.key); it != switches_.end())
    {
      if (it->second)
        params.set(p.key, true, "option " + p.flag);
    }
    else if (options_.at(p.key)->count() > 0)
    {
      // Given, even as "": an empty number is refused, not read as the default.
      const std::string& text = given_.at(p.key);
      if (text.empty() && (p.is_path || !std::holds_alternative<std::string>(p.default_value)))
        throw InputError(fmt::format("option {}: the value is empty", p.flag));
      params.set_text(p.key, text, "option " + p.flag);
    }
  }
  return params;
}

CaseFile read_case_file(const std::filesystem::path& path)
{
  const std::string name = path.string();
  const std::string text = core::read_bounded_file(path, "case file", max_case_file_bytes);
  core::check_line_caps(text, path, "case file", max_case_file_lines, max_case_line_bytes);
  check_toml_nesting(text, path, max_case_nesting);
  toml::table table;
  try
  {
    table = toml::parse(text, name);
  }
  catch (const toml::parse_error& e)
  {
    throw InputError(fmt::format("case file '{}': malformed TOML at line {}: {}", name,
                                 e.source().begin.line, e.description()));
  }
  for (const auto& [key, node] : table)
    if (key.str() != "scene" && key.str() != "check")
      throw InputError(fmt::format("case file '{}': unknown top-level key '{}' (the scene goes under [scene], "
                                   "its checks under [[check]])",
                                   name, key.str()));
  const toml::table* scene = table["scene"].as_table();
  if (!scene)
    throw InputError(fmt::format("case file '{}': no [scene] table", name));
  CaseFile file;
  for (const auto& [key, node] : *scene)
  {
    const std::string k(key.str());
    Value value;
    if (auto b = node.value<bool>(); node.is_boolean())
      value = *b;
    else if (node.is_integer())
      value = *node.value<std::int64_t>();
    else if (node.is_floating_point())
      value = *node.value<double>();
    else if (node.is_string())
      value = *node.value<std::string>();
    else
      throw InputError(fmt::format("case file '{}': key '{}' must be a boolean, number or string", name, k));
    if (k == "kind")
    {
      if (!std::holds_alternative<std::string>(value))
        throw InputError(fmt::format("case file '{}': 'kind' must be a string", name));
      file.kind = std::get<std::string>(value);
    }
    else
      file.values[k] = value;
  }
  if (file.kind.empty())
    throw InputError(fmt::format("case file '{}': [scene] has no 'kind'", name));
  file.checks = read_checks(table, name);
  file.folder = std::filesystem::absolute(path).parent_path();
  return file;
}

Parameters resolve_case(const CaseFile& file, const Schema& schema, const std::vector<std::string>& overrides,
                        const std::string& origin)
{
  Parameters params(schema);
  // Every bad key of the file is named at once, not one per run.
  std::vector<std::string> unknown, problems;
  for (const auto& [key, value] : file.values)
  {
    const auto known = std::ranges::find(schema.parameters, key, &Parameter::key);
    if (known == schema.parameters.end())
    {
      unknown.push_back(schema.unknown_key(key));
      continue;
    }
    const std::string* text = std::get_if<std::string>(&value);
    try
    {
      if (text && known->is_path && !text->empty() && std::filesystem::path(*text).is_relative())
        params.set(key, (file.folder / *text).lexically_normal().string(), origin);
      else
        params.set(key, value, origin);
    }
    catch (const InputError& e)
    {
      problems.emplace_back(e.what());
    }
  }
  if (!unknown.empty())
  {
    std::string known;
    for (const Parameter& p : schema.parameters)
      known += (known.empty() ? "" : ", ") + p.key;
    problems.insert(problems.begin(), fmt::format("{}: {} for a '{}' scene (known: {})", origin,
                                                  fmt::join(unknown, "; "), schema.kind, known));
  }
  if (!problems.empty())
    throw InputError(fmt::format("{}", fmt::join(problems, "\n")));
  for (const std::string& assignment : overrides)
  {
    const auto eq = assignment.find('=');
    if (eq == std::string::npos || eq == 0)
      throw InputError(fmt::format("--set '{}': expected key=value", assignment));
    std::string key = assignment.substr(0, eq);
    if (key.rfind("scene.", 0) == 0)
      key = key.substr(6);
    params.set_text(key, assignment.substr(eq + 1), fmt::format("--set {}", assignment));
  }
  return params;
}
} // namespace rollcheck::io
