#include "io/surface_vtu.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include <cstdint>
#include <cstring>
#include <fmt/format.h>
#include <numeric>
#include <vector>

namespace rollcheck::io
{
namespace
{
/// Base64 (RFC 4648, with padding) of `bytes`.
std::string base64(const std::vector<unsigned char>& bytes)
{
  static constexpr char digits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  for (std::size_t i = 0; i < bytes.size(); i += 3)
  {
    const std::size_t n = std::min<std::size_t>(3, bytes.size() - i);
    std::uint32_t word = 0;
    for (std::size_t k = 0; k < 3; ++k)
      word = word << 8 | (k < n ? bytes[i + k] : 0u);
    for (std::size_t k = 0; k < 4; ++k)
      out += k <= n ? digits[(word >> (18 - 6 * k)) & 63u] : '=';
  }
  return out;
}

/// One binary DataArray: base64 of a UInt32 byte count followed by the raw
/// little-endian values (VTK's "binary" format, header_type UInt32).
void write_array(std::string& out, const std::string& attributes, const void* data, std::size_t bytes)
{
  const auto count = static_cast<std::uint32_t>(bytes);
  std::vector<unsigned char> block(sizeof count + bytes);
  std::memcpy(block.data(), &count, sizeof count);
  std::memcpy(block.data() + sizeof count, data, bytes);
  out += "        <DataArray " + attributes + " format=\"binary\">" + base64(block) + "</DataArray>\n";
}
} // namespace

void write_surface_vtu(const std::filesystem::path& path, const geometry::SurfaceMesh& mesh,
                       const std::map<std::string, Eigen::VectorXd>& face_fields)
{
  const Eigen::Index n_faces = mesh.faces.rows();
  for (const auto& [name, values] : face_fields)
    if (values.size() != n_faces)
      throw InputError(fmt::format("VTU field '{}': {} values for {} faces", name, values.size(), n_faces));
  std::vector<std::int32_t> offsets(static_cast<std::size_t>(n_faces));
  std::iota(offsets.begin(), offsets.end(), 1);
  for (std::int32_t& o : offsets)
    o *= 3;
  const std::vector<std::uint8_t> types(static_cast<std::size_t>(n_faces), 5);
  // The file is made in memory and written by the checked writer: a full
  // disk or a failed rename exits 1 naming the file, the old file intact.
  std::string out = "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" "
                    "byte_order=\"LittleEndian\" header_type=\"UInt32\">\n  <UnstructuredGrid>\n";
  out += fmt::format("    <Piece NumberOfPoints=\"{}\" NumberOfCells=\"{}\">\n", mesh.vertices.rows(), n_faces);
  out += "      <Points>\n";
  write_array(out, "type=\"Float64\" NumberOfComponents=\"3\"", mesh.vertices.data(),
              sizeof(double) * static_cast<std::size_t>(mesh.vertices.size()));
  out += "      </Points>\n      <Cells>\n";
  write_array(out, "type=\"Int32\" Name=\"connectivity\"", mesh.faces.data(),
              sizeof(int) * static_cast<std::size_t>(mesh.faces.size()));
  write_array(out, "type=\"Int32\" Name=\"offsets\"", offsets.data(), sizeof(std::int32_t) * offsets.size());
  write_array(out, "type=\"UInt8\" Name=\"types\"", types.data(), types.size());
  out += "      </Cells>\n      <CellData>\n";
  for (const auto& [name, values] : face_fields)
    write_array(out, fmt::format("type=\"Float64\" Name=\"{}\"", name), values.data(),
                sizeof(double) * static_cast<std::size_t>(values.size()));
  out += "      </CellData>\n    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n";
  write_file_atomically(path, out);
}
} // namespace rollcheck::io
