#pragma once
// The name of a value in a list of (name, value) pairs, the form of the
// wing's choices (method_names(), family_score_names()): what the options and
// the JSON spell.
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace rollcheck::study::optimize
{
/// The first name `names` gives `value`; std::logic_error naming `what` when
/// none does (a value missing from its list).
template <class T>
const std::string& name_of(const std::vector<std::pair<std::string, T>>& names, T value, const std::string& what)
{
  for (const auto& [name, named] : names)
    if (named == value)
      return name;
  throw std::logic_error("unnamed " + what);
}
} // namespace rollcheck::study::optimize
