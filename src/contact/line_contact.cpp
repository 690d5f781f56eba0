#include "contact/line_contact.h"
#include "core/error.h"
#include "oracle/contact_density.h"
#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <limits>

namespace rollcheck::contact
{
SlicedLineContact sliced_line_contact(double force_n, double centre_of_pressure, double length_m,
                                      double start_radius_m, double end_radius_m, double effective_modulus_pa,
                                      double poisson_ratio, int slices)
{
  auto require_positive = [](double x, const char* what) {
    if (!std::isfinite(x) || x <= 0)
      throw InputError(fmt::format("sliced line contact: {} must be positive and finite, got {}", what, x));
  };
  require_positive(force_n, "normal force (N)");
  require_positive(length_m, "ruling length (m)");
  require_positive(start_radius_m, "radius at the start (m)");
  require_positive(end_radius_m, "radius at the end (m)");
  require_positive(effective_modulus_pa, "effective modulus (Pa)");
  if (!std::isfinite(centre_of_pressure) || centre_of_pressure < 0 || centre_of_pressure > 1)
    throw InputError(fmt::format("sliced line contact: centre of pressure must lie in [0, 1], got {}",
                                 centre_of_pressure));
  if (!(poisson_ratio >= 0 && poisson_ratio < 0.5))
    throw InputError(fmt::format("sliced line contact: Poisson ratio must lie in [0, 0.5), got {}", poisson_ratio));
  if (slices < 1)
    throw InputError(fmt::format("sliced line contact: at least one slice, got {}", slices));

  SlicedLineContact result;
  const double ds = 1.0 / slices;
  // Where the loaded length ends under the no-tension rule (none inside [0, 1]
  // when the centre of pressure lies in the middle third).
  const double kink = centre_of_pressure < 1.0 / 3   ? 3 * centre_of_pressure
                      : centre_of_pressure > 2.0 / 3 ? 1 - 3 * (1 - centre_of_pressure)
                                                     : 0.0;
  for (int k = 0; k < slices; ++k)
  {
    // Mean load of the slice, exact: p(s) is linear on either side of the end
    // of the loaded length, so the midpoint rule on each side integrates it.
    const double s0 = k * ds, s1 = (k + 1) * ds, s = (s0 + s1) / 2;
    double integral = 0;
    const double split = std::clamp(kink, s0, s1);
    for (const auto& [a, b] : {std::pair{s0, split}, std::pair{split, s1}})
      integral += (b - a) * oracle::line_load(force_n, centre_of_pressure, length_m, (a + b) / 2);
    LineContactSlice slice{};
    slice.position_m = s * length_m;
    slice.radius_m = (1 - s) * start_radius_m + s * end_radius_m;
    slice.load_n_per_m = integral / ds;
    if (slice.load_n_per_m > 0)
    {
      slice.hertz = line_contact(slice.load_n_per_m, slice.radius_m, effective_modulus_pa, poisson_ratio);
      result.loaded_length_m += ds * length_m;
      result.max_peak_pressure_pa = std::max(result.max_peak_pressure_pa, slice.hertz.peak_pressure_pa);
      result.max_von_mises_pa = std::max(result.max_von_mises_pa, slice.hertz.max_von_mises_pa);
      result.max_shear_pa = std::max(result.max_shear_pa, slice.hertz.max_shear_pa);
    }
    result.force_n += slice.load_n_per_m * ds * length_m;
    result.slices.push_back(slice);
  }
  return result;
}

double point_contact_radius(double kappa_1_per_m, double kappa_2_per_m)
{
  const double gaussian = kappa_1_per_m * kappa_2_per_m;
  return gaussian > 0 ? 1 / std::sqrt(gaussian) : std::numeric_limits<double>::infinity();
}
} // namespace rollcheck::contact
