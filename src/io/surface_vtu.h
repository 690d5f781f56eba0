#pragma once
// A surface mesh with per-face values as a VTK XML unstructured grid (.vtu),
// the format ParaView and meshio read: triangles, their vertices, and one
// named CellData array per field, so that ParaView colours the surface by a
// per-face score directly (contact counts, accumulated pressure, damage).
//
// Format: VTK file formats, "XML File Formats: UnstructuredGrid"
// (https://docs.vtk.org/en/latest/design_documents/VTKFileFormats.html),
// inline "binary" data arrays (base64 of a UInt32 byte count and the
// little-endian values), cell type 5 (VTK_TRIANGLE). Binary, not ASCII, so that
// doubles read back exactly and an infinite value (a flat face's effective
// radius) stays one: VTK's ASCII parser refuses "inf". Written by hand: the
// light executable links no VTK or DOLFINx, and a surface of triangles needs
// nothing beyond this.
//
// Contract: every field has one value per face (InputError naming the field
// otherwise); the file is written whole or not at all (core/atomic_file.h).
#include "geometry/surface_mesh.h"
#include <Eigen/Core>
#include <filesystem>
#include <map>
#include <string>

namespace rollcheck::io
{
void write_surface_vtu(const std::filesystem::path& path, const geometry::SurfaceMesh& mesh,
                       const std::map<std::string, Eigen::VectorXd>& face_fields);
} // namespace rollcheck::io
