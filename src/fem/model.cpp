#include "fem/model.h"
#include "core/error.h"
#include <fmt/format.h>

namespace rollcheck::fem
{
std::string model_name(Model model)
{
  switch (model)
  {
  case Model::axisymmetric: return "axi";
  case Model::plane_strain: return "plane-strain";
  case Model::solid: return "3d";
  }
  return "?";
}

Model parse_model(const std::string& name, const std::string& origin)
{
  for (Model m : {Model::axisymmetric, Model::plane_strain, Model::solid})
    if (name == model_name(m))
      return m;
  throw InputError(fmt::format("{}: model must be axi, plane-strain or 3d, got '{}'", origin, name));
}

} // namespace rollcheck::fem
