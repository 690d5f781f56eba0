// The exit distance of a ray from a convex mesh (geometry/convex_ray.h).
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

double ray_exit_distance(const HalfSpaces& body, const Eigen::Vector3d& from, const Eigen::Vector3d& direction)
{
  double scale = 0;
  for (const double h : body.offsets)
    scale = std::max(scale, std::abs(h));
  double t = std::numeric_limits<double>::infinity();
  for (std::size_t f = 0; f < body.normals.size(); ++f)
  {
    const double inside = body.offsets[f] - body.normals[f].dot(from);
    if (inside < -1e-12 * scale)
      throw ComputationError(fmt::format("convex ray: the point ({:.9g}, {:.9g}, {:.9g}) lies outside the body",
                                         from.x(), from.y(), from.z()));
    const double towards = body.normals[f].dot(direction);
    if (towards > 0)
      t = std::min(t, std::max(0.0, inside) / towards);
  }
  if (!std::isfinite(t))
    throw ComputationError("convex ray: no face of the body faces the ray (an open mesh?)");
  return t;
}
} // namespace rollcheck::geometry
