#include "geometry/write_mesh.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include <Eigen/Geometry>
#include <algorithm>
#include <cstring>
#include <fmt/format.h>
#include <fstream>

namespace rollcheck::geometry
{
void write_mesh(const SurfaceMesh& mesh, const std::filesystem::path& path)
{
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), ::tolower);
  if (ext != ".obj" && ext != ".stl" && ext != ".ply" && ext != ".off")
    throw InputError(fmt::format("output '{}': unknown mesh extension '{}' (use .obj, .stl, .ply, .off or .msh)",
                                 path.string(), ext));
  const auto nv = mesh.vertices.rows(), nf = mesh.faces.rows();
  write_atomically(path, [&](const std::filesystem::path& tmp) {
    std::ofstream out(tmp, std::ios::binary);
    // 17 significant digits: a written mesh reads back bit for bit.
    auto xyz = [&](Eigen::Index i) {
      return fmt::format("{:.17g} {:.17g} {:.17g}", mesh.vertices(i, 0), mesh.vertices(i, 1), mesh.vertices(i, 2));
    };
    if (ext == ".obj")
    {
      out << "# written by rollcheck\n";
      for (Eigen::Index i = 0; i < nv; ++i)
        out << "v " << xyz(i) << "\n";
      for (Eigen::Index f = 0; f < nf; ++f)
        out << fmt::format("f {} {} {}\n", mesh.faces(f, 0) + 1, mesh.faces(f, 1) + 1, mesh.faces(f, 2) + 1);
    }
    else if (ext == ".off" || ext == ".ply")
    {
      if (ext == ".off")
        out << fmt::format("OFF\n{} {} 0\n", nv, nf);
      else
        out << fmt::format("ply\nformat ascii 1.0\ncomment written by rollcheck\nelement vertex {}\n"
                           "property double x\nproperty double y\nproperty double z\nelement face {}\n"
                           "property list uchar int vertex_indices\nend_header\n",
                           nv, nf);
      for (Eigen::Index i = 0; i < nv; ++i)
        out << xyz(i) << "\n";
      for (Eigen::Index f = 0; f < nf; ++f)
        out << fmt::format("3 {} {} {}\n", mesh.faces(f, 0), mesh.faces(f, 1), mesh.faces(f, 2));
    }
    else
    {
      // Binary STL: 80-byte header, triangle count, then per triangle the
      // normal, three corners (float32) and a zero attribute word.
      char header[80] = {};
      std::strncpy(header, "binary STL written by rollcheck", sizeof header - 1);
      out.write(header, 80);
      const auto count = static_cast<std::uint32_t>(nf);
      out.write(reinterpret_cast<const char*>(&count), 4);
      for (Eigen::Index f = 0; f < nf; ++f)
      {
        const Eigen::Vector3d a = mesh.vertices.row(mesh.faces(f, 0)), b = mesh.vertices.row(mesh.faces(f, 1)),
                              c = mesh.vertices.row(mesh.faces(f, 2));
        const Eigen::Vector3f n = (b - a).cross(c - a).normalized().cast<float>();
        float record[12] = {n.x(), n.y(), n.z()};
        for (int k = 0; k < 3; ++k)
          for (int j = 0; j < 3; ++j)
            record[3 + 3 * k + j] = static_cast<float>(mesh.vertices(mesh.faces(f, k), j));
        out.write(reinterpret_cast<const char*>(record), sizeof record);
        const std::uint16_t attribute = 0;
        out.write(reinterpret_cast<const char*>(&attribute), 2);
      }
    }
    if (!out)
      throw InputError(fmt::format("output '{}': write failed", path.string()));
  });
}
} // namespace rollcheck::geometry
