#include "fem/mesh/oblique_end_angle.h"
#include <cmath>
#include <numbers>

namespace rollcheck::fem
{
bool crosses_obliquely(double crossing_angle_rad)
{
  // 90 deg through a conversion from degrees may miss pi / 2 in its last bit.
  return std::abs(crossing_angle_rad - std::numbers::pi / 2) > 1e-12;
}

double oblique_dihedral_angle(double section_angle_rad, double crossing_angle_rad)
{
  if (!crosses_obliquely(crossing_angle_rad))
    return section_angle_rad;
  return std::atan2(std::sin(section_angle_rad), std::cos(section_angle_rad) * std::sin(crossing_angle_rad));
}

double oblique_edge_x(double section_angle_rad, double crossing_angle_rad, double y, double z)
{
  if (!crosses_obliquely(crossing_angle_rad))
    return -z / std::tan(section_angle_rad);
  const double dihedral = oblique_dihedral_angle(section_angle_rad, crossing_angle_rad);
  return y / std::tan(crossing_angle_rad) - z / (std::tan(dihedral) * std::sin(crossing_angle_rad));
}

void oblique_edge_frame(double crossing_angle_rad, double x, double y, double& normal_m, double& across_m)
{
  if (!crosses_obliquely(crossing_angle_rad))
  {
    normal_m = x;
    across_m = y;
    return;
  }
  normal_m = x * std::sin(crossing_angle_rad) - y * std::cos(crossing_angle_rad);
  across_m = std::abs(y);
}
} // namespace rollcheck::fem
