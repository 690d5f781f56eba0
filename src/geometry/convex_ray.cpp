// The chord of a line through a convex mesh (geometry/convex_ray.h).
#include "geometry/convex_ray.h"
#include "core/error.h"
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <limits>

namespace rollcheck::geometry
{
HalfSpaces half_spaces(const SurfaceMesh& mesh)
{
  HalfSpaces h;
  for (Eigen::Index f = 0; f < mesh.faces.rows(); ++f)
  {
    const Eigen::Vector3d a = mesh.vertices.row(mesh.faces(f, 0)).transpose();
    const Eigen::Vector3d b = mesh.vertices.row(mesh.faces(f, 1)).transpose();
    const Eigen::Vector3d c = mesh.vertices.row(mesh.faces(f, 2)).transpose();
    const Eigen::Vector3d n = (b - a).cross(c - a);
    if (!(n.norm() > 0))
      throw InputError(fmt::format("convex ray: face {} of the body is degenerate", f));
    h.normals.push_back(n.normalized());
    h.offsets.push_back(h.normals.back().dot(a));
  }
  return h;
}

std::array<double, 2> line_chord(const HalfSpaces& body, const Eigen::Vector3d& point, const Eigen::Vector3d& direction)
{
  double low = -std::numeric_limits<double>::infinity(), high = std::numeric_limits<double>::infinity();
  for (std::size_t f = 0; f < body.normals.size(); ++f)
  {
    const double inside = body.offsets[f] - body.normals[f].dot(point);
    const double towards = body.normals[f].dot(direction);
    if (towards > 0)
      high = std::min(high, inside / towards);
    else if (towards < 0)
      low = std::max(low, inside / towards);
    else if (inside < 0)
      high = -std::numeric_limits<double>::infinity(); // parallel to a face, outside it
  }
  if (!(low <= high) || !std::isfinite(low) || !std::isfinite(high))
    throw ComputationError(fmt::format("convex ray: the line through ({:.9g}, {:.9g}, {:.9g}) along ({:.6g}, {:.6g}, "
                                       "{:.6g}) misses the body",
                                       point.x(), point.y(), point.z(), direction.x(), direction.y(), direction.z()));
  return {low, high};
}
} // namespace rollcheck::geometry
