#pragma once
// Hertz point-contact peak pressure of each face pressed on the plane with the
// reference load: a = (3 F R / (4 E*))^(1/3), p0 = 3 F / (2 pi a^2)
// (contact/hertz.h). contact::point_contact is evaluated once, at R = 1 m, and
// scaled to each face by Hertz similarity at fixed F and E* (a ~ R^(1/3),
// p0 ~ R^(-2/3)), because it also locates the subsurface stress maxima, which
// costs about 0.2 ms a call. Faces with R_eff above the flat-face radius, or
// not positive, carry no pressure (p0 = 0, a = 0), as in the reference code.
// E* is E / (2 (1 - nu^2)) in paper-compatible mode, else E / (1 - nu^2).
#include "contact/contact_parameters.h"
#include "oracle/paper_compat.h"
#include <Eigen/Core>

namespace rollcheck::contact
{
struct FacePressure
{
  Eigen::VectorXd peak_pressure_pa;  ///< p0 per face at the reference load
  Eigen::VectorXd contact_radius_m;  ///< a per face
  double effective_modulus_pa = 0;   ///< E* used
};

FacePressure face_pressure(const Eigen::VectorXd& effective_radius_m, const HertzParameters& hertz,
                           const oracle::PaperCompat& compat);
} // namespace rollcheck::contact
