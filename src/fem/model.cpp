#include "fem/model.h"
#include "core/named_values.h"

namespace rollcheck::fem
{
namespace
{
const NamedValues<Model>& model_names()
{
  static const NamedValues<Model> names = {
      {"axi", Model::axisymmetric}, {"plane-strain", Model::plane_strain}, {"3d", Model::solid}};
  return names;
}
} // namespace

std::string model_name(Model model) { return name_of(model_names(), model, "model"); }

Model parse_model(const std::string& name, const std::string& origin)
{
  return parse_named(model_names(), name, "model", origin);
}
} // namespace rollcheck::fem
