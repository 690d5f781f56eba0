#include "study/life/rounded_end_ratios.h"
#include "core/data_folder.h"
#include "core/error.h"
#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <fstream>
#include <nlohmann/json.hpp>

namespace rollcheck::study::life
{
double RoundedEndRatios::operator()(double x) const
{
  const auto& xs = r_over_edge_radius;
  const auto& ys = end_over_line_hertz;
  if (!(x > xs.front()))
    return ys.front();
  if (!(x < xs.back()))
    return ys.back();
  const std::size_t i = std::upper_bound(xs.begin(), xs.end(), x) - xs.begin();
  const double w = std::log(x / xs[i - 1]) / std::log(xs[i] / xs[i - 1]);
  return (1 - w) * ys[i - 1] + w * ys[i];
}

bool RoundedEndRatios::covers(double x) const { return x <= r_over_edge_radius.back(); }

RoundedEndRatios read_rounded_end_ratios(const std::filesystem::path& path)
{
  std::ifstream in(path);
  if (!in)
    throw InputError(fmt::format("life: cannot read the rounded-end table '{}'", path.string()));
  const nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
  if (j.is_discarded() || !j.is_object())
    throw InputError(fmt::format("life: the rounded-end table '{}' is not a JSON object", path.string()));
  auto key = [&](const char* name) -> const nlohmann::json& {
    if (!j.contains(name))
      throw InputError(fmt::format("life: the rounded-end table '{}' has no key '{}'", path.string(), name));
    return j.at(name);
  };
  RoundedEndRatios t;
  try
  {
    t.r_over_edge_radius = key("r_over_edge_radius").get<std::vector<double>>();
    t.end_over_line_hertz = key("end_over_line_hertz").get<std::vector<double>>();
    t.interior_angle_deg = key("interior_angle_deg").get<double>();
    t.source = key("source").get<std::string>();
  }
  catch (const nlohmann::json::exception& e)
  {
    throw InputError(fmt::format("life: the rounded-end table '{}': {}", path.string(), e.what()));
  }
  const auto& xs = t.r_over_edge_radius;
  const bool ascending = std::adjacent_find(xs.begin(), xs.end(), std::greater_equal<>()) == xs.end();
  const bool positive = std::all_of(xs.begin(), xs.end(), [](double x) { return x > 0; })
                        && std::all_of(t.end_over_line_hertz.begin(), t.end_over_line_hertz.end(),
                                       [](double y) { return y > 0; });
  if (xs.size() < 2 || xs.size() != t.end_over_line_hertz.size() || !ascending || !positive)
    throw InputError(fmt::format("life: the rounded-end table '{}' needs two or more nodes, r_over_edge_radius "
                                 "ascending, both lists positive and of one length",
                                 path.string()));
  return t;
}

std::filesystem::path default_rounded_end_ratios_path()
{
  return data_folder() / "cases" / "life" / "rounded_end_ratios.json";
}
} // namespace rollcheck::study::life
