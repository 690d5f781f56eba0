#pragma once
// A scene's parameters declared once, each bound to the member of the
// settings struct it sets. The declaration gives the case-file key, the
// option, the unit, the help and the valid range; the default is read from a
// default-constructed Settings, so the library struct stays the only place a
// default is written. bind() turns resolved Parameters into a Settings with no
// hand copying, after every range was checked in Parameters::set.
//
//   BoundSchema<fem::CreaseSettings> s("crease");
//   s.real("load_n", "--load", &fem::CreaseSettings::load_n, "N", "Force on the crease", positive);
//   fem::CreaseSettings setup = s.bind(params);
#include "io/parameters.h"
#include "io/work_budget.h"
#include <algorithm>
#include <functional>
#include <limits>
#include <type_traits>
#include <utility>

namespace rollcheck::io
{
inline constexpr Bounds positive{0.0, std::numeric_limits<double>::infinity(), true};
inline constexpr Bounds non_negative{0.0, std::numeric_limits<double>::infinity(), false};
inline constexpr Bounds unbounded{};
inline constexpr Bounds unit_interval{0.0, 1.0, false};
/// Poisson's ratio of an isotropic, stable solid.
inline constexpr Bounds poisson_range{-1.0, 0.5, true, true};

template <class Settings>
class BoundSchema
{
public:
  explicit BoundSchema(std::string kind) : schema_{std::move(kind), {}} {}

  /// A real member; the option's value times `scale` is stored (e.g. deg -> rad).
  template <class Access>
  BoundSchema& real(std::string key, std::string flag, Access access, std::string unit, std::string help,
                    Bounds bounds = unbounded, double scale = 1.0)
  {
    add({std::move(key), std::move(flag), 0.0, std::move(unit), std::move(help), {}, bounds},
        [access, scale](Settings& s, const Value& v) { std::invoke(access, s) = std::get<double>(v) * scale; },
        [access, scale](const Settings& s) -> Value { return read(access, s) / scale; });
    return *this;
  }

  /// An integer member of any integral type; the range is intersected with the
  /// member type's, so no value is narrowed silently.
  template <class Access>
  BoundSchema& integer(std::string key, std::string flag, Access access, std::string unit, std::string help,
                       Bounds bounds = unbounded)
  {
    using T = std::remove_cvref_t<std::invoke_result_t<Access, Settings&>>;
    static_assert(std::is_integral_v<T>);
    bounds.lower = std::max(bounds.lower, static_cast<double>(std::numeric_limits<T>::min()));
    // An integer beyond 2^53 is not exact in a double; no parameter needs it.
    bounds.upper = std::min({bounds.upper, static_cast<double>(std::numeric_limits<T>::max()), 9007199254740992.0});
    add({std::move(key), std::move(flag), std::int64_t{0}, std::move(unit), std::move(help), {}, bounds},
        [access](Settings& s, const Value& v) { std::invoke(access, s) = static_cast<T>(std::get<std::int64_t>(v)); },
        [access](const Settings& s) -> Value { return static_cast<std::int64_t>(read(access, s)); });
    return *this;
  }

  template <class Access>
  BoundSchema& flag(std::string key, std::string flag, Access access, std::string help)
  {
    add({std::move(key), std::move(flag), false, "", std::move(help)},
        [access](Settings& s, const Value& v) { std::invoke(access, s) = std::get<bool>(v); },
        [access](const Settings& s) -> Value { return static_cast<bool>(read(access, s)); });
    return *this;
  }

  /// A string member (a path, a list of options); `choices` restricts it.
  template <class Access>
  BoundSchema& text(std::string key, std::string flag, Access access, std::string help,
                    std::vector<std::string> choices = {})
  {
    add({std::move(key), std::move(flag), std::string(), "", std::move(help), std::move(choices)},
        [access](Settings& s, const Value& v) { std::invoke(access, s) = std::get<std::string>(v); },
        [access](const Settings& s) -> Value { return std::string(read(access, s)); });
    return *this;
  }

  /// A file path (a string member): relative in a case file, it is taken from
  /// the case file's folder; on the command line, from the working folder.
  template <class Access>
  BoundSchema& path(std::string key, std::string flag, Access access, std::string help)
  {
    text(std::move(key), std::move(flag), access, std::move(help));
    Parameter& p = schema_.parameters.back();
    p.is_path = true;
    const std::string declared = p.former_key.empty() ? p.key : p.former_key;
    p.key = case_key(p.flag, p.unit, true);
    p.former_key = declared == p.key ? "" : declared;
    return *this;
  }

  /// A member of any type chosen by name (an enum): `names` maps each name to its value.
  template <class Access, class T = std::remove_cvref_t<std::invoke_result_t<Access, Settings&>>>
  BoundSchema& choice(std::string key, std::string flag, Access access, std::string help,
                      std::vector<std::pair<std::string, T>> names)
  {
    std::vector<std::string> choices;
    for (const auto& entry : names)
      choices.push_back(entry.first);
    add({std::move(key), std::move(flag), std::string(), "", std::move(help), std::move(choices)},
        [access, names](Settings& s, const Value& v) {
          for (const auto& [name, value] : names)
            if (name == std::get<std::string>(v))
              std::invoke(access, s) = value;
        },
        [access, names](const Settings& s) -> Value {
          for (const auto& [name, value] : names)
            if (value == read(access, s))
              return name;
          return std::string();
        });
    return *this;
  }

  /// The key the last parameter had before it was renamed: a case file that
  /// still uses it is refused with a message naming the key to use.
  BoundSchema& former(std::string key)
  {
    schema_.parameters.back().former_key = std::move(key);
    return *this;
  }

  /// A parameter that sets no member (the scene reads it by name from
  /// Parameters): for what steers the scene itself rather than a library struct.
  BoundSchema& unbound(Parameter parameter)
  {
    const Value fallback = parameter.default_value;
    add(std::move(parameter), [](Settings&, const Value&) {}, [fallback](const Settings&) { return fallback; });
    return *this;
  }

  /// Every parameter of `group`, whose settings are our member reached through
  /// `access`: shared groups such as the body's or the material's parameters.
  template <class Group, class Access>
  BoundSchema& include(const BoundSchema<Group>& group, Access access)
  {
    for (std::size_t i = 0; i < group.schema().parameters.size(); ++i)
      add(group.schema().parameters[i],
          [set = group.setter(i), access](Settings& s, const Value& v) { set(std::invoke(access, s), v); },
          [get = group.getter(i), access](const Settings& s) { return get(read(access, s)); });
    for (const RatioCap& cap : group.schema().ratio_caps)
      schema_.ratio_caps.push_back(cap);
    return *this;
  }

  /// Caps numerator / denominator (two keys of this schema) at `max` (io/work_budget.h).
  BoundSchema& ratio_cap(std::string numerator, std::string denominator, double max, std::string what)
  {
    schema_.ratio_caps.push_back({std::move(numerator), std::move(denominator), max, std::move(what)});
    return *this;
  }

  /// Settings{} with every parameter of `params` stored in its member, once
  /// the schema's ratio caps hold.
  Settings bind(const Parameters& params) const
  {
    params.check_ratio_caps();
    Settings s;
    for (std::size_t i = 0; i < setters_.size(); ++i)
      setters_[i](s, params.value(schema_.parameters[i].key));
    return s;
  }

  const Schema& schema() const { return schema_; }
  const std::function<void(Settings&, const Value&)>& setter(std::size_t i) const { return setters_[i]; }
  const std::function<Value(const Settings&)>& getter(std::size_t i) const { return getters_[i]; }

private:
  /// The member `access` leads to, read from a const Settings: accessors are
  /// written for Settings& (they also set), so they read a copy.
  template <class Access>
  static auto read(const Access& access, const Settings& s)
  {
    Settings copy = s;
    return std::remove_cvref_t<std::invoke_result_t<Access, Settings&>>(std::invoke(access, copy));
  }

  /// The default is the member's value in Settings{}: the library struct is
  /// the only place a default is written.
  void add(Parameter parameter, std::function<void(Settings&, const Value&)> set,
           std::function<Value(const Settings&)> get)
  {
    static const Settings defaults{};
    parameter.default_value = get(defaults);
    // The key follows the one rule (io::case_key); a key declared otherwise
    // is the former key, refused by name in case files.
    if (const std::string key = case_key(parameter.flag, parameter.unit, parameter.is_path); key != parameter.key)
    {
      if (parameter.former_key.empty())
        parameter.former_key = parameter.key;
      parameter.key = key;
    }
    schema_.parameters.push_back(std::move(parameter));
    setters_.push_back(std::move(set));
    getters_.push_back(std::move(get));
  }

  Schema schema_;
  std::vector<std::function<void(Settings&, const Value&)>> setters_;
  std::vector<std::function<Value(const Settings&)>> getters_;
};
} // namespace rollcheck::io
