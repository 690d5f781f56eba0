#include "io/case_hash.h"
#include "core/build_id.h"
#include "core/sha256.h"
#include "rollcheck_version.h"
#include <fmt/format.h>

namespace rollcheck::io
{
std::string case_hash(const nlohmann::json& resolved_parameters)
{
  const std::string text
      = fmt::format("rollcheck {} build {}\n{}", ROLLCHECK_VERSION, build_id(), resolved_parameters.dump());
  return sha256_hex(text).substr(0, 16);
}
} // namespace rollcheck::io
