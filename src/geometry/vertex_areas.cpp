#include "geometry/vertex_areas.h"
#include <cmath>
#include <numbers>

namespace rollcheck::geometry
{
Eigen::VectorXd barycentric_vertex_areas(const SurfaceMesh& mesh, const InternalAngles& angles)
{
  Eigen::VectorXd areas = Eigen::VectorXd::Zero(mesh.vertices.rows());
  for (Eigen::Index f = 0; f < mesh.faces.rows(); ++f)
  {
    if (angles.degenerate[f])
      continue;
    const double third = angles.areas[f] / 3;
    for (int c = 0; c < 3; ++c)
      areas[mesh.faces(f, c)] += third;
  }
  return areas;
}

Eigen::VectorXd mixed_voronoi_vertex_areas(const SurfaceMesh& mesh, const InternalAngles& angles)
{
  Eigen::VectorXd areas = Eigen::VectorXd::Zero(mesh.vertices.rows());
  for (Eigen::Index f = 0; f < mesh.faces.rows(); ++f)
  {
    if (angles.degenerate[f])
      continue;
    const double a = angles.areas[f];
    int obtuse = -1;
    for (int c = 0; c < 3; ++c)
      if (angles.angles(f, c) > std::numbers::pi / 2)
        obtuse = c;
    for (int c = 0; c < 3; ++c)
    {
      double part;
      if (obtuse >= 0)
        part = c == obtuse ? a / 2 : a / 4;
      else
      {
        // Corner c; the edges to the next two corners, each weighted by the
        // cotangent of the angle opposite it.
        const int j = (c + 1) % 3, k = (c + 2) % 3;
        const Eigen::Vector3d vc = mesh.vertices.row(mesh.faces(f, c));
        const double ej2 = (mesh.vertices.row(mesh.faces(f, j)).transpose() - vc).squaredNorm();
        const double ek2 = (mesh.vertices.row(mesh.faces(f, k)).transpose() - vc).squaredNorm();
        part = (ej2 / std::tan(angles.angles(f, k)) + ek2 / std::tan(angles.angles(f, j))) / 8;
      }
      areas[mesh.faces(f, c)] += part;
    }
  }
  return areas;
}
} // namespace rollcheck::geometry
