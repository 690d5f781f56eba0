#pragma once
// A scene is what a case file runs: a schema of parameters and a function from
// resolved parameters to a JSON summary. Subcommands register theirs, so that
// `rollcheck run CASE.toml` and `rollcheck <kind> --options` share one code path.
#include "cli/cli.h"
#include "geometry/body.h"
#include "io/bound_schema.h"
#include "io/parameters.h"
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <type_traits>

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

/// A scene's schema: its bound parameters, and the one-line description of
/// its subcommand, whose name is the schema's kind.
template <class Settings>
struct SceneSchema : io::BoundSchema<Settings>
{
  SceneSchema(std::string kind, std::string description)
      : io::BoundSchema<Settings>(std::move(kind)), description(std::move(description))
  {
  }
  std::string description;
};

/// A scene's schema, built on first use and kept for the process (the
/// subcommand's options and case files refer to it): `declare` adds the
/// scene's parameters to an empty schema of kind `kind`. `declare` is the
/// scene's own lambda, whose type keys the kept schema.
template <class Settings, class Declare>
const SceneSchema<Settings>& kept_schema(const char* kind, const char* description, Declare declare)
{
  static_assert(std::is_class_v<Declare>, "declare: a lambda, one type per scene");
  static const SceneSchema<Settings> schema = [&] {
    SceneSchema<Settings> s(kind, description);
    declare(s);
    return s;
  }();
  return schema;
}

/// A group of parameters that scenes include (body_schema, penalty_schema):
/// a kept schema with no subcommand of its own.
template <class Settings, class Declare>
const io::BoundSchema<Settings>& kept_schema(const char* kind, Declare declare)
{
  return kept_schema<Settings>(kind, "", declare);
}

/// add_scene_command for a scene of bound parameters: the subcommand's name
/// and description are the schema's, declared once.
template <class Settings>
CLI::App* add_scene_command(CLI::App& app, const SceneSchema<Settings>& schema, SceneRun run, SceneRun command = {})
{
  return add_scene_command(app, schema.schema().kind, schema.description, schema.schema(), std::move(run),
                           std::move(command));
}

/// Samples per generating circle: resource guard. 100k points per circle is a
/// 200k-vertex hull, far beyond any converged score and about 0.1 GB.
inline constexpr io::Bounds body_points_range{3, 100000};

/// The body's parameters, bound to geometry::BodySpec: include them with
/// `schema.include(body_schema(), &Settings::body)`.
const io::BoundSchema<geometry::BodySpec>& body_schema();

/// body_schema for the scenes that follow a contact ruling (fem-sds, rim,
/// flat-rim, whole-body): only the bodies they take, the hulls of two circles.
const io::BoundSchema<geometry::BodySpec>& line_contact_body_schema();

/// The penalty of the FEM contact, one spelling in every scene that has
/// it: penalty_c (--penalty-c), kappa = c E / h_c. A group of one parameter,
/// bound to the scene's member: `schema.include(penalty_schema(), &Settings::penalty_c)`.
const io::BoundSchema<double>& penalty_schema();

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
