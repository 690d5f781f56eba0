#pragma once
// c_f = (v0 + v1 + v2) / 3 for every face f.
#include "geometry/surface_mesh.h"

namespace rollcheck::geometry
{
Vertices face_centroids(const SurfaceMesh& mesh);
} // namespace rollcheck::geometry
