#include "fem/mesh/rim_end_geometry.h"
#include "fem/mesh/oblique_end_angle.h"
#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <numbers>

namespace rollcheck::fem
{
double fillet_start_distance(double edge_radius_m, double interior_angle_rad)
{
  return edge_radius_m * std::tan((std::numbers::pi - interior_angle_rad) / 2);
}

double rim_end_element_size(const RimEndSizes& sizes, const double* point)
{
  double x[3] = {0, 0, point[2]};
  oblique_edge_frame(sizes.crossing_angle_rad, point[0], point[1], x[0], x[1]);
  // Distances from the loaded part of the edge's band (along y about
  // (edge_x_m, 0, 0)) and from the contact strip (along -x).
  const double to_edge = std::sqrt(std::pow(std::max(std::abs(x[0] - sizes.edge_x_m) - sizes.edge_band_m, 0.0), 2)
                                   + x[2] * x[2]
                                   + std::pow(std::max(x[1] - sizes.edge_zone_m, 0.0), 2));
  const double to_strip = std::sqrt(x[2] * x[2] + std::pow(std::max(x[1] - sizes.contact_zone_m, 0.0), 2)
                                    + std::pow(std::max(x[0], 0.0), 2));
  return std::min(
      {sizes.far_m, sizes.edge_m + sizes.growth * to_edge, sizes.contact_m + sizes.growth * to_strip});
}
} // namespace rollcheck::fem
