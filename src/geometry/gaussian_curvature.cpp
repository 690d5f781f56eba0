#include "geometry/gaussian_curvature.h"
#include <numbers>

namespace rollcheck::geometry
{
Eigen::VectorXd angle_defects(const SurfaceMesh& mesh, const InternalAngles& angles)
{
  Eigen::VectorXd defect = Eigen::VectorXd::Constant(mesh.vertices.rows(), 2 * std::numbers::pi);
  for (Eigen::Index f = 0; f < mesh.faces.rows(); ++f)
    if (!angles.degenerate[f])
      for (int c = 0; c < 3; ++c)
        defect[mesh.faces(f, c)] -= angles.angles(f, c);
  return defect;
}

Eigen::VectorXd gaussian_curvature(const SurfaceMesh& mesh, const InternalAngles& angles,
                                   const Eigen::VectorXd& vertex_areas)
{
  constexpr double min_area = 1e-15; // m^2, the reference's cut-off
  Eigen::VectorXd k = angle_defects(mesh, angles);
  for (Eigen::Index v = 0; v < k.size(); ++v)
    k[v] = vertex_areas[v] > min_area ? k[v] / vertex_areas[v] : 0.0;
  return k;
}
} // namespace rollcheck::geometry
