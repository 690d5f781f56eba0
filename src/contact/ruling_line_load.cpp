#include "contact/ruling_line_load.h"
#include <algorithm>

namespace rollcheck::contact
{
double RulingLineLoad::at(double x) const { return x < 0 || x > length_m ? 0.0 : at_end_n_per_m + slope_n_per_m2 * x; }

double RulingLineLoad::load_to(double x) const
{
  x = std::clamp(x, 0.0, length_m);
  return at_end_n_per_m * x + slope_n_per_m2 * x * x / 2;
}

double RulingLineLoad::moment_to(double x) const
{
  x = std::clamp(x, 0.0, length_m);
  return at_end_n_per_m * x * x / 2 + slope_n_per_m2 * x * x * x / 3;
}

RulingLineLoad RulingLineLoad::no_tension(double at_end, double slope, double ruling_length)
{
  return {at_end, slope, slope < 0 ? std::min(ruling_length, -at_end / slope) : ruling_length};
}

std::optional<RulingLineLoad> RulingLineLoad::carrying(double force, double centre, double from, double ruling_length)
{
  const double length = ruling_length - from, e = (centre - from) / length;
  double at_from = 0, slope = 0;
  if (e > 0 && e < 1.0 / 3)
  {
    at_from = 2 * force / (3 * e * length);
    slope = -at_from / (3 * e * length);
  }
  else if (e >= 1.0 / 3 && e <= 2.0 / 3)
  {
    at_from = force / length * (4 - 6 * e);
    slope = (force / length * (6 * e - 2) - at_from) / length;
  }
  else
    return std::nullopt;
  return no_tension(at_from - slope * from, slope, ruling_length);
}
} // namespace rollcheck::contact
