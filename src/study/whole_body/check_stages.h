#pragma once
// The stages of one whole-body check after its load rule (run_whole_body_check,
// study/whole_body/whole_body_check.h): the slices, the end models, the
// whole body, the comparison. Internal to the check; not part of the wing's
// umbrella header.
#include "fem/scenes/slice_contact.h"
#include "study/whole_body/check_context.h"
#include <array>
#include <string>
#include <vector>

namespace rollcheck::study::whole_body
{
/// The plane-strain slices: one at each station, then one at each loaded
/// end (the locus's loaded ends), at the end or, under a rule that softens
/// the ends, d_m inside it (EndComparison).
struct SliceReadings
{
  std::vector<fem::SliceLoad> loads;        ///< the stations', then the loaded ends'
  std::vector<fem::SliceFem> slices;        ///< in the same order
  std::size_t stations = 0;                 ///< how many of them are stations
  std::vector<int> loaded_ends;             ///< 0 the ruling's start, 1 its end
  std::array<double, 2> read_at_fraction{}; ///< where each loaded end's q and slice are taken
  double wall_s = 0;
};

/// Slices under the rule's q(f) at the stations and the loaded ends.
SliceReadings solve_slice_stage(const CheckContext& context, const LineLoad& load_at, bool match_near_edge);

/// The end model at each loaded end under the rule's q there, read against
/// its far side or, under a rule that softens the ends, its own pressure at
/// d_m (end_model_stage.cpp). Identical ends share one solve.
std::vector<EndComparison> solve_end_model_stage(const CheckContext& context, const LineLoad& load_at,
                                                 const SliceReadings& slices, bool match_near_edge);

/// The whole body at the check's sizes, started from the rule's q at the
/// centre of mass's foot: check's fem, node planes, section nodes, gmsh_s
/// and body_s.
void solve_whole_body_stage(const CheckContext& context, double load_at_centre, WholeBodyCheck& check);

/// Each station's slice against the whole body's peak and line load there
/// (interpolated between its node planes): check's stations, worst_along,
/// worst_load and largest_peak_difference.
void compare_stations(const SliceReadings& slices, WholeBodyCheck& check);

/// Each loaded end's prediction against the whole body's edge (or near-edge
/// peak), the outcome and the verdict: check's ends' body readings and
/// differences, worst_end, outcome, pass and verdict.
void compare_ends(const CheckContext& context, WholeBodyCheck& check);
} // namespace rollcheck::study::whole_body
