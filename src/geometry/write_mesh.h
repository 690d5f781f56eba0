#pragma once
// Writes OBJ, STL (binary), PLY (ASCII) or OFF by extension, atomically, and
// checks the .msh files gmsh writes.
#include "geometry/surface_mesh.h"
#include <filesystem>

namespace rollcheck::geometry
{
/// The surface mesh as OBJ, STL, PLY or OFF by the extension of `path`
/// (InputError for another), written whole or not at all (core/atomic_file.h).
void write_mesh(const SurfaceMesh& mesh, const std::filesystem::path& path);

/// gmsh::write reports no error of the file system (a full disk leaves a
/// file cut at a buffer's end and gmsh silent): ComputationError naming
/// `target` unless the file gmsh wrote at `written` ends with the line
/// "$EndElements", the last section of every mesh it writes (format 4.1).
void check_gmsh_file_complete(const std::filesystem::path& written, const std::filesystem::path& target);
} // namespace rollcheck::geometry
