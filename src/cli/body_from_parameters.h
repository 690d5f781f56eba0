#pragma once
#include "geometry/body.h"
#include "geometry/surface_mesh.h"
#include "io/parameters.h"
#include <string>

namespace rollcheck::cli
{
/// The named body of body_parameters() (mesh_file is not looked at).
geometry::BodySpec body_spec_from_parameters(const io::Parameters& params);

/// The body of body_parameters(): read from mesh_file if given, else built.
/// Either way checked closed, outward and convex. `label` names it.
geometry::SurfaceMesh body_from_parameters(const io::Parameters& params, std::string* label = nullptr);
} // namespace rollcheck::cli
