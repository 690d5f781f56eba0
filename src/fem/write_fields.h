#pragma once
// The recovered fields of one solve in ONE self-contained XDMF file: one grid
// (the mesh's vertices, gathered to rank 0 in global order) carrying every
// field as a node attribute in float64 — "displacement" (3 components, 0 for z
// in 2D), "stress" (3x3, in (x|r, y|theta, z)), "von_mises", "max_shear",
// "contact_pressure" — with the data inline (Format="XML"), so ParaView warps
// and colours it directly and meshio reads every field from the one file.
// Written whole or not at all (core/atomic_file.h); every rank learns of a
// failure. The scenes are small (<= ~10^5 nodes), so inline text is affordable.
// The path is checked before any computation by the scene's setup
// (fem::validate: a .xdmf in a writable folder, not a folder itself).
#include "fem/nodal_fields.h"
#include <filesystem>

namespace rollcheck::fem
{
void write_fields(const std::filesystem::path& xdmf_path, const NodalFields& fields);
} // namespace rollcheck::fem
