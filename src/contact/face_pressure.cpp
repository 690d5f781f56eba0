#include "contact/face_pressure.h"
#include "contact/hertz.h"
#include <cmath>

namespace rollcheck::contact
{
FacePressure face_pressure(const Eigen::VectorXd& radius, const HertzParameters& hertz,
                           const oracle::PaperCompat& compat)
{
  FacePressure out;
  out.effective_modulus_pa = compat.identical_bodies_modulus
                                 ? effective_modulus_identical_bodies(hertz.youngs_modulus_pa, hertz.poisson_ratio)
                                 : effective_modulus_rigid_plane(hertz.youngs_modulus_pa, hertz.poisson_ratio);
  const PointHertz unit = point_contact(hertz.normal_load_n, 1.0, out.effective_modulus_pa, hertz.poisson_ratio);
  out.peak_pressure_pa = Eigen::VectorXd::Zero(radius.size());
  out.contact_radius_m = Eigen::VectorXd::Zero(radius.size());
  for (Eigen::Index f = 0; f < radius.size(); ++f)
  {
    const double r = radius[f];
    if (!(r > 0) || !(r <= hertz.flat_radius_m))
      continue;
    const double scale = std::cbrt(r); // a / a(1 m)
    out.contact_radius_m[f] = unit.contact_radius_m * scale;
    out.peak_pressure_pa[f] = unit.peak_pressure_pa / (scale * scale);
  }
  return out;
}
} // namespace rollcheck::contact
