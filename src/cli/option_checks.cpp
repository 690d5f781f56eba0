#include "cli/option_checks.h"
#include <cmath>
#include <string>

namespace rollcheck::cli
{
CLI::Validator finite_number()
{
  return CLI::Validator(
      [](std::string& text) -> std::string {
        try
        {
          std::size_t used = 0;
          const double x = std::stod(text, &used);
          if (used == text.size() && std::isfinite(x))
            return "";
        }
        catch (const std::logic_error&)
        {
        }
        return "must be a finite number, got '" + text + "'";
      },
      "FINITE");
}

CLI::Validator non_empty()
{
  return CLI::Validator([](std::string& text) -> std::string { return text.empty() ? "must not be empty" : ""; },
                        "");
}
} // namespace rollcheck::cli
