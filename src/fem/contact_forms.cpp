#include "fem/contact_forms.h"
#include "hertz.h"
#include <stdexcept>

namespace rollcheck::fem
{
ContactForms contact_forms(Model model, int degree)
{
#define ROLLCHECK_FORMS(TAG, DEG)                                                                      \
  ContactForms{form_hertz_residual_##TAG##_p##DEG,                                                     \
               form_hertz_jacobian_##TAG##_p##DEG,                                                     \
               form_hertz_energy_##TAG##_p##DEG,                                                       \
               form_hertz_contact_force_##TAG##_p##DEG,                                                \
               form_hertz_pressure_load_##TAG##_p##DEG,                                                \
               form_hertz_stress_load_##TAG##_p##DEG,                                                  \
               form_hertz_volume_mass_##TAG,                                                           \
               form_hertz_contact_mass_##TAG##_p##DEG,                                                          \
               functionspace_form_hertz_residual_##TAG##_p##DEG,                                       \
               functionspace_form_hertz_volume_mass_##TAG,                                             \
               functionspace_form_hertz_stress_load_##TAG##_p##DEG,                                    \
               functionspace_form_hertz_residual_##TAG##_p1,                                           \
               #TAG "_p" #DEG}
  switch (model)
  {
  case Model::axisymmetric: return degree == 1 ? ROLLCHECK_FORMS(axi, 1) : ROLLCHECK_FORMS(axi, 2);
  case Model::plane_strain: return degree == 1 ? ROLLCHECK_FORMS(plane, 1) : ROLLCHECK_FORMS(plane, 2);
  case Model::solid: return degree == 1 ? ROLLCHECK_FORMS(solid, 1) : ROLLCHECK_FORMS(solid, 2);
  }
#undef ROLLCHECK_FORMS
  throw std::logic_error("contact_forms: unknown model");
}
} // namespace rollcheck::fem
