#include "geometry/face_centroids.h"

namespace rollcheck::geometry
{
Vertices face_centroids(const SurfaceMesh& mesh)
{
  Vertices centroids(mesh.faces.rows(), 3);
  for (Eigen::Index f = 0; f < mesh.faces.rows(); ++f)
    centroids.row(f) = (mesh.vertices.row(mesh.faces(f, 0)) + mesh.vertices.row(mesh.faces(f, 1))
                        + mesh.vertices.row(mesh.faces(f, 2)))
                       / 3.0;
  return centroids;
}
} // namespace rollcheck::geometry
