#include "contact/rim_dihedral_angle.h"
#include "contact/rim_overhang.h"
#include <algorithm>
#include <cmath>
#include <numbers>

namespace rollcheck::contact
{
std::array<double, 2> rim_dihedral_angle(std::span<const oracle::Circle> circles, int start_circle, int end_circle,
                                         const oracle::Ruling& ruling)
{
  const Eigen::Vector3d& u = ruling.direction;
  const std::array<std::pair<int, Eigen::Vector3d>, 2> ends{
      {{start_circle, ruling.start_m}, {end_circle, ruling.end_m}}};
  std::array<double, 2> dihedral{};
  for (std::size_t e = 0; e < 2; ++e)
  {
    const Eigen::Vector3d other = other_face_normal(circles, ends[e].first, ends[e].second, u);
    dihedral[e] = std::numbers::pi - std::acos(std::clamp(u.dot(other), -1.0, 1.0));
  }
  return dihedral;
}
} // namespace rollcheck::contact
