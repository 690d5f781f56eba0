#pragma once
// Discrete Gaussian curvature at each vertex by the angle defect
// (M. Meyer et al. 2003, eq. 9):
//   K_i = (2 pi - sum over faces f at i of theta_i^f) / A_i,
// A_i the area attributed to vertex i (vertex_areas.h). The defects of a closed
// genus-0 surface sum to 4 pi (discrete Gauss-Bonnet). The angles are
// subtracted from 2 pi one face at a time in face order, as the reference code
// does. Vertices with A_i <= 1e-15 m^2 get 0.
#include "geometry/internal_angles.h"
#include "geometry/surface_mesh.h"
#include <Eigen/Core>

namespace rollcheck::geometry
{
/// 2 pi minus the angles at each vertex (rad), the integrated curvature.
Eigen::VectorXd angle_defects(const SurfaceMesh& mesh, const InternalAngles& angles);

/// angle_defects / vertex_areas (1/m^2).
Eigen::VectorXd gaussian_curvature(const SurfaceMesh& mesh, const InternalAngles& angles,
                                   const Eigen::VectorXd& vertex_areas);
} // namespace rollcheck::geometry
