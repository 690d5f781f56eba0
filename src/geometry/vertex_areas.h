#pragma once
// Area attributed to each vertex, the denominator of discrete curvature
// densities. Degenerate faces (see internal_angles.h) contribute nothing.
//  - barycentric: A_i = sum over incident faces of a_f / 3 (what the reference
//    code calls its "Voronoi area").
//  - mixed Voronoi (M. Meyer, M. Desbrun, P. Schroeder, A. Barr, "Discrete
//    differential-geometry operators for triangulated 2-manifolds", 2003,
//    fig. 4): for a non-obtuse face, the Voronoi part
//    (|e_ij|^2 cot(theta_k) + |e_ik|^2 cot(theta_j)) / 8; for an obtuse face,
//    a_f / 2 at the obtuse corner and a_f / 4 at the other two. The areas tile
//    the surface exactly and make the curvature densities consistent.
#include "geometry/internal_angles.h"
#include "geometry/surface_mesh.h"
#include <Eigen/Core>

namespace rollcheck::geometry
{
Eigen::VectorXd barycentric_vertex_areas(const SurfaceMesh& mesh, const InternalAngles& angles);
Eigen::VectorXd mixed_voronoi_vertex_areas(const SurfaceMesh& mesh, const InternalAngles& angles);
} // namespace rollcheck::geometry
