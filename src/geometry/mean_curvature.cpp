#include "geometry/mean_curvature.h"
#include <cmath>

namespace rollcheck::geometry
{
Eigen::VectorXd mean_curvature(const SurfaceMesh& mesh, const InternalAngles& angles,
                               const Eigen::VectorXd& vertex_areas)
{
  Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> laplacian
      = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>::Zero(mesh.vertices.rows(), 3);
  for (Eigen::Index f = 0; f < mesh.faces.rows(); ++f)
  {
    if (angles.degenerate[f])
      continue;
    double cot[3];
    for (int c = 0; c < 3; ++c)
      cot[c] = angles.cosines(f, c) / (std::sin(angles.angles(f, c)) + 1e-30);
    const int i = mesh.faces(f, 0), j = mesh.faces(f, 1), k = mesh.faces(f, 2);
    const Eigen::RowVector3d vi = mesh.vertices.row(i), vj = mesh.vertices.row(j), vk = mesh.vertices.row(k);
    // Each edge is weighted by the cotangent of the angle opposite it.
    laplacian.row(i) += (cot[2] * (vj - vi) + cot[1] * (vk - vi)).eval();
    laplacian.row(j) += (cot[2] * (vi - vj) + cot[0] * (vk - vj)).eval();
    laplacian.row(k) += (cot[1] * (vi - vk) + cot[0] * (vj - vk)).eval();
  }
  constexpr double min_area = 1e-15; // m^2, the reference's cut-off
  Eigen::VectorXd h = Eigen::VectorXd::Zero(mesh.vertices.rows());
  for (Eigen::Index v = 0; v < h.size(); ++v)
  {
    if (vertex_areas[v] <= min_area)
      continue;
    const auto l = laplacian.row(v);
    // |L| with the fused-multiply-add rounding of the reference's BLAS norm.
    const double length = std::sqrt(std::fma(l[2], l[2], std::fma(l[1], l[1], l[0] * l[0])));
    h[v] = length / (4 * vertex_areas[v]);
  }
  return h;
}
} // namespace rollcheck::geometry
