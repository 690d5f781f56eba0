#pragma once
// Interior angles of every triangle, with their cosines, as the reference code
// (hertz_oracle.compute_vertex_curvatures) forms them:
//   cos(theta_i) = clamp(e_ij . e_ik / (|e_ij| |e_ik| + 1e-30), -1, 1),
//   theta_i = acos(cos(theta_i)),
// the 1e-30 keeping zero-length edges finite. Faces whose doubled area
// |e_ij x e_ik| is below 1e-15 m^2 are flagged degenerate: the reference skips
// them in every curvature sum, and so do mean_curvature, gaussian_curvature and
// vertex_areas.
#include "geometry/surface_mesh.h"
#include <Eigen/Core>
#include <vector>

namespace rollcheck::geometry
{
struct InternalAngles
{
  Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> cosines; ///< per face, at corners 0, 1, 2
  Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> angles;  ///< rad
  Eigen::VectorXd areas;          ///< face areas (m^2), 0 for degenerate faces
  std::vector<bool> degenerate;   ///< doubled area below 1e-15 m^2
};

InternalAngles internal_angles(const SurfaceMesh& mesh);
} // namespace rollcheck::geometry
