#pragma once
// Where over the rim loop (study/rims/rim_loop.h) its largest end pressure
// sits: the loaded end, of every ruling sample of every rank, whose ratio
// (study/rims/end_ratios.h) times its line Hertz peak p_H = sqrt(q E* / (pi R))
// is largest, at its finished R (loop_scores::finished_end) and inside the
// end model (b / R below fem::largest_half_width_over_radius). The end-aware
// scores take that end's pressure as the ratio times p_H g(lambda), the
// slices' factor g (fem/scenes/slice_scaling.h) within a few per mille of
// 1 over a loop, so this is the end that sets their peak but where two
// ends lie that close.
#include "study/loop_scores/loop_sds.h"
#include "study/rims/end_ratios.h"
#include <cstddef>
#include <mpi.h>
#include <nlohmann/json.hpp>
#include <optional>
#include <span>

namespace rollcheck::study::rims
{
struct LoopLargestEnd
{
  std::size_t sample = 0;       ///< index in the loop
  double time_s = 0;            ///< of the sample
  double loop_fraction = 0;     ///< time over the loop's last sample's
  double section_angle_rad = 0; ///< in the ruling's vertical plane
  double dihedral_angle_rad = 0;
  double sheet_radius_m = 0;    ///< finished: at least r_e
  double line_load_n_per_m = 0;
  double ratio = 0;             ///< end over line Hertz (the tables')
  bool flat_rim_table = false;  ///< the ratio is the flat-rim table's
};

/// Collective on `comm`. `ruling_sample` gives each of this rank's ruling
/// samples' index in the loop, `times_s` every sample's time; none when no
/// end has a ratio (no loaded end, or every one singular or outside the model).
std::optional<LoopLargestEnd> loop_largest_end(MPI_Comm comm, const loop_scores::LoopSamples& samples,
                                               std::span<const std::size_t> ruling_sample,
                                               std::span<const double> times_s, const EndRatios& ratios,
                                               double edge_radius_m, double effective_modulus_pa);

nlohmann::json to_json(const LoopLargestEnd& end);
} // namespace rollcheck::study::rims
