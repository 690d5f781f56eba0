#pragma once
// FEM-SDS's continuum value: the score of the loop's FEM pressures on the
// body's exact surface, with no mesh (docs/methods/fem-sds.md#the-continuum-value).
//
// The template's per-face sum of each sample's largest pressure tends, as the
// faces and samples become fine, to a density on the surface: a point P swept
// by the ruling at turning rate |sigma'|, where the radius across the ruling
// is R, holds a pass's pressure p for a time proportional to 1 / (|sigma'| R),
// so the sum becomes
//     x(P) = sum over passes of p(P) / (|sigma'| R(P)),
// the accumulated pressure of contact/continuum_loop_scores.h with the
// geometric width (the template sums peak pressures, not pressure over the
// patch; the Hertz width gives the pressure-time integral instead). With
// p = p_hertz g(lambda), the plane-strain FEM's correction (fem/scenes/slice_scaling.h),
// its normalised variance over the whole surface of area A,
//     fem_sds_continuum = A integral x^2 dA / (integral x dA)^2 - 1,
// is what the template measures without its N^-2: for N faces of equal area
// the template is V / N^2 to leading order. g = 1 gives the line-Hertz value.
// Closed form for the cylinder of radius r and length L (x uniform on the
// side, 0 on the caps): V = A_caps / A_side = r / L.
//
// Resolution: the loop's samples and the Gauss pieces along each ruling;
// `change` is the value against that with every other sample and half the
// pieces. And the FEM table: the caller's, extended to the loop's load ratios
// and refined (doubling its nodes per decade) until its every other node
// changes the value by less than the tolerance, as the face template's
// (loop_sds.h): the value is converged when both changes are below it.
#include "contact/continuum_loop_scores.h"
#include "fem/scenes/slice_scaling.h"
#include "oracle/rolling_study.h"
#include <mpi.h>
#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

namespace rollcheck::study::loop_scores
{
struct ContinuumSds
{
  double line_hertz = 0;  ///< V of x with g = 1
  double fem = 0;         ///< V of x with the FEM's g
  double fem_coarse = 0;  ///< every other sample, half the pieces
  double fem_half_table = 0; ///< every other node of the FEM table
  int nodes_per_decade = 0;  ///< of the table it was scored with
  double tolerance = 0;      ///< relative change that counts as converged
  double load_ratio_min = 0, load_ratio_max = 0;
  /// Whether some point's load ratio lies below the slice table's least, where
  /// g is held at the table's last value (JSON fem_sds_continuum_held_below_table).
  bool below_table = false;
  double change() const { return fem / fem_coarse - 1; }
  double table_change() const { return fem / fem_half_table - 1; }
  bool converged() const { return std::abs(change()) < tolerance && std::abs(table_change()) < tolerance; }
  /// "converged", or "not converged: ..." with both changes.
  std::string status() const;
};

/// When the table is fine enough (loop_sds.h LoopSdsSettings has the same two).
struct ContinuumTableRefinement
{
  double tolerance = 0.01;       ///< relative change that counts as converged
  int max_nodes_per_decade = 64; ///< the refinement stops here
};

/// The continuum line-Hertz and FEM-SDS of the first loop of `run` (the
/// whole scored window if no loop completed) under `settings` (its pressure
/// factor is replaced); collective on `comm`: each rank integrates its part
/// of the loop's samples, and solves its share of the table's new nodes,
/// which it refines as `refinement` says. Every rank gets the result.
ContinuumSds continuum_sds(MPI_Comm comm, const oracle::RealRolling& run, contact::ContinuumLoopSettings settings,
                           fem::SliceScaling& table, const ContinuumTableRefinement& refinement = {});

/// {"line_hertz_sds_continuum", "fem_sds_continuum", "fem_sds_continuum_change",
/// "fem_sds_continuum_table_change", "fem_sds_continuum_status", ...}.
nlohmann::json to_json(const ContinuumSds& continuum);
} // namespace rollcheck::study::loop_scores
