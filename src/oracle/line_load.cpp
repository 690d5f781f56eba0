#include "oracle/line_load.h"
#include <algorithm>

namespace rollcheck::oracle
{
double line_load(double normal_force_n, double centre_of_pressure, double length_m, double s)
{
  if (!(normal_force_n > 0) || !(length_m > 0))
    return 0;
  const double c = std::clamp(centre_of_pressure, 0.0, 1.0);
  if (c < 1.0 / 3)
  {
    const double loaded = 3 * c; // triangle from s = 0, zero at s = 3c
    return s < loaded ? 2 * normal_force_n / (loaded * length_m) * (1 - s / loaded) : 0.0;
  }
  if (c > 2.0 / 3)
    return line_load(normal_force_n, 1 - c, length_m, 1 - s);
  return normal_force_n / length_m * ((4 - 6 * c) + (12 * c - 6) * s);
}
} // namespace rollcheck::oracle
