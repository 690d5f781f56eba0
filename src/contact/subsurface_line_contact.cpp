#include "contact/subsurface_line_contact.h"
#include "core/error.h"
#include <cmath>
#include <fmt/format.h>

namespace rollcheck::contact
{
double LineContactStress::in_plane_shear() const { return std::hypot((xx - zz) / 2, xz); }

LineContactStress line_contact_subsurface_stress(double x, double z, double nu)
{
  if (!(z >= 0))
    throw InputError(fmt::format("line contact subsurface stress: the depth z / b must be >= 0, got {}", z));
  const double a = 1 - x * x + z * z;
  const double d = std::sqrt(a * a + 4 * x * x * z * z);
  const double m = std::sqrt(std::max(0.0, (d + a) / 2));
  const double n = std::copysign(std::sqrt(std::max(0.0, (d - a) / 2)), x);
  LineContactStress s;
  const double mn = m * m + n * n;
  if (mn == 0) // the contact's edge on the surface: every component vanishes there
    return s;
  const double ratio = (z * z + n * n) / mn;
  s.xx = -(m * (1 + ratio) - 2 * z);
  s.zz = -m * (1 - ratio);
  s.xz = -n * (m * m - z * z) / mn;
  s.yy = nu * (s.xx + s.zz);
  return s;
}
} // namespace rollcheck::contact
