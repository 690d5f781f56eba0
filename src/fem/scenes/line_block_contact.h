#pragma once
// Line Hertz between two elastic bodies by FEM: the check of the node-to-node
// penalty formulation (fem/penalty_contact.h NodePair) that the rim scene's
// steel counter-face uses. Two like bodies (the preprint's steel on steel)
// meet along a flat interface meshed as twins (fem/mesh/scene_mesh.h
// build_line_block_mesh); the upper body's cylindrical profile of radius R
// lies in the pairs' initial gap, x^2 / (2 R) (half-space theory's
// profile), and the load q per unit length presses them together. Line
// Hertz (K. L. Johnson, "Contact Mechanics", 1985, sec. 4.2) with
// E* = E / (2 (1 - nu^2)) gives b = sqrt(4 q R / (pi E*)) and
// p0 = sqrt(q E* / (pi R)); the FEM's are the Hertz-form fit of the pair
// pressures (fem/contact_measures.h fit_hertz_profile).
#include <cstdint>
#include <mpi.h>

namespace rollcheck::fem
{
struct LineBlockSettings
{
  double radius_m = 0.01;           ///< R: the Hertz scenes' 10 mm cylinder
  double load_n_per_m = 1e4;        ///< q: the preprint's 100 N over 10 mm
  double youngs_modulus_pa = 200e9; ///< steel (the preprint's), both bodies
  double poisson_ratio = 0.3;       ///< steel (the preprint's), both bodies
  double size_over_half_width = 50; ///< each body's width and height, in b
  int contact_elements = 20;        ///< across b
  double penalty_c = 10.0;          ///< kappa = c E / h_c
};

struct LineBlockResult
{
  double half_width_m = 0, peak_pressure_pa = 0;             ///< the FEM's, Hertz-form fit
  double hertz_half_width_m = 0, hertz_peak_pressure_pa = 0; ///< line Hertz
  double force_n_per_m = 0;                                  ///< the top's reaction reached
  int pairs = 0;
  std::int64_t dofs = 0;
  double wall_s = 0;
};

/// Collective over `comm` (pairs across processes); every process gets the result.
LineBlockResult solve_line_block(MPI_Comm comm, const LineBlockSettings& settings);
} // namespace rollcheck::fem
