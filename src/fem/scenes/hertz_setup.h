#pragma once
// What a Hertz verification run is given: the model, the body, the load and
// the numerical choices, with the defaults that the penalty and convergence
// studies justify (docs/methods/hertz-fem.md). Also the analytic reference the run
// is compared with, and the mesh sizes derived from it.
#include "fem/mesh/hertz_mesh.h"
#include "fem/mesh/mesh_grading.h"
#include "fem/model.h"
#include <filesystem>
#include <optional>
#include <string>

namespace rollcheck::fem
{
/// How the nodal contact pressure is found: recovered from the nodal contact
/// forces F_i, lumped, F_i / A_i (fem/nodal_fields.h), or consistent, the
/// contact patch's mass-matrix system M p = F (fem/consistent_pressure.h);
/// or read from the penalty's gap at the node (fem/penalty_pressure.h):
/// penalty, kappa <-g_i>_+; touching, the lumped pressure where g_i < 0 and
/// 0 where the node's gap is open.
/// automatic: the model's default for its degree (with_model_defaults).
enum class PressureRecovery
{
  automatic,
  lumped,
  consistent,
  penalty,
  touching
};

/// How the 3D model's contact cap (the sphere's surface within 2 c_H of the
/// axis) is meshed: unstructured, by gmsh's Frontal-Delaunay with the rest;
/// rings, the structured cap whose node rings keep off the Hertz edge
/// (fem/mesh/cap_rings.h, fem/mesh/hertz_mesh.h); automatic: the model's
/// default for its degree (with_model_defaults).
enum class ContactCapMesh
{
  automatic,
  unstructured,
  rings
};

struct HertzSettings
{
  Model model = Model::axisymmetric;
  double radius_m = 0.01;             ///< sphere or cylinder radius R
  double youngs_modulus_pa = 200e9;   ///< steel
  double poisson_ratio = 0.3;         ///< steel
  double force_n = 100.0;             ///< total force on the body
  /// Plane strain: axial length of the cylinder that carries force_n; the
  /// model sees force_n / length_m per unit length. Default 2R: a roller as
  /// long as it is wide.
  double length_m = 0.02;
  /// Lagrange degree of the displacement, 1 or 2; 0: the model's default
  /// (with_model_defaults).
  int degree = 0;
  /// Contact-zone element size h_c = c_H / (10 * 2^(refine / 2)), c_H the
  /// Hertz radius or half-width: refine 0 puts 10 elements across it, each
  /// step adds a factor sqrt(2). Negative: the model's default (default_refine).
  int refine = -1;
  /// kappa = penalty_c * E / h_c. The penalty's own error falls as 1 / c;
  /// the penalty study (README) puts it at a fifth of the mesh's at c = 100.
  double penalty_c = default_penalty_c;
  /// Compare with the two-identical-bodies E* = E / (2 (1 - nu^2)) (the
  /// preprint's choice): the FEM body then gets the modulus E / 2 against the
  /// rigid plane, which is Hertz-equivalent for identical materials.
  bool elastic_plane = false;
  /// 3D: extra refine levels (each a factor sqrt(2) smaller elements than
  /// the contact zone's h_c) in a ball of radius pole_radius c_H about the
  /// first point of contact, and within edge_half_width c_H of the contact's
  /// edge circle r = c_H on the sphere (fem/mesh/hertz_mesh.h); 0: none;
  /// -1: the model's default (with_model_defaults).
  int pole_refine = -1;
  int edge_refine = -1;
  /// 3D: the contact cap's mesh; with rings, the rings are spaced as the
  /// finer of pole_refine's and edge_refine's sizes (fem/mesh/cap_rings.h).
  ContactCapMesh contact_cap = ContactCapMesh::automatic;
  /// Contact-zone element size in m; overrides refine when > 0 (used by the
  /// hard cases: a fixed mesh under a varying load).
  double contact_element_size_m = 0.0;
  double force_rtol = 1e-6;           ///< load control: |F_h - F| / F at the end
  /// Nodal pressure recovery. Lumped: consistent recovery, exact for a
  /// pressure linear over a node's patch, amplifies the nodal forces' own
  /// scatter and is the less accurate on every model's default mesh; in 3D
  /// P1 penalty and touching are the lumped recovery to the digit, and with
  /// P2 penalty overshoots at the vertices while touching helps only where
  /// the edge is refined (docs/methods/hertz-fem.md#pointwise-accuracy-in-3d).
  PressureRecovery pressure_recovery = PressureRecovery::automatic;
  /// Extra PETSc options, e.g. "-hertz_ksp_type gmres"; the solver's prefix is "hertz_".
  std::string petsc_options;
  /// 3D: each load step's Newton iterations keep its first preconditioner
  /// (fem/penalty_contact.h reuse_preconditioner_within_solve).
  bool reuse_preconditioner = true;
  /// Progress lines (meshing, size, load control) at info level; else at debug (-v).
  bool log_progress = true;
  /// If set, the fields of every load step are written there (fem/write_fields.h), the data in a .h5 beside it.
  std::filesystem::path xdmf_path;

  static constexpr double default_penalty_c = 100.0;
};

/// The model's default refine level for a degree: the coarsest level that
/// meets the model's tolerances with a 2x margin (docs/results/hertz.md#convergence-study-speed-against-error);
/// plane strain, within them from level 0, takes the axisymmetric level.
int default_refine(Model model, int degree);

/// The setup with every "model's default" (degree 0, pole_refine and
/// edge_refine -1, the automatic cap and recovery) replaced by the model's
/// choice for its degree; the rest as given. 3D: P2 with the pole and edge
/// refined two levels, the cap's rings and the touching recovery, the
/// cheapest setup whose largest nodal pressure and profile RMS are both within
/// 0.5 % of Hertz (docs/methods/hertz-fem.md#pointwise-accuracy-in-3d); 3D at
/// degree 1 and the 2D models: none of these, the lumped recovery.
HertzSettings with_model_defaults(HertzSettings setup);

/// "auto", "lumped", "consistent", "penalty" or "touching".
std::string recovery_name(PressureRecovery recovery);

/// "auto", "unstructured" or "rings".
std::string contact_cap_name(ContactCapMesh cap);

/// InputError naming the bad field (the model's-default values, degree 0
/// and pole or edge refinement -1, are good); called by solve_hertz.
void validate(const HertzSettings& setup);

/// Hertz theory for the setup, in the model's terms.
struct HertzReference
{
  double effective_modulus_pa;   ///< E* that Hertz uses
  double body_modulus_pa;        ///< the modulus the FEM body gets
  double contact_size_m;         ///< a (point) or b (line)
  double peak_pressure_pa;
  double load;                   ///< F (N) or F / L (N/m)
  std::optional<double> approach_m; ///< point contact only: a^2 / R
  double max_shear_pa;
  double max_shear_depth_m;
  double max_von_mises_pa;
  double max_von_mises_depth_m;
};
HertzReference hertz_reference(const HertzSettings& setup);

MeshGrading mesh_grading(const HertzSettings& setup, const HertzReference& reference);

/// The 3D contact's pole and edge refinement (pole_refine, edge_refine) for
/// the grading, and the structured cap's rings (contact_cap); none in 2D.
ContactRefinement contact_refinement(const HertzSettings& setup, const HertzReference& reference,
                                     const MeshGrading& grading);

} // namespace rollcheck::fem
