// What read_mesh and check_mesh say about a bad mesh (issue 58, defect 9):
// the message names the real problem, in the file's own numbering. Special
// files (devices, fifos, directories, symlink loops) are refused by name
// through core::read_bounded_file (tests/core/test_bounded_file.cpp).
#include "core/error.h"
#include "geometry/mesh_checks.h"
#include "geometry/read_mesh.h"
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <unistd.h>

namespace fs = std::filesystem;
using namespace rollcheck;
using namespace rollcheck::geometry;

namespace
{
fs::path write_file(const std::string& name, const std::string& text)
{
  const fs::path dir = fs::path(ROLLCHECK_TEST_TMP) / ("read_mesh_diagnoses_" + std::to_string(getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / name, std::ios::binary) << text;
  return dir / name;
}

std::string refusal(const fs::path& path)
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

const std::string tetrahedron_vertices = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n";
/// An outward tetrahedron in OBJ numbering.
const std::string tetrahedron_faces = "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
} // namespace

TEST(ReadMeshDiagnoses, ObjIndexZeroIsNamed)
{
  const std::string message = refusal(write_file("zero.obj", tetrahedron_vertices + "f 0 1 2\n"));
  EXPECT_NE(message.find("zero.obj:5: vertex index 0 (OBJ numbers vertices from 1)"), std::string::npos) << message;
}

TEST(ReadMeshDiagnoses, ObjRelativeIndexBeforeTheFirstVertexIsNamed)
{
  const std::string message = refusal(write_file("relative.obj", tetrahedron_vertices + "f -1 -2 -5\n"));
  EXPECT_NE(message.find("relative vertex index -5"), std::string::npos) << message;
}

TEST(ReadMeshDiagnoses, OffAndPlyNegativeIndexInTheFilesNumbering)
{
  const std::string off = refusal(write_file("minus.off", "OFF\n4 1 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 -1 1 2\n"));
  EXPECT_NE(off.find("face 1 refers to vertex index -1, but the 4 vertices are numbered 0 to 3"), std::string::npos)
      << off;
  const std::string ply = refusal(write_file(
      "minus.ply", "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
                   "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n"
                   "3 0 1 -1\n"));
  EXPECT_NE(ply.find("refers to vertex index -1, but the 4 vertices are numbered 0 to 3"), std::string::npos) << ply;
  const std::string obj = refusal(write_file("beyond.obj", tetrahedron_vertices + "f 1 2 9\n"));
  EXPECT_NE(obj.find("refers to vertex index 9, but the 4 vertices are numbered 1 to 4"), std::string::npos) << obj;
}

TEST(ReadMeshDiagnoses, PlyNegativeElementCountIsNamed)
{
  const std::string message
      = refusal(write_file("negative.ply", "ply\nformat ascii 1.0\nelement vertex -4\nproperty float x\nend_header\n"));
  EXPECT_NE(message.find("'element vertex -4' does not declare a count >= 0"), std::string::npos) << message;
}

TEST(ReadMeshDiagnoses, HugeCoordinatesAreNamedNotCalledInward)
{
  const std::string message
      = refusal(write_file("huge.obj", "v 0 0 0\nv 1e300 0 0\nv 0 1e300 0\nv 0 0 1e300\n" + tetrahedron_faces));
  EXPECT_NE(message.find("a vertex coordinate of 1e+300 m is beyond the 1e+30 m"), std::string::npos) << message;
}

TEST(ReadMeshDiagnoses, OneFlippedFaceIsNotConsistentlyOriented)
{
  const SurfaceMesh good = read_mesh(write_file("good.obj", tetrahedron_vertices + tetrahedron_faces));
  EXPECT_TRUE(check_mesh(good).problem.empty()) << check_mesh(good).problem;
  const SurfaceMesh flipped
      = read_mesh(write_file("flipped.obj", tetrahedron_vertices + "f 1 2 3\nf 1 2 4\nf 1 4 3\nf 2 3 4\n"));
  const MeshChecks checks = check_mesh(flipped);
  EXPECT_TRUE(checks.watertight);
  EXPECT_FALSE(checks.consistently_oriented);
  EXPECT_NE(checks.problem.find("not consistently oriented"), std::string::npos) << checks.problem;
  // An open surface is still "not watertight".
  const SurfaceMesh open = read_mesh(write_file("open.obj", tetrahedron_vertices + "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 1 4 3\n"));
  EXPECT_NE(check_mesh(open).problem.find("not watertight"), std::string::npos) << check_mesh(open).problem;
}

TEST(ReadMeshDiagnoses, DevicesAndFoldersAreRefusedByName)
{
  EXPECT_NE(refusal("/dev/zero.obj").find("does not exist"), std::string::npos);
  const fs::path link = write_file("placeholder", "").parent_path() / "z.stl";
  fs::remove(link);
  fs::create_symlink("/dev/zero", link);
  EXPECT_NE(refusal(link).find("z.stl': is a character device"), std::string::npos) << refusal(link);
  const fs::path folder = link.parent_path() / "folder.obj";
  fs::create_directories(folder);
  EXPECT_NE(refusal(folder).find("folder.obj': is a directory"), std::string::npos) << refusal(folder);
}
