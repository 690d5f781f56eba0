#pragma once
// The names of an enumeration's values, as options, case files and JSON spell
// them: one table of (name, value) pairs per enumeration, read both ways.
#include "core/error.h"
#include <fmt/format.h>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace rollcheck
{
template <class T>
using NamedValues = std::vector<std::pair<std::string, T>>;

/// The first name `names` gives `value`; std::logic_error naming `what` when
/// none does (a value missing from its table is a bug, not an input).
template <class T>
const std::string& name_of(const NamedValues<T>& names, T value, const std::string& what)
{
  for (const auto& [name, named] : names)
    if (named == value)
      return name;
  throw std::logic_error("unnamed " + what);
}

/// The value `names` calls `name`; else InputError "ORIGIN: WHAT must be A, B
/// or C, got 'NAME'".
template <class T>
T parse_named(const NamedValues<T>& names, const std::string& name, const std::string& what,
              const std::string& origin)
{
  std::string choices;
  for (std::size_t i = 0; i < names.size(); ++i)
  {
    if (names[i].first == name)
      return names[i].second;
    choices += (i == 0 ? "" : (i + 1 == names.size() ? " or " : ", ")) + names[i].first;
  }
  throw InputError(fmt::format("{}: {} must be {}, got '{}'", origin, what, choices, name));
}
} // namespace rollcheck
