#pragma once
// Surface mesh files: OBJ, STL (ASCII and binary), PLY (ASCII and binary
// little-endian), OFF; the format is chosen by extension. Vertex and face order
// are kept as in the file (the reference outputs are per face); polygons are
// fanned into triangles. Raises InputError naming the file on any problem.
//
// Bounds (docs/guide/case-files.md, "Limits"): the file is read whole by
// core::read_bounded_file, so it must be a regular file of at most
// max_mesh_file_bytes (64 MiB: a binary STL of 1.3 million triangles; parsing
// takes at most about 20 bytes of memory per file byte, so well under 2 GB);
// every coordinate is within max_mesh_coordinate_m of the origin, so that the
// fifth powers in the inertia stay finite in double precision.
#include "geometry/surface_mesh.h"
#include <cstddef>
#include <filesystem>

namespace rollcheck::geometry
{
inline constexpr std::size_t max_mesh_file_bytes = std::size_t{64} << 20;
inline constexpr double max_mesh_coordinate_m = 1e30;

SurfaceMesh read_mesh(const std::filesystem::path& path);
} // namespace rollcheck::geometry
