#pragma once
// Curvature of each face and its effective Hertz radius, as the reference code
// (hertz_oracle.compute_face_curvatures) derives them, with the paper-compat
// switches for the vertex mean curvature, the vertex areas and the averaging
// to faces:
//   vertex H_v, K_v       (geometry/mean_curvature.h, gaussian_curvature.h)
//   face H_f, K_f         mean of the three vertex values, or area-weighted
//   kappa_1,2 = H_f +- sqrt(max(H_f^2 - K_f, 0))
//   R_eff = 1 / sqrt(|kappa_1 kappa_2|)  both |kappa| above the floor (point contact)
//         = 1 / |kappa_1|                only kappa_1 above it (used as a point contact too)
//         = infinity                     flat: no Hertz pressure.
#include "contact/contact_parameters.h"
#include "geometry/surface_mesh.h"
#include "oracle/paper_compat.h"
#include <Eigen/Core>

namespace rollcheck::contact
{
struct FaceCurvature
{
  Eigen::VectorXd vertex_mean;        ///< H_v as used (1/m): doubled in paper-compatible mode
  Eigen::VectorXd vertex_gaussian;    ///< K_v (1/m^2)
  Eigen::VectorXd mean, gaussian;     ///< per face
  Eigen::VectorXd kappa1, kappa2;     ///< per face (1/m)
  Eigen::VectorXd effective_radius_m; ///< per face, +inf when flat
  long flat_faces = 0;
};

FaceCurvature face_curvature(const geometry::SurfaceMesh& mesh, const HertzParameters& hertz,
                             const oracle::PaperCompat& compat);
} // namespace rollcheck::contact
