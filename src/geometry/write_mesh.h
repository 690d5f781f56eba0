#pragma once
// Writes OBJ, STL (binary), PLY (ASCII) or OFF by extension, atomically.
#include "geometry/surface_mesh.h"
#include <filesystem>

namespace rollcheck::geometry
{
void write_mesh(const SurfaceMesh& mesh, const std::filesystem::path& path);
} // namespace rollcheck::geometry
