#pragma once
// The body's own sections across its contact ruling, each in plane strain
// at a prescribed approach: how much line load a section carries when the
// held cut through the centre of mass moves down by delta there (the
// sections' share rule, study/whole_body/section_share.h).
//
// A section at station a is the mapped reference segment of the whole body
// (fem/mesh/whole_body_mesh.h build_mapped_section_mesh), one layer thick with
// u_x = 0 on both faces, its cut z = z_G moved rigidly down by delta against
// the rigid frictionless plane, the exact sheet in the initial gap, the
// penalty kappa = c E / h_c of the whole body: the whole body's section
// without its neighbours, meshed as the whole body's interior (the sizes
// passed; the whole body's end refinement near the contact line is not
// needed for a section's load). Its line load is the top face's reaction over the
// layer's thickness. Displacement control needs one Newton solve per
// approach. The sections are independent problems, so the ranks share them
// out (fem/share_out.h).
#include "fem/mesh/whole_body_mesh.h"
#include <cstdint>
#include <mpi.h>
#include <span>
#include <string>
#include <vector>

namespace rollcheck::fem
{
struct SectionSettings
{
  double youngs_modulus_pa = 200e9; ///< steel (the preprint's)
  double poisson_ratio = 0.3;       ///< steel (the preprint's)
  double penalty_c = 100.0;         ///< kappa = c E / h_c (the whole body's and the slices' c)
  /// The body starts shifted down by this (PenaltyContact::start_translated:
  /// the sheet's height at the contact's edge, b^2 / (2 R)).
  double first_shift_m = 0;
  std::string petsc_options = "-hertz_ksp_type preonly -hertz_pc_type lu -hertz_pc_factor_mat_solver_type mumps";
};

struct SectionFem
{
  double station_m = 0;
  double approach_m = 0;          ///< delta, prescribed
  double load_n_per_m = 0;        ///< q the section carries
  double peak_pressure_pa = 0;    ///< largest nodal pressure
  std::int64_t dofs = 0;
  int newton_iterations = 0;
  double wall_s = 0;              ///< mesh and solve, on the rank that solved it
};

/// Section i at stations_m[i] pressed by approaches_m[i] (the two spans as
/// long); `sizes` as the whole body's (its contact_m the layer's thickness
/// too). Every rank gets every result. InputError for spans of different
/// lengths, an approach <= 0 or a station off the ruling; ComputationError
/// on every rank when a solve fails on any.
std::vector<SectionFem> solve_sections(MPI_Comm comm, const MappedBodyPose& pose, std::span<const double> stations_m,
                                       std::span<const double> approaches_m, const WholeBodySizes& sizes,
                                       const SectionSettings& settings);
} // namespace rollcheck::fem
