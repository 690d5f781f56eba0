#pragma once
// Unsigned discrete mean curvature at each vertex from the cotangent Laplacian
// (U. Pinkall, K. Polthier 1993; M. Meyer et al. 2003, eq. 8):
//   L_i = sum over faces f at i of  cot(theta_k) (x_j - x_i) + cot(theta_j) (x_k - x_i),
//   H_i = |L_i| / (4 A_i),
// where j, k are the other corners of f and theta_j, theta_k their angles, so
// that every edge (i, j) collects cot(alpha_ij) + cot(beta_ij), and A_i is the
// area attributed to vertex i (vertex_areas.h). H is 1/r on a sphere of radius
// r and 1/(2r) on a cylinder side. Vertices with A_i <= 1e-15 m^2 get 0.
//
// The reference code (hertz_oracle.compute_vertex_curvatures) divides by
// 2 A_i instead, i.e. returns 2 H = kappa_1 + kappa_2, with barycentric A_i;
// its cotangent is cos(theta) / (sin(theta) + 1e-30) from the clamped cosine of
// internal_angles.h, which is the form used here, so that 2 * mean_curvature()
// reproduces its values to rounding.
#include "geometry/internal_angles.h"
#include "geometry/surface_mesh.h"
#include <Eigen/Core>

namespace rollcheck::geometry
{
Eigen::VectorXd mean_curvature(const SurfaceMesh& mesh, const InternalAngles& angles,
                               const Eigen::VectorXd& vertex_areas);
} // namespace rollcheck::geometry
