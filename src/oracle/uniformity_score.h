#pragma once
// A resolution-independent uniformity score of a contact density.
//
// With face areas a_f, total area A, contact measure mu_f per face
// (contact_density.h), density rho_f = mu_f / a_f and mean density
// rho_bar = sum mu_f / A, the normalised score is the area-weighted variance
// of the density relative to its mean,
//   U = (1/A) sum_f a_f (rho_f / rho_bar - 1)^2,
// the squared coefficient of variation of rho over the surface. U = 0 for
// uniform contact; a body touched on a fraction phi of its area, uniformly
// there, has U = 1/phi - 1. As the mesh is refined, rho_f tends to the face
// averages of the continuous density and U to
//   U_inf = (1/A) integral (rho / rho_bar - 1)^2 dA = A integral rho^2 dA / (integral rho dA)^2 - 1,
// which is finite whenever rho is square-integrable (always for line contact
// with radii of curvature bounded away from zero).
//
// The preprint's CDS (Definition 1) applies the same template to the hit
// shares p_f = c_f / sum c: since p_f = (a_f / A)(rho_f / rho_bar),
//   CDS = (1/A) sum_f a_f (a_f / A)^2 (rho_f / rho_bar - 1)^2,
// i.e. U with every face's term weighted by (a_f / A)^2 ~ N_faces^-2, which is
// the preprint's observed CDS ~ N^-2.03: the decay is the weight, not the body.
//
// For line contact the continuum value needs no mesh. Over one pass of the
// contact ruling (each surface point swept once), a point at fraction s of a
// ruling of length L, radius of normal curvature R(s) = (1 - s) R_0 + s R_1
// across it, swept at turning rate sigma', lies in the area element
// dA = L R dsigma ds, and (contact_density.h):
//  - hertz: rho = 2 b / (|sigma'| R), b^2 = 4 p R / (pi E*), so
//      integral rho dA   = integral dt integral 2 b L ds   (patch area x time),
//      integral rho^2 dA = integral 16 N / (pi E* |sigma'|) dt,
//    N the normal force: the curvature drops out of the second moment;
//  - rigid: rho = 1 / (|sigma'| R), so
//      integral rho dA   = integral L dt,
//      integral rho^2 dA = integral (L / |sigma'|) ln(R_1 / R_0) / (R_1 - R_0) dt,
//    which is large where a ruling end pivots on a rim (R_0 -> 0).
#include "oracle/contact_density.h"
#include "oracle/rolling_dynamics.h"
#include <Eigen/Core>

namespace rollcheck::oracle
{
struct UniformityScore
{
  double normalised_variance = 0; ///< U
  double coverage = 0;            ///< area fraction with rho_f > 1e-6 rho_bar (above clipping rounding)
  double max_over_mean = 0;       ///< max_f rho_f / rho_bar
  double surface_area_m2 = 0;     ///< A
};

/// U from per-face contact measure and face areas. InputError for mismatched
/// sizes, negative or non-finite entries, a non-positive area, or no contact.
UniformityScore uniformity_score(const Eigen::VectorXd& measure, const Eigen::VectorXd& face_areas_m2);

/// U_inf of a line-contact trajectory over [begin_s, end_s], on a body of
/// surface area `surface_area_m2`, assuming each surface point is swept at most
/// once in that window (one loop of the contact curve). InputError for a
/// point-contact trajectory or an empty window.
double continuum_uniformity(const RollingTrajectory& trajectory, double begin_s, double end_s,
                            double surface_area_m2, const ContactWidth& width = {});
} // namespace rollcheck::oracle
