#pragma once
// The whole body (fem/mesh/whole_body_mesh.h) pressed onto the rigid frictionless
// plane z = 0 by the normal force F along the vertical through its centre of
// mass, as the preprint loads it (the whole-body check, study/whole_body).
//
// Load and rigid-body modes: the body's section z = z_G through the centre
// of mass is moved rigidly (fem/penalty_contact.h top face, every component
// prescribed): no horizontal motion, a vertical approach delta and a tilt t
// about the horizontal line across the ruling through the centre of mass's
// foot x_G,
//   u_z = -delta (1 + tau (x - x_G) / L),   t = delta tau / L,
// and no rotation about the ruling (a line contact carries no moment about
// its own line: the body would roll). Load control sets delta and tau until
// the contact force is F and its centre of pressure x_c lies at x_G, so that
// force and moment about the centre of mass balance and the load's line of
// action is the vertical through G. Updates: delta by the secant on
// log F - log delta (fem/load_control.h), tau by the secant on x_c - tau,
// started from x_c - x_G = n tau L / 12 (a uniform line load whose load
// follows the approach to the power n).
//
// Reading: the nodal contact pressure (fem/nodal_fields.h) on each node plane
// x = const of the structured mesh: its largest value (the peak across the
// ruling), the line load q = sum p_i A_i / dx (A_i the node's tributary
// area, dx the plane's tributary length), and at both end planes the mean
// pressure of the sheet's nodes (WholeBodyMesh::on_sheet) with |y| <=
// edge_half_width (the end model's edge pressure, fem/scenes/rim_end_contact.h: its
// nodes on the edge with y <= b / 2).
#include "fem/mesh/whole_body_mesh.h"
#include <array>
#include <cstdint>
#include <mpi.h>
#include <string>
#include <vector>

namespace rollcheck::fem
{
struct WholeBodyLoad
{
  double force_n = 100;               ///< F (the preprint's)
  double centre_of_mass_along_m = 0;  ///< x_G, the foot of the centre of mass on the ruling
  double youngs_modulus_pa = 200e9;   ///< steel (the preprint's)
  double poisson_ratio = 0.3;         ///< steel (the preprint's)
  /// kappa = c E / h_c with h_c the contact strip's element size (the
  /// slices' and the slab's c = 100).
  double penalty_c = 100.0;
  double contact_element_m = 0;       ///< h_c
  double first_approach_m = 0;        ///< delta of the first solve (the line-contact estimate)
  double first_shift_m = 0;           ///< the body's start translation (PenaltyContact::start_translated)
  double approach_exponent = 1.1;     ///< n_0 of F ~ delta^n
  double force_rtol = 1e-4;           ///< |F_h / F - 1|
  double centre_rtol = 1e-4;          ///< |x_c - x_G| / L
  double edge_half_width_m = 0;       ///< the end planes' nodes with |y| <= this give the edge pressure
  /// Prefix "hertz_". MUMPS LU: the layers are thousands of times longer
  /// than the strip's elements are wide (the slab's experience with GAMG).
  std::string petsc_options = "-hertz_ksp_type preonly -hertz_pc_type lu -hertz_pc_factor_mat_solver_type mumps";
};

struct WholeBodyFem
{
  std::vector<double> plane_x_m;              ///< node planes along the ruling
  std::vector<double> plane_peak_pa;          ///< largest nodal pressure in each
  std::vector<double> plane_load_n_per_m;     ///< q in each
  std::array<double, 2> edge_pressure_pa{};   ///< at x = 0 and x = L
  double force_n = 0;                         ///< contact force (integrated pressure)
  double reaction_n = 0;                      ///< at the rigid section
  double centre_of_pressure_m = 0;            ///< x_c
  double approach_m = 0, tilt_rad = 0;
  std::int64_t dofs = 0;
  int load_steps = 0, newton_iterations = 0, krylov_iterations = 0;
  double solve_s = 0;                         ///< load control and reading
};

/// Every rank gets the result. ComputationError for a failed solve or load
/// control that does not converge in 30 solves; InputError for bad settings.
WholeBodyFem solve_whole_body(MPI_Comm comm, const WholeBodyMesh& mesh, const WholeBodyLoad& load);

/// Piecewise-linear interpolation through (xs, ys) (xs increasing),
/// constant beyond the first and last points.
double interpolate_planes(const std::vector<double>& xs, const std::vector<double>& ys, double x);
} // namespace rollcheck::fem
