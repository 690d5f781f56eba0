// Fuzzes geometry::read_mesh for the format of ROLLCHECK_FUZZ_EXTENSION
// (".obj", ".stl", ".ply", ".off"). A file is either refused with InputError
// or read into a mesh whose faces index its vertices and whose coordinates are
// finite; anything else (another exception, a sanitizer report, a huge
// allocation or a hang) is a finding.
#include "core/error.h"
#include "fuzz_input_file.h"
#include "geometry/read_mesh.h"
#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  const auto path = rollcheck::fuzz::write_input_file({reinterpret_cast<const char*>(data), size},
                                                      ROLLCHECK_FUZZ_EXTENSION);
  try
  {
    const rollcheck::geometry::SurfaceMesh mesh = rollcheck::geometry::read_mesh(path);
    const bool indices_valid = mesh.faces.size() > 0 && mesh.faces.minCoeff() >= 0
                               && mesh.faces.maxCoeff() < mesh.vertices.rows();
    if (!indices_valid || !mesh.vertices.allFinite())
      std::abort();
  }
  catch (const rollcheck::InputError&)
  {
  }
  return 0;
}
