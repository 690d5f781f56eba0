#pragma once
// Tetrahedral volume mesh of the solid bounded by a closed surface, by gmsh
// (Geuzaine & Remacle 2009): the triangles become a discrete surface, which
// bounds one volume meshed with target element size `mesh_size_m` (surface
// triangles are kept as they are). Writes a gmsh .msh file, atomically.
#include "geometry/surface_mesh.h"
#include <filesystem>

namespace rollcheck::geometry
{
struct VolumeMeshInfo
{
  std::size_t nodes;
  std::size_t tetrahedra;
};

VolumeMeshInfo write_tetrahedral_mesh(const SurfaceMesh& surface, double mesh_size_m,
                                      const std::filesystem::path& path);
} // namespace rollcheck::geometry
