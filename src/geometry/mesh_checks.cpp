#include "geometry/mesh_checks.h"
#include "core/error.h"
#include "geometry/mass_properties.h"
#include <Eigen/Geometry>
#include <fmt/format.h>
#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace rollcheck::geometry
{
namespace
{
std::uint64_t edge_key(int from, int to)
{
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(from)) << 32) | static_cast<std::uint32_t>(to);
}
} // namespace

MeshChecks check_mesh(const SurfaceMesh& mesh)
{
  MeshChecks checks;
  const auto nv = mesh.vertices.rows();
  const auto nf = mesh.faces.rows();
  checks.finite = mesh.vertices.allFinite();
  if (!checks.finite)
  {
    checks.problem = "vertices contain NaN or infinity";
    return checks;
  }
  if (nf < 4 || (mesh.faces.array() < 0).any() || (mesh.faces.array() >= nv).any())
  {
    checks.problem = nf < 4 ? "fewer than 4 faces" : "a face refers to a vertex that does not exist";
    return checks;
  }

  // Watertight: every undirected edge has exactly two faces. Consistently
  // oriented: besides, each directed edge occurs once, so the two faces of an
  // edge run along it in opposite directions (one flipped face breaks this
  // but not watertightness).
  std::unordered_map<std::uint64_t, int> face_of_edge;
  std::unordered_map<std::uint64_t, int> faces_at_edge;
  face_of_edge.reserve(static_cast<std::size_t>(3 * nf));
  faces_at_edge.reserve(static_cast<std::size_t>(3 * nf));
  bool duplicate_directed = false;
  for (Eigen::Index f = 0; f < nf; ++f)
    for (int j = 0; j < 3; ++j)
    {
      const int a = mesh.faces(f, j), b = mesh.faces(f, (j + 1) % 3);
      if (!face_of_edge.emplace(edge_key(a, b), static_cast<int>(f)).second)
        duplicate_directed = true;
      ++faces_at_edge[edge_key(std::min(a, b), std::max(a, b))];
    }
  checks.watertight = std::ranges::all_of(faces_at_edge, [](const auto& entry) { return entry.second == 2; });
  checks.consistently_oriented = checks.watertight && !duplicate_directed;
  if (!checks.watertight)
  {
    checks.problem = "not watertight: some edge does not have exactly two faces";
    return checks;
  }
  if (!checks.consistently_oriented)
  {
    checks.problem = "faces are not consistently oriented: two faces run along a shared edge in the same direction "
                     "(a flipped face)";
    return checks;
  }
  const double volume_m3 = mass_properties(mesh).volume_m3;
  if (!std::isfinite(volume_m3))
  {
    checks.problem = "the enclosed volume overflows (coordinates too large)";
    return checks;
  }
  checks.outward = volume_m3 > 0;
  if (!checks.outward)
    checks.problem = "faces point inward (negative enclosed volume)";

  // Convexity: a closed, consistently oriented surface is convex when every
  // edge is convex, i.e. the far vertex of each neighbour lies on or below
  // the face's plane.
  const double size = (mesh.vertices.colwise().maxCoeff() - mesh.vertices.colwise().minCoeff()).norm();
  const double tolerance = 1e-9 * size;
  checks.convex = checks.outward;
  for (Eigen::Index f = 0; f < nf && checks.convex; ++f)
  {
    const Eigen::Vector3d v0 = mesh.vertices.row(mesh.faces(f, 0));
    const Eigen::Vector3d v1 = mesh.vertices.row(mesh.faces(f, 1));
    const Eigen::Vector3d v2 = mesh.vertices.row(mesh.faces(f, 2));
    const Eigen::Vector3d n = (v1 - v0).cross(v2 - v0);
    if (n.norm() <= 1e-14 * size * size)
    {
      ++checks.degenerate_faces;
      continue;
    }
    const Eigen::Vector3d unit = n.normalized();
    for (int j = 0; j < 3; ++j)
    {
      const int a = mesh.faces(f, j), b = mesh.faces(f, (j + 1) % 3);
      const int g = face_of_edge.at(edge_key(b, a));
      for (int k = 0; k < 3; ++k)
      {
        const Eigen::Vector3d p = mesh.vertices.row(mesh.faces(g, k));
        if (unit.dot(p - v0) > tolerance)
        {
          checks.convex = false;
          checks.problem = fmt::format("not convex: the surface folds inward at the edge ({}, {})", a, b);
        }
      }
    }
  }
  return checks;
}

void require_closed_convex(const SurfaceMesh& mesh, std::string_view what)
{
  const MeshChecks checks = check_mesh(mesh);
  if (!checks.problem.empty())
    throw InputError(fmt::format("{}: {}", what, checks.problem));
}
} // namespace rollcheck::geometry
