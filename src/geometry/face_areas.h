#pragma once
// a_f = |(v1 - v0) x (v2 - v0)| / 2 for every face f.
#include "geometry/surface_mesh.h"
#include <Eigen/Core>

namespace rollcheck::geometry
{
Eigen::VectorXd face_areas(const SurfaceMesh& mesh);
} // namespace rollcheck::geometry
