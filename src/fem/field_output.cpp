#include "fem/field_output.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include <cctype>
#include <cerrno>
#include <cstdlib>
#include <fmt/format.h>

namespace rollcheck::fem
{
std::chrono::seconds write_patience()
{
  const char* text = std::getenv(write_patience_variable);
  if (!text || !*text)
    return std::chrono::seconds(30);
  char* end = nullptr;
  errno = 0;
  const long seconds = std::strtol(text, &end, 10);
  // Digits only: strtol would also take a leading space or sign.
  if (!std::isdigit(static_cast<unsigned char>(text[0])) || errno != 0 || *end != '\0' || seconds < 1
      || seconds > 86400)
    throw InputError(fmt::format("{}='{}': the write's patience must be a whole number of seconds from 1 to 86400",
                                 write_patience_variable, text));
  return std::chrono::seconds(seconds);
}

void check_field_output(const std::filesystem::path& xdmf_path, const std::string& origin)
{
  if (xdmf_path.extension() != ".xdmf")
    throw InputError(fmt::format("{} '{}' must end in .xdmf", origin, xdmf_path.string()));
  check_output_file(xdmf_path, origin);
  write_patience();
}
} // namespace rollcheck::fem
