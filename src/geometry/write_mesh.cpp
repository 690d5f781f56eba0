#include "geometry/write_mesh.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include <Eigen/Geometry>
#include <algorithm>
#include <cstring>
#include <fmt/format.h>
#include <fstream>
#include <iterator>
#include <string_view>

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
  // The whole file is made in memory and written by one checked writer.
  std::string bytes;
  {
    auto out = std::back_inserter(bytes);
    // 17 significant digits: a written mesh reads back bit for bit.
    auto xyz = [&](Eigen::Index i) {
      return fmt::format("{:.17g} {:.17g} {:.17g}", mesh.vertices(i, 0), mesh.vertices(i, 1), mesh.vertices(i, 2));
    };
    if (ext == ".obj")
    {
      fmt::format_to(out, "# written by rollcheck\n");
      for (Eigen::Index i = 0; i < nv; ++i)
        fmt::format_to(out, "v {}\n", xyz(i));
      for (Eigen::Index f = 0; f < nf; ++f)
        fmt::format_to(out, "f {} {} {}\n", mesh.faces(f, 0) + 1, mesh.faces(f, 1) + 1, mesh.faces(f, 2) + 1);
    }
    else if (ext == ".off" || ext == ".ply")
    {
      if (ext == ".off")
        fmt::format_to(out, "OFF\n{} {} 0\n", nv, nf);
      else
        fmt::format_to(out, "ply\nformat ascii 1.0\ncomment written by rollcheck\nelement vertex {}\n"
                           "property double x\nproperty double y\nproperty double z\nelement face {}\n"
                           "property list uchar int vertex_indices\nend_header\n",
                           nv, nf);
      for (Eigen::Index i = 0; i < nv; ++i)
        fmt::format_to(out, "{}\n", xyz(i));
      for (Eigen::Index f = 0; f < nf; ++f)
        fmt::format_to(out, "3 {} {} {}\n", mesh.faces(f, 0), mesh.faces(f, 1), mesh.faces(f, 2));
    }
    else
    {
      // Binary STL: 80-byte header, triangle count, then per triangle the
      // normal, three corners (float32) and a zero attribute word.
      char header[80] = {};
      std::strncpy(header, "binary STL written by rollcheck", sizeof header - 1);
      auto put = [&](const void* data, std::size_t size) { bytes.append(static_cast<const char*>(data), size); };
      put(header, 80);
      const auto count = static_cast<std::uint32_t>(nf);
      put(&count, 4);
      for (Eigen::Index f = 0; f < nf; ++f)
      {
        const Eigen::Vector3d a = mesh.vertices.row(mesh.faces(f, 0)), b = mesh.vertices.row(mesh.faces(f, 1)),
                              c = mesh.vertices.row(mesh.faces(f, 2));
        const Eigen::Vector3f n = (b - a).cross(c - a).normalized().cast<float>();
        float record[12] = {n.x(), n.y(), n.z()};
        for (int k = 0; k < 3; ++k)
          for (int j = 0; j < 3; ++j)
            record[3 + 3 * k + j] = static_cast<float>(mesh.vertices(mesh.faces(f, k), j));
        put(record, sizeof record);
        const std::uint16_t attribute = 0;
        put(&attribute, 2);
      }
    }
  }
  write_file_atomically(path, bytes);
}

void check_gmsh_file_complete(const std::filesystem::path& written, const std::filesystem::path& target)
{
  constexpr std::string_view last_line = "$EndElements\n";
  std::ifstream in(written, std::ios::binary | std::ios::ate);
  const std::streamoff size = in ? static_cast<std::streamoff>(in.tellg()) : 0;
  std::string tail(static_cast<std::size_t>(std::min<std::streamoff>(size, last_line.size())), '\0');
  if (size > 0)
  {
    in.seekg(size - static_cast<std::streamoff>(tail.size()));
    in.read(tail.data(), static_cast<std::streamsize>(tail.size()));
  }
  if (!in || tail != last_line)
    throw ComputationError(fmt::format("cannot write '{}': gmsh wrote {} bytes that do not end with its last "
                                       "section (is the disk full?)",
                                       target.string(), size));
}
} // namespace rollcheck::geometry
