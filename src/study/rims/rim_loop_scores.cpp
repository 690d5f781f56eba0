// What the rim loop's result says of its end-aware scores
// (study/rims/rim_loop.h RimLoopResult).
#include "study/rims/rim_loop.h"
#include "core/degree.h"
#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <numbers>

namespace rollcheck::study::rims
{
namespace
{
} // namespace

std::optional<double> RimLoopResult::worst_end_to_interior() const
{
  std::optional<double> worst;
  for (const RimLoopEnd& e : ends)
    if (e.end_peak_pa && e.interior_peak_pa > 0)
      worst = std::max(worst.value_or(0.0), *e.end_peak_pa / e.interior_peak_pa);
  return worst;
}

std::optional<double> RimLoopResult::covered_end_to_interior() const { return covered_end_to_interior(loop); }
std::optional<double> RimLoopResult::covered_limit_change() const { return covered_limit_change(loop); }
std::optional<double> RimLoopResult::loop_end_to_interior() const { return loop_end_to_interior(loop); }
std::string RimLoopResult::end_aware_status() const { return end_aware_status(loop); }

std::optional<double> RimLoopResult::covered_end_to_interior(const loop_scores::LoopSds& of) const
{
  if (of.end_aware.empty() || of.end_aware[0].singular_ends > 0 || !(of.end_aware[0].peak_pa > 0)
      || !(of.fem_peak_pa > 0))
    return std::nullopt;
  return of.end_aware[0].peak_pa / of.fem_peak_pa;
}

std::optional<double> RimLoopResult::covered_limit_change(const loop_scores::LoopSds& of) const
{
  if (!covered_end_to_interior(of) || !(of.end_aware[0].peak_within_half_limit_pa > 0))
    return std::nullopt;
  return of.end_aware[0].peak_pa / of.end_aware[0].peak_within_half_limit_pa - 1;
}

std::optional<double> RimLoopResult::loop_end_to_interior(const loop_scores::LoopSds& of) const
{
  if (of.end_aware.empty() || of.end_aware[0].outside_model_ends > 0)
    return std::nullopt;
  return covered_end_to_interior(of);
}

std::string RimLoopResult::end_aware_status(const loop_scores::LoopSds& of) const
{
  if (of.loaded_ends == 0)
    return "no sample of the loop loads a rim end";
  if (of.end_aware.empty())
    return "not computed";
  const loop_scores::EndAwareScores& all = of.end_aware[0];
  if (all.singular_ends > 0)
    return fmt::format("singular: {} of the loop's {} loaded rim ends have a sharp edge of dihedral angle above "
                       "{:.2f} deg",
                       all.singular_ends, of.loaded_ends, singular_from_rad / degree);
  if (all.outside_model_ends > 0)
    return fmt::format("undefined: {} of the loop's {} loaded rim ends lie where b / R >= {:.1f} (a ruling ending "
                       "near its sheet's apex, no line contact), where no end pressure is defined",
                       all.outside_model_ends, of.loaded_ends, fem::largest_half_width_over_radius);
  const double tolerance = of.tolerance;
  std::vector<std::string> why;
  if (!table_converged)
    why.push_back("a node of the end table or the flat-rim table did not converge");
  if (table_vs_direct && *table_vs_direct > end_setup.tolerance)
    why.push_back(
        fmt::format("the end table differs from the direct end models by {:.1f} %", 100 * *table_vs_direct));
  if (std::abs(all.sds.sample_change()) >= tolerance)
    why.push_back(fmt::format("halving the samples changes it by {:+.2f} %", 100 * all.sds.sample_change()));
  if (of.end_aware.size() > 1 && all.sds.value && of.end_aware[1].sds.value)
    if (const double change = *all.sds.value / *of.end_aware[1].sds.value - 1; std::abs(change) >= tolerance)
      why.push_back(fmt::format("halving the end table's nodes changes it by {:+.2f} %", 100 * change));
  if (!of.converged())
    why.push_back("the interior FEM-SDS is not converged");
  if (why.empty())
    return "converged";
  std::string text = "not converged:";
  for (std::size_t i = 0; i < why.size(); ++i)
    text += (i ? "; " : " ") + why[i];
  return text;
}

double RimLoopResult::flat_rim_seam_radius() const
{
  return std::max(flat_table.front().largest_ratio_side().end_radius_m, end_setup.edge_radius_m);
}

double RimLoopResult::flat_rim_seam_dihedral() const
{
  // The end table is indexed by the dihedral angle, the flat-rim table by the
  // section: at the seam the end table is read at the first node's dihedral.
  return std::clamp(flat_table.front().dihedral_angle_rad, smallest_modelled_angle_rad,
                    largest_modelled_angle(end_setup));
}

std::optional<RimLoopResult::FlatRimSeam> RimLoopResult::flat_rim_seam() const
{
  if (flat_table.empty() || table.empty())
    return std::nullopt;
  const double radius = flat_rim_seam_radius(), dihedral = flat_rim_seam_dihedral();
  for (const std::size_t k : end_table_nodes_read(table, 1, singular_from_rad, dihedral, radius))
    if (!table[k].reached || !table[k].study.end_to_interior)
      return std::nullopt;
  const std::optional<double> ratio = end_table_ratio(table, 1, singular_from_rad, dihedral, radius);
  if (!ratio)
    return std::nullopt;
  return FlatRimSeam{dihedral, radius, *ratio, flat_table.front().ratio()};
}
} // namespace rollcheck::study::rims
