#include "study/rims/loop_half_space_end.h"
#include "contact/hertz.h"
#include "core/degree.h"
#include "core/error.h"
#include "study/rims/end_table.h"
#include <spdlog/spdlog.h>

namespace rollcheck::study::rims
{
namespace
{
HalfSpaceEndSettings half_space_settings(const fem::RimEndSettings& end, unsigned threads)
{
  HalfSpaceEndSettings s;
  s.sheet_radius_m = end.radius_m;
  s.load_n_per_m = end.load_n_per_m;
  s.edge_radius_m = end.edge_radius_m;
  s.youngs_modulus_pa = end.youngs_modulus_pa;
  s.poisson_ratio = end.poisson_ratio;
  s.steel_counter_face = end.counter_face == fem::CounterFace::block;
  s.depth_over_half_width = end.depth_over_half_width;
  // Its own two levels, not the FEM's: the half-space's grid resolves the
  // boundary layer from the first, and its second level moves the ratio by
  // 0.02 % (docs/methods/rims.md#half-space-theory-as-a-reduction).
  s.levels = 2;
  s.tolerance = end.tolerance;
  s.threads = threads;
  return s;
}
} // namespace

bool takes_half_space_end(const fem::RimEndSettings& end, double from_rad)
{
  if (!(end.edge_radius_m > 0) || end.interior_angle_rad < from_rad
      || end.depth_over_half_width > largest_held_length_over_half_width)
    return false;
  const double modulus = contact::effective_modulus(end.youngs_modulus_pa, end.poisson_ratio,
                                                    end.counter_face == fem::CounterFace::block);
  const double b = contact::line_contact(end.load_n_per_m, end.radius_m, modulus, end.poisson_ratio).half_width_m;
  return end.edge_radius_m >= smallest_half_space_edge_over_half_width * b;
}

std::pair<fem::RimEndStudy, HalfSpaceEndStudy> half_space_end_model(const fem::RimEndSettings& end, unsigned threads)
{
  const HalfSpaceEndStudy hs = half_space_end(half_space_settings(end, threads));
  fem::RimEndStudy record;
  record.setup = end;
  record.effective_modulus_pa = hs.effective_modulus_pa;
  record.half_width_m = hs.half_width_m;
  record.hertz_peak_pa = hs.line_hertz_p0_pa;
  record.dihedral_angle_rad = end.interior_angle_rad;
  record.boundary_layer_m = hs.boundary_layer_m;
  record.resolved = true; // its finest cells are s / 8 at the first level
  record.flat_sheet = true;
  record.converged = hs.converged;
  record.end_to_interior = hs.end_to_interior();
  for (std::size_t k = 0; k < hs.levels.size(); ++k)
  {
    const HalfSpaceEndLevel& l = hs.levels[k];
    fem::RimEndLevel level;
    level.edge_element_m = hs.end_factor.element_size_m[k];
    level.far_load_n_per_m = end.load_n_per_m;
    level.far_peak_pa = l.end.far_over_p0 * hs.line_hertz_p0_pa;
    level.mid_peak_pa = level.far_peak_pa;
    level.end_peak_pa = l.end.peak_over_p0 * hs.line_hertz_p0_pa;
    level.end_peak_x_m = l.end.peak_x_over_layer * hs.boundary_layer_m;
    level.wall_s = l.wall_s;
    record.levels.push_back(level);
  }
  if (hs.levels.size() >= 2)
    record.end_change = fem::end_to_interior_ratio_change(hs.end_factor.value.end()[-2], hs.end_factor.value.back());
  return {record, hs};
}

std::pair<fem::RimEndStudy, std::optional<HalfSpaceEndStudy>>
loop_end_model(MPI_Comm comm, const fem::RimEndSettings& end, double from_rad)
{
  if (takes_half_space_end(end, from_rad))
  {
    int ranks = 1, rank = 0;
    MPI_Comm_size(comm, &ranks);
    MPI_Comm_rank(comm, &rank);
    try
    {
      auto [record, half_space] = half_space_end_model(end, ranks > 1 ? 1 : 0);
      return {std::move(record), std::move(half_space)};
    }
    catch (const ComputationError& e)
    {
      // Every rank solved the same end and failed alike: the FEM takes it.
      if (rank == 0)
        spdlog::warn("rim loop: the half-space end at {:.2f} deg, R = {:.4g} m, q = {:.4g} N/m failed ({}); the FEM "
                     "end model takes it",
                     end.interior_angle_rad / degree, end.radius_m, end.load_n_per_m, e.what());
    }
  }
  return {fem::solve_rim_end(comm, end), std::nullopt};
}
} // namespace rollcheck::study::rims
