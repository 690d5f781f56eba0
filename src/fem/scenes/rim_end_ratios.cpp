// The end model's end-to-interior ratio, read on its centre line, and its
// change between edge levels (fem/scenes/rim_end_contact.h).
#include "fem/scenes/rim_end_contact.h"
#include "core/error.h"
#include <algorithm>
#include <fmt/format.h>

namespace rollcheck::fem
{
double centre_line_pressure_at(const RimEndLevel& level, double x_m)
{
  const auto& line = level.centre_line; // sorted by x
  const auto after = std::lower_bound(line.begin(), line.end(), x_m,
                                      [](const CentreLineNode& n, double x) { return n.x_m < x; });
  if (after == line.end() || (after == line.begin() && after->x_m != x_m))
    throw ComputationError(fmt::format("rim: x = {:.3g} m lies outside the centre line", x_m));
  if (after->x_m == x_m)
    return after->pressure_pa;
  const CentreLineNode& before = *(after - 1);
  const double t = (x_m - before.x_m) / (after->x_m - before.x_m);
  return (1 - t) * before.pressure_pa + t * after->pressure_pa;
}

double end_to_interior(const RimEndLevel& level, bool sharp_edge)
{
  // A sharp edge's own pressure, not the largest near it: at a square end
  // that largest is the interior's, falling towards the edge. A rounded
  // edge's peak on its fillet.
  return (sharp_edge ? level.edge_pressure_pa : level.end_peak_pa) / level.far_peak_pa;
}

double end_to_interior_ratio_change(double before, double last)
{
  // The ratio's, not the end's pressure in Pa: the interior's own pressure
  // moves with the mesh by a per cent or two (P1 nodal scatter; 1.498 then
  // 1.469 GPa at the 120 deg steel rim from b/128 to b/256), which the end's
  // pressure carries but the ratio does not. Over the larger of the ratio
  // and 1: an acute edge's pressure tends to zero, where its own relative
  // change means nothing.
  return (last - before) / std::max(last, 1.0);
}

double end_to_interior_change(const RimEndLevel& before, const RimEndLevel& last, bool sharp_edge)
{
  return end_to_interior_ratio_change(end_to_interior(before, sharp_edge), end_to_interior(last, sharp_edge));
}
} // namespace rollcheck::fem
