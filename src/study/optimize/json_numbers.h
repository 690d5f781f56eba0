#pragma once
// Lists of numbers in the wing's JSON: an array whose every entry follows the
// project's number convention (core/json_number.h: "inf" for infinity,
// ComputationError for NaN).
#include "core/json_number.h"
#include <Eigen/Core>
#include <nlohmann/json.hpp>
#include <span>

namespace rollcheck::study::optimize
{
inline nlohmann::json numbers(std::span<const double> values)
{
  nlohmann::json j = nlohmann::json::array();
  for (const double v : values)
    j.push_back(json_number(v));
  return j;
}

inline nlohmann::json numbers(const Eigen::VectorXd& v) { return numbers(std::span<const double>(v.data(), v.size())); }
} // namespace rollcheck::study::optimize
