#pragma once
// Plane-strain FEM of a line contact, slice by slice: each slice ds of a
// contact ruling is the plane-strain problem of a cylinder of the slice's
// radius R(s) pressed onto the rigid plane by its line load q(s) (the slicing
// of contact/line_contact.h), solved by the penalty-contact Hertz solver
// (fem/scenes/hertz_solve.h, model plane_strain, per unit length) twice: at the
// settings' refinement level and one level finer, whose change estimates the
// discretisation error of the peak pressure. The slices are independent
// problems, so the ranks of `comm` share them out, each solving its slices on
// its own (MPI_COMM_SELF).
#include "core/refinement_series.h"
#include <cstdint>
#include <mpi.h>
#include <span>
#include <string>
#include <vector>

namespace rollcheck::fem
{
struct SliceLoad
{
  double position_m = 0;     ///< along the ruling, from its start
  double radius_m = 0;       ///< R(s)
  double load_n_per_m = 0;   ///< q(s); a slice without load is not solved
};

struct SliceSettings
{
  double youngs_modulus_pa = 200e9; ///< steel (the preprint's)
  double poisson_ratio = 0.3;       ///< steel (the preprint's)
  int refine = -1;                  ///< HertzSettings::refine; -1: the plane-strain default
  double penalty_c = 100.0;         ///< HertzSettings::penalty_c
  bool elastic_plane = false;       ///< HertzSettings::elastic_plane (the preprint's E*)
  std::string petsc_options;
};

struct SliceFem
{
  SliceLoad load;
  double peak_pressure_pa = 0;          ///< largest nodal pressure, at the settings' level
  double refined_peak_pressure_pa = 0;  ///< the same one level finer
  double half_width_m = 0;              ///< b of the Hertz-form fit, at the settings' level
  double hertz_peak_pressure_pa = 0;    ///< sqrt(q E* / (pi R))
  double hertz_half_width_m = 0;        ///< sqrt(4 q R / (pi E*))
  double approach_m = 0;                ///< of the slice's top (height R) at q, at the settings' level
  std::int64_t dofs = 0;                ///< at the settings' level
  std::int64_t refined_dofs = 0;
  int newton_iterations = 0;            ///< both levels
  int krylov_iterations = 0;            ///< both levels
  double wall_s = 0;                    ///< both levels, on the rank that solved it
  /// Relative change of the peak pressure from the settings' level to the finer one (0 without a peak).
  double refinement_change() const
  {
    return peak_pressure_pa > 0 ? relative_change(peak_pressure_pa, refined_peak_pressure_pa) : 0;
  }
};

/// Every rank gets every slice's result. ComputationError on every rank when
/// a solve fails on any.
std::vector<SliceFem> solve_slices(MPI_Comm comm, std::span<const SliceLoad> slices, const SliceSettings& settings);

/// One slice's recovered stress (fem/nodal_fields.h) where the subsurface
/// extrema of line contact lie (contact/subsurface_line_contact.h), against
/// the Hertz p0 and b of the load the slice carries (its reaction):
///  - the largest in-plane principal shear near (0, 0.786 b) and its depth;
///  - the orthogonal shear |tau_xz| at its extremum near (0.87 b, 0.5 b);
/// each at the stationary point of a least-squares cubic in (x, z) through
/// the nodes within 0.15 b of that point (the shear's nodes mirrored about
/// the axis).
struct SliceSubsurface
{
  int refine = 0;
  double elements_across_b = 0;         ///< b / h_c
  double load_n_per_m = 0;              ///< reaction
  double hertz_half_width_m = 0, hertz_peak_pressure_pa = 0; ///< at the reaction
  double max_shear_pa = 0, max_shear_depth_m = 0;
  double orthogonal_shear_pa = 0, orthogonal_shear_depth_m = 0, orthogonal_shear_offset_m = 0;
  std::int64_t dofs = 0;
  double wall_s = 0;
};

/// The slice of `load` at contact-zone refinement `refine` (HertzSettings::refine)
/// with Lagrange elements of `degree` (1 or 2),
/// solved on this process alone. ComputationError for a failed solve or a
/// fit without enough nodes.
SliceSubsurface solve_slice_subsurface(const SliceLoad& load, const SliceSettings& settings, int refine, int degree);
} // namespace rollcheck::fem
