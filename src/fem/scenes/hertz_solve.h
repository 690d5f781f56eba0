#pragma once
// One Hertz verification run: mesh the scene, reach the force by load
// control, recover pressure and stress, and measure them against Hertz.
#include "fem/contact_measures.h"
#include "fem/scenes/hertz_setup.h"
#include <cstdint>
#include <mpi.h>
#include <string>
#include <vector>

namespace rollcheck::fem
{
struct HertzResult
{
  HertzSettings setup;
  HertzReference hertz;
  MeshGrading grading;

  // Contact, measured (point: a; line: b).
  double contact_size_m = 0;        ///< from the Hertz-form fit of the nodal pressure
  double contact_edge_m = 0;        ///< outermost zero of the nodal gap
  double peak_pressure_pa = 0;      ///< p0 of the Hertz-form fit (contact_measures.h)
  double max_nodal_pressure_pa = 0; ///< largest nodal pressure
  double load_reaction = 0;         ///< N (point) or N/m (line), at the loaded face
  double load_contact = 0;          ///< the same from the integrated contact pressure
  double approach_m = 0;            ///< prescribed displacement of the loaded face
  DepthMaximum max_shear;           ///< (sigma_1 - sigma_3) / 2 on the axis
  DepthMaximum max_von_mises;
  std::vector<SurfaceNode> profile; ///< contact-surface nodes with s < 1.5 c_H, by s
  double profile_rms_error = 0;     ///< RMS of (p - p_Hertz(s)) / p0_Hertz over `profile`
  double profile_rms_error_interior = 0; ///< the same over the nodes of `profile` with s < 0.9 c_H
  int touching_nodes = 0;           ///< contact-surface nodes with a negative gap
  double elements_across_contact = 0; ///< c_H / h_c
  /// Estimated relative error of the contact size due to the penalty alone
  /// and due to the mesh alone (docs/results/hertz.md#penalty-study-error-against-c-at-fixed-mesh).
  double penalty_error_estimate = 0;
  double discretisation_error_estimate = 0;
  std::vector<std::string> flags;   ///< see docs/methods/hertz-fem.md#flags-and-hard-cases-each-a-test-in-testsfemtest_hertz_axisymmetriccpp

  // Cost.
  std::int64_t dofs = 0;
  std::int64_t cells = 0;
  int ranks = 1;
  int load_steps = 0;
  int newton_iterations = 0;
  int krylov_iterations = 0;
  int preconditioner_setups = 0;
  double mesh_s = 0, assembly_s = 0, solve_s = 0, postprocess_s = 0, wall_s = 0;
  double peak_memory_mb = 0;        ///< largest resident set of one rank
  double total_peak_memory_mb = 0;  ///< summed over ranks
};

/// Runs the setup on `comm` (every rank calls it and gets the same result).
/// InputError for a bad setup, ComputationError for a failed solve or a
/// contact that the mesh does not resolve (fewer than two touching nodes).
HertzResult solve_hertz(MPI_Comm comm, const HertzSettings& setup);

/// Relative error (fem - reference) / reference.
inline double relative_error(double fem, double reference) { return (fem - reference) / reference; }
} // namespace rollcheck::fem
