#pragma once
// Convex hull of a point cloud by Qhull (Barber, Dobkin, Huhdanpaa 1996),
// triangulated, faces oriented outward. Raises InputError for fewer than four
// points, non-finite points, or a flat (coplanar) or degenerate cloud.
#include "geometry/surface_mesh.h"
#include <string_view>

namespace rollcheck::geometry
{
SurfaceMesh convex_hull(const Vertices& points, std::string_view what = "point cloud");
} // namespace rollcheck::geometry
