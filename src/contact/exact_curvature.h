#pragma once
// Exact curvature of the two-circle rollers (the oloid among them) beside the
// discrete estimates on their hull meshes.
//
// The hull of two circles is bounded by a developable ruled surface (plus, for
// some rollers, flat pieces of the circles' discs). Along a ruling from s_1 on
// the first circle to s_2 on the second (oracle/rolling_dynamics.h), the
// tangent plane is constant, so one principal curvature is 0 (along the
// ruling) and the Gaussian curvature is K = 0. Parametrising the ruling family
// by the turning angle sigma of its normal, X(sigma, s) = (1 - s) s_1 + s s_2,
// the normal turns at unit rate while the surface point moves across the
// ruling at dX/dsigma . T = (1 - s) R_1 + s R_2, so the other principal
// curvature is
//   kappa(s) = 1 / R(s),  R(s) = (1 - s) R_1 + s R_2,  R_i = (ds_i/dsigma) . T,
// linear in s for its radius (do Carmo, "Differential Geometry of Curves and
// Surfaces", 1976, sec. 3-5; H. Dirnboeck, H. Stachel, J. Geom. Graph. 1 (1997)
// 105-118, for the oloid). H = 1 / (2 R), K = 0.
//
// The hull meshes have all their vertices on the two circles, i.e. on the
// rims, where the surface has a crease: the discrete Gaussian curvature there
// (angle defect / vertex area) measures the turning of the normal across the
// crease, which the exact smooth pieces do not have. Its total is 4 pi (Gauss-
// Bonnet) whatever the mesh, so on the oloid its mean over the surface is
// 4 pi / A = 1 / r^2 and never tends to the exact K = 0 of the surface the
// rulings sweep.
#include "geometry/surface_mesh.h"
#include "oracle/rolling_dynamics.h"
#include <Eigen/Core>
#include <vector>

namespace rollcheck::contact
{
struct DevelopableCurvature
{
  double radius_m;        ///< R(s), radius of normal curvature across the ruling
  double maximum_per_m;   ///< 1 / R(s)
  double mean_per_m;      ///< 1 / (2 R(s))
  double gaussian_per_m2; ///< 0
};

/// At fraction s in [0, 1] of the ruling (InputError outside).
DevelopableCurvature developable_curvature(const oracle::Ruling& ruling, double s);

struct FaceCurvatureComparison
{
  /// Exact mean curvature at the face centroid's point of the ruled surface
  /// (the face normal projected onto the contact curve, the centroid onto its
  /// ruling); 0 on faces lying in a circle's plane.
  Eigen::VectorXd exact_mean_per_m;
  Eigen::VectorXd exact_gaussian_per_m2; ///< 0 everywhere
  /// Mean of the three vertices' discrete curvatures: cotangent-Laplacian H and
  /// angle-defect K over mixed Voronoi areas (geometry/).
  Eigen::VectorXd discrete_mean_per_m;
  Eigen::VectorXd discrete_gaussian_per_m2;
  std::vector<bool> ruled; ///< face spans the two circles (not a flat disc piece)
};

/// For a mesh of the hull of `body`'s two circles (vertices on the circles).
FaceCurvatureComparison compare_face_curvatures(const geometry::SurfaceMesh& mesh, const oracle::TwoCircleBody& body);
} // namespace rollcheck::contact
