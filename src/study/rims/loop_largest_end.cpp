// Where the rim loop's largest end pressure sits (study/rims/loop_largest_end.h).
#include "study/rims/loop_largest_end.h"
#include "core/degree.h"
#include "fem/scenes/rim_end_contact.h"
#include <numbers>
#include <vector>

namespace rollcheck::study::rims
{
std::optional<LoopLargestEnd> loop_largest_end(MPI_Comm comm, const loop_scores::LoopSamples& samples,
                                               std::span<const std::size_t> ruling_sample,
                                               std::span<const double> times_s, const EndRatios& ratios,
                                               double edge_radius_m, double effective_modulus_pa)
{
  struct
  {
    double value;
    int rank;
  } largest{0.0, 0};
  MPI_Comm_rank(comm, &largest.rank);
  LoopLargestEnd here;
  for (std::size_t k = 0; k < samples.rulings.size(); ++k)
  {
    const std::vector<loop_scores::LoadedEnd>& ends = samples.rulings[k].ends;
    for (const loop_scores::LoadedEnd& hull_end : ends)
    {
      const loop_scores::LoadedEnd end = loop_scores::finished_end(hull_end, edge_radius_m);
      if (!(loop_scores::half_width_over_radius(end) < fem::largest_half_width_over_radius))
        continue;
      const std::optional<double> ratio = ratios(1, end);
      if (!ratio || !(*ratio * end.line_hertz_pa > largest.value))
        continue;
      largest.value = *ratio * end.line_hertz_pa;
      here.sample = ruling_sample[k];
      here.time_s = times_s[here.sample];
      here.loop_fraction = here.time_s / times_s.back();
      here.section_angle_rad = end.interior_angle_rad;
      here.dihedral_angle_rad = end.dihedral_angle_rad;
      here.sheet_radius_m = end.radius_m;
      here.line_load_n_per_m = end.load_ratio * effective_modulus_pa * end.radius_m;
      here.ratio = *ratio;
      here.flat_rim_table = !ratios.flat_table.empty() && end.interior_angle_rad >= ratios.flat_from_rad;
    }
  }
  MPI_Allreduce(MPI_IN_PLACE, &largest, 1, MPI_DOUBLE_INT, MPI_MAXLOC, comm);
  if (!(largest.value > 0))
    return std::nullopt;
  MPI_Bcast(&here, sizeof here, MPI_BYTE, largest.rank, comm);
  return here;
}

nlohmann::json to_json(const LoopLargestEnd& end)
{
  return {{"sample", end.sample},
          {"time_s", end.time_s},
          {"loop_fraction", end.loop_fraction},
          {"interior_angle_deg", end.section_angle_rad / degree},
          {"dihedral_angle_deg", end.dihedral_angle_rad / degree},
          {"sheet_radius_m", end.sheet_radius_m},
          {"line_load_n_per_m", end.line_load_n_per_m},
          {"ratio", end.ratio},
          {"table", end.flat_rim_table ? "flat-rim" : "end"}};
}
} // namespace rollcheck::study::rims
