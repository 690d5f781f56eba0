#pragma once
// A crease inside the contact, by FEM: the crease scene (fem/mesh/scene_mesh.h
// build_crease_mesh) pressed onto the rigid plane in plane strain, at several
// mesh levels. Where a body stands on an edge (the rigid-body oracle's rim
// points, contact/contact_locus.h) the contact straddles the crease and the
// surface slope jumps by 2 tan(beta) inside it. Half-space theory for the
// blunt wedge (K. L. Johnson, "Contact Mechanics", CUP 1985, sec. 5.8), with
// P the load per unit length and E* the plane-strain modulus:
//   a = P / (E* tan(beta)),   p(x) = (E* tan(beta) / pi) arccosh(a / |x|),
// a logarithmic singularity at the apex. The FEM apex pressure (a nodal
// average over the elements at the apex) therefore grows by
// (E* tan(beta) / pi) ln(h / h') when the contact element size falls from h
// to h', without bound, while the pressure at a fixed x inside the contact
// converges to p(x): a mesh-dependent peak that must not be reported as a
// converged number.
#include <cstdint>
#include <mpi.h>
#include <numbers>
#include <string>
#include <vector>

namespace rollcheck::fem
{
struct CreaseSettings
{
  /// beta: a blunt crease, where half-space theory holds (tan beta << 1).
  double face_angle_rad = 5 * std::numbers::pi / 180;
  /// P: the preprint's F = 100 N over a 10 mm length of crease.
  double load_n_per_m = 1e4;
  double width_m = 0.01;            ///< W; the height H is the same
  double youngs_modulus_pa = 200e9; ///< steel (the preprint's)
  double poisson_ratio = 0.3;       ///< steel (the preprint's)
  double penalty_c = 100.0;         ///< kappa = c E / h_c, as the Hertz scenes
  int refine = 0;                   ///< first level: h_c = a / (10 2^(refine / 2))
  int levels = 3;                   ///< refine, refine + 1, ...
  std::string petsc_options;        ///< prefix "hertz_" (default MUMPS LU)
};

struct CreaseLevel
{
  int refine = 0;
  double contact_element_m = 0;       ///< h_c
  double apex_pressure_pa = 0;        ///< nodal pressure at the apex
  double half_contact_pressure_pa = 0; ///< at x = a / 2 (theory's a), interpolated between nodes
  double contact_edge_m = 0;          ///< outermost node with pressure
  std::int64_t dofs = 0;
  int newton_iterations = 0;
  int krylov_iterations = 0;
  double wall_s = 0;
};

struct CreaseStudy
{
  CreaseSettings setup;
  double effective_modulus_pa = 0;   ///< E / (1 - nu^2)
  double half_width_m = 0;           ///< a
  double half_contact_pressure_pa = 0; ///< p(a / 2) = (E* tan beta / pi) arccosh 2
  /// (E* tan beta / pi) ln sqrt 2: the apex pressure's growth per level (h / sqrt 2).
  double apex_growth_per_level_pa = 0;
  std::vector<CreaseLevel> levels;
};

/// Every rank gets the study. InputError for a bad setup, ComputationError
/// for a failed solve.
CreaseStudy solve_crease(MPI_Comm comm, const CreaseSettings& setup);
} // namespace rollcheck::fem
