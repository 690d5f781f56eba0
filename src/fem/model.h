#pragma once
// The three discretisations of a contact scene: the coordinates its forms,
// meshes and solver defaults are written in.
#include <string>

namespace rollcheck::fem
{
/// axisymmetric: sphere on plane in (r, z); plane_strain: cylinder on plane
/// in (x, z), per unit length; solid: 3D hemisphere (a quarter by symmetry).
enum class Model
{
  axisymmetric,
  plane_strain,
  solid
};

/// "axi", "plane-strain", "3d" (the --model spellings).
std::string model_name(Model model);
/// Inverse of model_name; InputError naming `origin` for anything else.
Model parse_model(const std::string& name, const std::string& origin);

} // namespace rollcheck::fem
