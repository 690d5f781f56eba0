#include "io/toml_nesting.h"
#include "core/error.h"
#include <fmt/format.h>
#include <string>

namespace rollcheck::io
{
namespace
{
/// The index just past the string that starts at `at` (a quote), or the text's
/// end: basic strings ("...", """...""") take escapes, literal ones do not.
std::size_t skip_string(std::string_view text, std::size_t at)
{
  const char quote = text[at];
  const bool triple = text.substr(at, 3) == std::string(3, quote);
  const std::string_view close = triple ? text.substr(at, 3) : text.substr(at, 1);
  for (std::size_t i = at + close.size(); i < text.size(); ++i)
  {
    if (quote == '"' && text[i] == '\\')
      ++i;
    else if (!triple && text[i] == '\n')
      return i; // an unterminated one-line string: the parser names it
    else if (text.substr(i, close.size()) == close)
      return i + close.size();
  }
  return text.size();
}
} // namespace

void check_toml_nesting(std::string_view text, const std::filesystem::path& path, std::size_t max_depth)
{
  std::string open; // the brackets open here, innermost last
  std::size_t dots = 0, line = 1;
  bool in_key = true; // reading a key (or a table header) rather than a value
  for (std::size_t i = 0; i < text.size();)
  {
    const char c = text[i];
    if (c == '"' || c == '\'')
    {
      const std::size_t end = skip_string(text, i);
      for (std::size_t k = i; k < end; ++k)
        line += text[k] == '\n';
      i = end;
      continue;
    }
    if (c == '#')
    {
      i = std::min(text.find('\n', i), text.size());
      continue;
    }
    if (c == '\n')
    {
      ++line;
      dots = 0;
      in_key = open.empty();
    }
    else if (c == '[' || c == '{')
    {
      open.push_back(c);
      if (c == '{')
        in_key = true, dots = 0;
    }
    else if ((c == ']' || c == '}') && !open.empty())
      open.pop_back();
    else if (c == '=')
      in_key = false, dots = 0;
    else if (c == ',' && !open.empty() && open.back() == '{')
      in_key = true, dots = 0;
    else if (c == '.' && in_key)
      ++dots;
    if (open.size() + dots > max_depth)
      throw InputError(fmt::format("case file '{}': line {} nests tables, arrays or dotted keys deeper than {} "
                                   "levels (a case file needs 2)",
                                   path.string(), line, max_depth));
    ++i;
  }
}
} // namespace rollcheck::io
