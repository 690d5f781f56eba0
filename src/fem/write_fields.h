#pragma once
// XDMF + HDF5 output of the recovered fields, one file pair that ParaView
// opens: functions "displacement", "stress" (3x3, in (x|r, y|theta, z)),
// "von_mises", "max_shear" and "contact_pressure" on the P1 nodes. Written
// into a scratch folder beside the target and moved in place only when
// complete (the .xdmf names its .h5 by a relative path, so both keep their
// names).
#include "fem/nodal_fields.h"
#include <filesystem>

namespace rollcheck::fem
{
void write_fields(const std::filesystem::path& xdmf_path, const NodalFields& fields);
} // namespace rollcheck::fem
