#include "contact/straight_rim_end.h"
#include <algorithm>
#include <cmath>
#include <numbers>

namespace rollcheck::contact
{
RoundedEndProblem straight_rim_end(const RoundedEndSettings& s, double interior_angle_rad, double sheet_radius_m,
                                   double load_n_per_m)
{
  RoundedEndProblem end;
  const double lean = std::tan(std::numbers::pi - interior_angle_rad), radius = sheet_radius_m;
  end.hull_height = [lean, radius](double x, double y) { return y * y / (2 * radius) + std::max(0.0, -x * lean); };
  end.sheet_radius = [radius](double) { return radius; };
  end.load = {load_n_per_m, 0.0, 0.0};
  const double half_width = end_line_hertz(s, end).half_width_m;
  end.load.length_m = std::max(400.0, 3 * s.after_over_half_width) * half_width;
  end.ruling_length_m = end.load.length_m;
  return end;
}
} // namespace rollcheck::contact
