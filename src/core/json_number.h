#pragma once
// A number as JSON, the one convention of every rollcheck output: "inf" /
// "-inf" when infinite (JSON has no infinity; the results store turns them
// back into floats), ComputationError for NaN, which would hide a bug.
#include "core/error.h"
#include <cmath>
#include <nlohmann/json.hpp>

namespace rollcheck
{
inline nlohmann::json json_number(double value)
{
  if (std::isnan(value))
    throw ComputationError("a result came out NaN; refusing to write it");
  if (std::isinf(value))
    return value > 0 ? "inf" : "-inf";
  return value;
}
} // namespace rollcheck
