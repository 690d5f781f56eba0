#pragma once
// A scene is what a case file runs: a schema of parameters and a function from
// resolved parameters to a JSON summary. Subcommands register theirs, so that
// `rollcheck run CASE.toml` and `rollcheck <kind> --options` share one code path.
#include "io/parameters.h"
#include <functional>
#include <nlohmann/json.hpp>

namespace rollcheck::cli
{
struct Scene
{
  const io::Schema* schema;
  std::function<nlohmann::json(const io::Parameters&)> run;
};

void register_scene(const Scene& scene);
/// InputError naming `origin` if no scene of that kind exists.
const Scene& find_scene(const std::string& kind, const std::string& origin);
std::vector<std::string> scene_kinds();

/// Parameters shared by every scene that starts from a body.
std::vector<io::Parameter> body_parameters();
} // namespace rollcheck::cli
