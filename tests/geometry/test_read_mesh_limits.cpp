// Counts and indices a mesh file declares are checked before they size an
// allocation or are narrowed to int: a few bytes claiming gigabytes, or an
// index beyond int, are refused with an InputError naming the file and the
// value. Files that end exactly where their counts say are still read.
// (fuzz/regressions/ keeps the inputs the fuzzers found.)
#include "core/error.h"
#include "geometry/read_mesh.h"
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <string>

using namespace rollcheck;
using namespace rollcheck::geometry;

namespace
{
std::filesystem::path write_file(const std::string& name, const std::string& bytes)
{
  const std::filesystem::path dir = std::filesystem::path(ROLLCHECK_TEST_TMP) / "read_mesh_limits";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / name, std::ios::binary) << bytes;
  return dir / name;
}

/// The message of the InputError read_mesh raises for `path` ("" if none).
std::string refusal(const std::filesystem::path& path)
{
  try
  {
    read_mesh(path);
  }
  catch (const InputError& e)
  {
    return e.what();
  }
  return "";
}

template <class T>
std::string little_endian(T value)
{
  std::string bytes(sizeof value, '\0');
  std::memcpy(bytes.data(), &value, sizeof value);
  return bytes;
}

const std::string tetrahedron_off_vertices = "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n";
const std::string binary_ply_triangle_header = "ply\nformat binary_little_endian 1.0\nelement vertex 3\n"
                                               "property float x\nproperty float y\nproperty float z\n"
                                               "element face 1\nproperty list int int vertex_indices\nend_header\n";

std::string binary_ply_triangle_vertices()
{
  std::string bytes;
  for (float v : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f})
    bytes += little_endian(v);
  return bytes;
}
} // namespace

TEST(ReadMeshLimits, OffFaceOfTwoBillionVerticesIsRefusedBeforeAllocating)
{
  // The fuzzer's 45-byte file (fuzz/regressions/off/): 7.7 GB were allocated for the face.
  const auto path = write_file("face_of_2e9_vertices.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2000000000 0 1 2\n");
  const std::string message = refusal(path);
  EXPECT_NE(message.find(path.string()), std::string::npos) << message;
  EXPECT_NE(message.find("2000000000"), std::string::npos) << message;
  EXPECT_NE(message.find("face 1"), std::string::npos) << message;
}

TEST(ReadMeshLimits, OffFacesEndingAtTheEndOfTheFileAreRead)
{
  const auto path = write_file("tetrahedron.off", tetrahedron_off_vertices + "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3");
  const SurfaceMesh mesh = read_mesh(path);
  EXPECT_EQ(mesh.vertices.rows(), 4);
  ASSERT_EQ(mesh.faces.rows(), 4);
  EXPECT_EQ(mesh.faces(3, 0), 1);
  EXPECT_EQ(mesh.faces(3, 2), 3);
  // One vertex index short: the last face declares more than the file holds.
  const auto short_path
      = write_file("tetrahedron_short.off", tetrahedron_off_vertices + "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2");
  EXPECT_NE(refusal(short_path).find("face 4 declares 3 vertices"), std::string::npos) << refusal(short_path);
}

TEST(ReadMeshLimits, OffCountBeyondIntIsNotAnInteger)
{
  // 1e10 does not fit an int: refused, where the cast used to be undefined.
  const auto path = write_file("count_1e10.off", "OFF\n1e10 1 0\n0 0 0\n");
  const std::string message = refusal(path);
  EXPECT_NE(message.find("'1e10' is not an integer"), std::string::npos) << message;
}

TEST(ReadMeshLimits, PlyListCountBeyondTheFileIsRefused)
{
  const auto path = write_file("list_of_2e9.ply", binary_ply_triangle_header + binary_ply_triangle_vertices()
                                                      + little_endian(std::int32_t{2000000000})
                                                      + little_endian(std::int32_t{0}));
  const std::string message = refusal(path);
  EXPECT_NE(message.find(path.string()), std::string::npos) << message;
  EXPECT_NE(message.find("face 1 declares 2000000000 list entries"), std::string::npos) << message;
}

TEST(ReadMeshLimits, PlyListEndingAtTheEndOfTheFileIsRead)
{
  std::string face = little_endian(std::int32_t{3});
  for (std::int32_t v : {0, 1, 2})
    face += little_endian(v);
  const SurfaceMesh mesh
      = read_mesh(write_file("triangle.ply", binary_ply_triangle_header + binary_ply_triangle_vertices() + face));
  ASSERT_EQ(mesh.faces.rows(), 1);
  EXPECT_EQ(mesh.faces(0, 2), 2);
  EXPECT_EQ(mesh.vertices(1, 0), 1.0);
}

TEST(ReadMeshLimits, PlyElementCountBeyondTheFileIsRefused)
{
  // An element without properties takes no bytes: four billion of them were
  // four billion loop turns, each pushing a vertex.
  const auto path = write_file("many_vertices.ply", "ply\nformat ascii 1.0\nelement vertex 4000000000\nend_header\n");
  const std::string message = refusal(path);
  EXPECT_NE(message.find("element 'vertex' declares 4000000000 items"), std::string::npos) << message;
}

TEST(ReadMeshLimits, PlyIndexBeyondIntIsRefused)
{
  std::string face = little_endian(std::int32_t{3});
  for (std::uint32_t v : {0u, 1u, 4000000000u})
    face += little_endian(v);
  std::string header = binary_ply_triangle_header;
  header.replace(header.find("list int int"), 12, "list int uint");
  const std::string message = refusal(write_file("index_4e9.ply", header + binary_ply_triangle_vertices() + face));
  EXPECT_NE(message.find("face 1: 4000000000 is not an index or count in the range of int"), std::string::npos)
      << message;
}

TEST(ReadMeshLimits, PlyHeaderWithoutItsEndOfLineIsRefused)
{
  const auto path = write_file("no_newline.ply", "ply\nformat binary_little_endian 1.0\nelement vertex 1\nend_header");
  EXPECT_NE(refusal(path).find("'end_header' does not end"), std::string::npos) << refusal(path);
}
