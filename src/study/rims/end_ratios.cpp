// The loop's end/interior ratio of a loaded end (study/rims/end_ratios.h).
#include "study/rims/end_ratios.h"
#include "study/rims/table_nodes.h"
#include <algorithm>

namespace rollcheck::study::rims
{
std::optional<double> EndRatios::operator()(int stride, const loop_scores::LoadedEnd& end) const
{
  if (!flat_table.empty() && end.interior_angle_rad >= flat_from_rad)
  {
    const int flat_stride = static_cast<int>(own_stride(stride, flat_table.size()));
    return flat_rim_own_load ? flat_rim_peak(flat_table, flat_stride, end.interior_angle_rad) / end.line_hertz_pa
                             : flat_rim_ratio(flat_table, flat_stride, end.interior_angle_rad);
  }
  // The end table's angle is the wedge's, normal to the rim; the flat-rim
  // table's is the section's (its nodes are the loop's own ends).
  return end_table_ratio(table, stride, singular_from_rad,
                         std::clamp(end.dihedral_angle_rad, smallest_modelled_angle_rad, largest_modelled_rad),
                         end.radius_m);
}

std::vector<loop_scores::EndFactor> EndRatios::factors() const
{
  std::vector<loop_scores::EndFactor> factors;
  for (const int stride : {1, 2})
    if (stride == 1 || table.size() >= 3 || flat_table.size() >= 3)
      factors.push_back([ratios = *this, stride](const loop_scores::LoadedEnd& end) { return ratios(stride, end); });
  return factors;
}
} // namespace rollcheck::study::rims
