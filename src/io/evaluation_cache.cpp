#include "io/evaluation_cache.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/json_number.h"
#include <fmt/format.h>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>

namespace rollcheck::io
{
namespace
{
constexpr const char* layout = "rollcheck-evaluations-1";

/// json_number's inverse: a number, or "inf" / "-inf".
double number_of(const nlohmann::json& value)
{
  if (value.is_string() && (value == "inf" || value == "-inf"))
    return value == "inf" ? std::numeric_limits<double>::infinity() : -std::numeric_limits<double>::infinity();
  return value.get<double>();
}
} // namespace

EvaluationCache::EvaluationCache(std::filesystem::path file, std::string settings_hash)
    : file_(std::move(file)), settings_hash_(std::move(settings_hash))
{
  if (!std::filesystem::exists(file_))
    return;
  try
  {
    const nlohmann::json j = nlohmann::json::parse(std::ifstream(file_));
    if (j.at("layout") != layout)
      throw std::runtime_error(fmt::format("layout is not {}", layout));
    if (j.at("settings_hash") != settings_hash_)
      return;
    for (const nlohmann::json& run : j.at("runs"))
      values_[{run.at("x").get<std::vector<double>>(), run.at("replicate").get<int>()}] = number_of(run.at("value"));
  }
  catch (const std::exception& e)
  {
    throw InputError(fmt::format("evaluation cache '{}' cannot be read ({}); remove it to start afresh",
                                 file_.string(), e.what()));
  }
}

std::optional<double> EvaluationCache::recall(std::span<const double> x, int replicate) const
{
  const auto found = values_.find({std::vector<double>(x.begin(), x.end()), replicate});
  return found == values_.end() ? std::nullopt : std::optional(found->second);
}

void EvaluationCache::add(std::span<const double> x, int replicate, double value)
{
  values_[{std::vector<double>(x.begin(), x.end()), replicate}] = value;
}

void EvaluationCache::save(const std::filesystem::path& file) const
{
  nlohmann::json runs = nlohmann::json::array();
  for (const auto& [run, value] : values_)
    runs.push_back({{"x", run.first}, {"replicate", run.second}, {"value", json_number(value)}});
  const nlohmann::json j = {{"layout", layout}, {"settings_hash", settings_hash_}, {"runs", runs}};
  write_file_atomically(file, j.dump() + "\n");
}
} // namespace rollcheck::io
