#pragma once
// A rounded end of the rim loop (a direct end or an end table node) by
// half-space theory instead of the FEM end model (study/rims/half_space_end.h,
// RimLoopSettings::half_space_from_rad): which ends take it, the end
// model's record of it that the loop reads (its end/interior ratio, its
// convergence, its far side and end peak per level), and the loop's choice
// between it and the FEM at each end.
#include "fem/scenes/rim_end_contact.h"
#include "study/rims/half_space_end.h"
#include <mpi.h>
#include <optional>
#include <utility>

namespace rollcheck::study::rims
{
/// Whether the loop end model at `end` (its q, R, angle and depth set)
/// takes half-space theory: a rounded edge, its angle at least `from_rad`,
/// r_e at least smallest_half_space_edge_over_half_width times line Hertz's
/// b there and its block at most largest_held_length_over_half_width b deep.
bool takes_half_space_end(const fem::RimEndSettings& end, double from_rad);

/// The end at `end` by half-space theory held over its block's depth, at
/// two levels and the end model's tolerance, and the end model's record of it
/// (no DOFs, approach or centre line: its levels' far side, end peak and
/// wall time); `threads` the influence's (0: every core; the loop's ranks
/// each solve it alike, on one thread each when there are several).
std::pair<fem::RimEndStudy, HalfSpaceEndStudy> half_space_end_model(const fem::RimEndSettings& end, unsigned threads);

/// The loop's end model at `end`: the FEM's (fem::solve_rim_end on `comm`),
/// or the half-space end and its record where takes_half_space_end(end,
/// from_rad), which every rank solves alike, on one influence thread each
/// where there are several; where that fails (ComputationError: its
/// contact outgrew its grid) the FEM's, with a warning.
std::pair<fem::RimEndStudy, std::optional<HalfSpaceEndStudy>>
loop_end_model(MPI_Comm comm, const fem::RimEndSettings& end, double from_rad);
} // namespace rollcheck::study::rims
