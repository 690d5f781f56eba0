#pragma once
// A number as JSON, the one convention of every rollcheck output: "inf" /
// "-inf" when infinite (JSON has no infinity; the results store turns them
// back into floats), ComputationError for NaN, which would hide a bug.
#include "core/error.h"
#include <cmath>
#include <nlohmann/json.hpp>
#include <optional>

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
/// An optional number: null when absent.
inline nlohmann::json json_number(const std::optional<double>& value)
{
  return value ? json_number(*value) : nlohmann::json(nullptr);
}

/// A number that is undefined (NaN) when what it compares is missing, as a
/// change between two scores of which one is absent: null then.
inline nlohmann::json json_number_or_null(double value)
{
  return std::isnan(value) ? nlohmann::json(nullptr) : json_number(value);
}
} // namespace rollcheck
