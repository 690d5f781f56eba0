#pragma once
// Surface mesh files: OBJ, STL (ASCII and binary), PLY (ASCII and binary
// little-endian), OFF; the format is chosen by extension. Vertex and face order
// are kept as in the file (the reference outputs are per face); polygons are
// fanned into triangles. Raises InputError naming the file on any problem.
#include "geometry/surface_mesh.h"
#include <filesystem>

namespace rollcheck::geometry
{
SurfaceMesh read_mesh(const std::filesystem::path& path);
} // namespace rollcheck::geometry
