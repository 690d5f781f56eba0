#include "contact/wedge_exponent.h"
#include "core/error.h"
#include <cmath>
#include <fmt/format.h>
#include <numbers>

namespace rollcheck::contact
{
double wedge_stress_exponent(double w)
{
  constexpr double pi = std::numbers::pi;
  if (!(w > 0 && w <= 2 * pi))
    throw InputError(fmt::format("wedge angle {} rad: must lie in (0, 2 pi]", w));
  if (w <= pi)
    return 0.0; // no root in (0, 1): the stresses stay bounded
  // f(lambda) = sin(lambda w) + lambda sin(w) is positive just above 0
  // (f ~ lambda (w + sin w) > 0) and f(1) = sin w + sin w <= 0 for w in (pi, 2 pi];
  // the least root lies below pi / w, where sin(lambda w) turns negative.
  auto f = [w](double lambda) { return std::sin(lambda * w) + lambda * std::sin(w); };
  double lo = 1e-9, hi = pi / w + 1e-12;
  for (int i = 0; i < 200 && hi - lo > 1e-15; ++i)
  {
    const double mid = 0.5 * (lo + hi);
    (f(mid) > 0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi) - 1.0;
}

double edge_on_rigid_plane_exponent(double interior_angle_rad) { return wedge_stress_exponent(2 * interior_angle_rad); }
} // namespace rollcheck::contact
