#pragma once
// Checks that a surface is a closed, consistently outward-oriented, convex
// triangle mesh: every edge shared by exactly two faces in opposite directions,
// positive enclosed volume, and every vertex on or below every face plane
// (tolerance relative to the body's size).
#include "geometry/surface_mesh.h"
#include <string>
#include <string_view>

namespace rollcheck::geometry
{
struct MeshChecks
{
  bool watertight = false;       ///< every edge used by exactly two faces
  bool consistently_oriented = false; ///< ...in opposite directions
  bool outward = false;          ///< positive signed volume
  bool convex = false;           ///< no vertex above any face plane
  bool finite = false;           ///< no NaN or infinity in the vertices
  int degenerate_faces = 0;      ///< faces of zero area
  std::string problem;           ///< first problem found, empty if none
};

MeshChecks check_mesh(const SurfaceMesh& mesh);

/// Raises InputError naming `what` unless the mesh is closed, outward and convex.
void require_closed_convex(const SurfaceMesh& mesh, std::string_view what);
} // namespace rollcheck::geometry
