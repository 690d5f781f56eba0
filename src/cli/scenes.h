#pragma once
// A scene is what a case file runs: a schema of parameters and a function from
// resolved parameters to a JSON summary. Subcommands register theirs, so that
// `rollcheck run CASE.toml` and `rollcheck <kind> --options` share one code path.
#include "geometry/body.h"
#include "io/bound_schema.h"
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

/// Samples per generating circle: resource guard. 100k points per circle is a
/// 200k-vertex hull, far beyond any converged score and about 0.1 GB.
inline constexpr io::Bounds body_points_range{3, 100000};

/// The body's parameters, bound to geometry::BodySpec: include them with
/// `schema.include(body_schema(), &Settings::body)`.
const io::BoundSchema<geometry::BodySpec>& body_schema();

/// The material pair's parameters, one spelling in every scene:
/// youngs_modulus_pa (--youngs-modulus, Pa) and poisson_ratio (--poisson).
template <class Settings, class Youngs, class Poisson>
void add_material(io::BoundSchema<Settings>& schema, Youngs youngs_modulus, Poisson poisson_ratio)
{
  schema.real("youngs_modulus_pa", "--youngs-modulus", youngs_modulus, "Pa",
              "Young's modulus E of the body (steel, the preprint's 200 GPa)", io::positive);
  schema.real("poisson_ratio", "--poisson", poisson_ratio, "", "Poisson's ratio nu of the body (steel, the preprint's 0.3)",
              io::poisson_range);
}
} // namespace rollcheck::cli
