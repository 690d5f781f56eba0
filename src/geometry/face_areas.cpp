#include "geometry/face_areas.h"
#include <Eigen/Geometry>

namespace rollcheck::geometry
{
Eigen::VectorXd face_areas(const SurfaceMesh& mesh)
{
  Eigen::VectorXd areas(mesh.faces.rows());
  for (Eigen::Index f = 0; f < mesh.faces.rows(); ++f)
  {
    const Eigen::Vector3d v0 = mesh.vertices.row(mesh.faces(f, 0));
    const Eigen::Vector3d e1 = mesh.vertices.row(mesh.faces(f, 1)).transpose() - v0;
    const Eigen::Vector3d e2 = mesh.vertices.row(mesh.faces(f, 2)).transpose() - v0;
    areas[f] = 0.5 * e1.cross(e2).norm();
  }
  return areas;
}
} // namespace rollcheck::geometry
