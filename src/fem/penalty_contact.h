#pragma once
// The discrete penalty-contact problem of one scene: displacement field,
// Dirichlet conditions (symmetry planes, prescribed approach of the top face),
// and a semismooth Newton solver with an energy line search.
//
// Newton: the penalty term <-g>_+ is piecewise linear, so within one set of
// penetrating quadrature points the problem is linear and Newton ends with
// the step after which that set stops changing: the residual is then the
// linear solve's own (below 1e-8 of the solve's largest), or the next
// Newton increment is (below 1e-10 of the displacement, or ten times an
// iterative linear solve's rtol where that is looser: taken whole, without
// the line search, whose test is round-off at that size). The total energy is
// convex, and a larger step that raises it is halved (Armijo backtracking on
// the energy), which makes the iteration globally convergent. Every linear solve's KSPConvergedReason
// is checked: a diverged solve raises ComputationError, never a result.
//
// Linear solver: KSP with options prefix "hertz_". Defaults, overridable by
// PETSC_OPTIONS or HertzSettings::petsc_options (fem/solver_defaults.h): 2D
// MUMPS LU; 3D GMRES (rtol 1e-10) with GAMG on an aij matrix with the
// rigid-body near-nullspace, or, once node pairs join two bodies, with hypre
// BoomerAMG (set_node_pairs); MUMPS LU where the scene prefers it up to a
// size (prefer_direct_solver). An iterative solve stops at the larger of
// rtol times its own initial residual and min(rtol, 1e-10) times the largest
// initial residual of the problem's solves so far (a given -hertz_ksp_atol
// replaces the latter): a Newton correction, or a load step's small change of
// approach, is resolved to the Newton increment's 1e-10 of the load's scale
// rather than to rtol of its own, already small, right-hand side.
#include "fem/contact_forms.h"
#include "fem/lumped_projection.h"
#include "fem/mesh/scene_mesh.h"
#include "fem/node_pairs.h"
#include <dolfinx/fem/Constant.h>
#include <dolfinx/fem/DirichletBC.h>
#include <dolfinx/fem/Form.h>
#include <dolfinx/fem/Function.h>
#include <dolfinx/fem/FunctionSpace.h>
#include <dolfinx/la/Vector.h>
#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <utility>
#include <vector>
#include <petscksp.h>

namespace rollcheck::fem
{
struct NewtonReport
{
  int newton_iterations = 0;
  int krylov_iterations = 0;
  int preconditioner_setups = 0; ///< linear solves that built their preconditioner afresh
  int line_search_halvings = 0;
  double final_relative_increment = 0;
  double assembly_s = 0;
  double solve_s = 0;
};

/// A pair's place and state, as gathered from every process.
struct PairPressure
{
  std::array<double, 3> x;
  double pressure_pa, area_m2, initial_gap_m;
};

class PenaltyContact;

/// The node pairs of fem/node_pairs.h (interface_node_pairs) of the
/// problem: its displacement space's nodes, their contact area (the lumped
/// contact-surface weight, fem/lumped_projection.h) and the scene's contact
/// facets. Collective.
std::vector<NodePair> interface_node_pairs(const PenaltyContact& problem, double tol,
                                           const std::function<double(const double* x)>& initial_gap,
                                           const std::function<bool(const double* x)>& mortar_zone = {});

/// Every process's pairs (position, pressure at the current state, area,
/// initial gap), on every process in rank order. Collective.
std::vector<PairPressure> gather_pair_pressures(const PenaltyContact& problem);

class PenaltyContact
{
public:
  using T = double;
  PenaltyContact(const SceneMesh& scene, Model model, int degree, double body_modulus_pa, double poisson_ratio,
                 double penalty_stiffness_pa_per_m, const std::string& petsc_options);
  ~PenaltyContact();
  PenaltyContact(const PenaltyContact&) = delete;
  PenaltyContact& operator=(const PenaltyContact&) = delete;

  /// Start state for a first solve: the body translated down by `shift_m`,
  /// its top face at -approach_m.
  void start_translated(double shift_m, double approach_m);
  /// Start state from a state solved on another mesh of the same scene
  /// (fem/interpolate_between_meshes.h; `part` tells two bodies' cells
  /// apart), the top face at -approach_m.
  void start_interpolated(const dolfinx::fem::Function<T>& solved, double approach_m,
                          const std::function<int(const double* midpoint)>& part = {});
  /// Sets the top face's prescribed displacement to -approach_m (times the
  /// profile's weight) and nothing else: the first Newton step then is the tangent (Euler) predictor, the
  /// linear response of the current state to the change of approach.
  void set_approach(double approach_m);
  double approach_m() const { return _approach_m; }
  /// The top face's vertical displacement becomes -approach_m * weight(x) at
  /// each of its nodes (1 before this is called): a top face that follows a
  /// prescribed profile, e.g. the approaches of plane-strain slices along a
  /// ruling (fem/scenes/slab_contact.h). Applies from the next set_approach.
  void set_approach_profile(const std::function<double(const double* x)>& weight);

  /// The penalty stiffness becomes penalty_stiffness * scale(x) in the cell
  /// whose midpoint is x (1 before this is called): graded with the mesh, the
  /// penalty stays as stiff against its elements where they are small.
  void set_penalty_scale(const std::function<double(const double* x)>& scale);

  /// The gap to the plane becomes z + u_z + gap(x) (0 before this is
  /// called): a surface the mesh carries flattened onto z = 0.
  void set_initial_gap(const std::function<double(const double* x)>& gap);

  /// Contact between two bodies by node pairs (fem/node_pair.h), besides (or instead of: set
  /// the penalty scale to 0) the rigid plane's; each process passes the
  /// pairs whose upper node it owns. Collective. The lower blocks another
  /// process owns become extra ghosts of the pairs' index map (their
  /// displacements come by a forward scatter, their forces go back by a
  /// reverse one), and the Jacobian's sparsity is rebuilt to hold the pairs
  /// (off-process rows are sent to their owners at assembly).
  void set_node_pairs(std::vector<NodePair> pairs);
  /// MUMPS LU instead of the 3D iterative default while the problem has at
  /// most `max_dofs` unknowns (fem/solver_defaults.h
  /// use_direct_solver_default: a given -hertz_ksp_type or -hertz_pc_type
  /// wins). For scenes whose strongly graded meshes cost GAMG more than the
  /// factorisation costs LU.
  void prefer_direct_solver(std::int64_t max_dofs);
  /// Within each solve() the preconditioner of its first Newton iteration
  /// serves the later ones (an iterative solver only, and unless
  /// -hertz_ksp_reuse_preconditioner is given), until a solve takes more
  /// than twice that first solve's Krylov iterations or gives up (that one
  /// is solved again with a fresh preconditioner): the set of penetrating
  /// points, and so the Jacobian, changes little within one approach on the
  /// hemisphere, but enough on a steel block's node pairs to multiply
  /// BoomerAMG's iterations (measured in docs/methods/hertz-fem.md).
  void reuse_preconditioner_within_solve(bool reuse) { _reuse_within_solve = reuse; }
  /// This process's pairs, as set.
  const std::vector<NodePair>& node_pairs() const { return _pairs; }
  /// p = kappa <-g>_+ of each of this process's pairs at the current state.
  std::vector<double> pair_pressures_pa() const;

  /// Newton to convergence at the current approach; throws ComputationError
  /// on a diverged linear solve or when Newton does not converge.
  NewtonReport solve();

  /// Total force on the whole body (symmetry multiplicity applied), from the
  /// integrated contact pressure and from the reaction at the top face.
  double contact_force_n() const;
  double reaction_force_n() const;

  const ContactForms& forms() const { return _forms; }
  std::shared_ptr<const dolfinx::fem::Function<T>> displacement() const { return _u; }
  std::shared_ptr<const dolfinx::mesh::Mesh> mesh() const { return _scene.mesh; }
  const SceneMesh& scene() const { return _scene; }
  /// Coordinates (x, y, z) of each local dof block.
  const std::vector<double>& dof_coordinates() const { return _dof_coordinates; }
  std::int64_t num_dofs() const;
  /// Coefficients of the forms (displacement, penalty scale, initial gap), by their UFL names.
  const std::map<std::string, std::shared_ptr<const dolfinx::fem::Function<T>>>& coefficients() const
  {
    return _coefficients;
  }
  /// Constants shared by all forms of this model/degree, by their UFL names.
  const std::map<std::string, std::shared_ptr<const dolfinx::fem::Constant<T>>>& constants() const
  {
    return _constants;
  }
  const std::map<dolfinx::fem::IntegralType, const dolfinx::mesh::MeshTags<int>*>& subdomains() const
  {
    return _subdomains;
  }
  /// The forms and what they are bound to (mesh, coefficients, constants,
  /// subdomains), for forms assembled beside the problem's own.
  FormBindings form_bindings() const { return {_forms, _scene.mesh, _coefficients, _constants, _subdomains}; }

private:
  void assemble_residual(dolfinx::la::Vector<T>& b) const;
  /// Adds the pairs' forces (the residual's part) to b, on _pair_map.
  void add_pair_forces(std::span<T> b) const;
  void assemble_jacobian();
  double energy() const;

  SceneMesh _scene;
  ContactForms _forms;
  std::shared_ptr<dolfinx::fem::FunctionSpace> _V;
  std::shared_ptr<dolfinx::fem::Function<T>> _u;
  std::shared_ptr<dolfinx::fem::Function<T>> _penalty_scale; ///< DG0
  std::shared_ptr<dolfinx::fem::Function<T>> _initial_gap;   ///< P1
  std::vector<NodePair> _pairs;
  /// The space's owned blocks and ghosts, then the pairs' blocks owned elsewhere
  /// (the space's own map while there are no pairs).
  std::shared_ptr<const dolfinx::common::IndexMap> _pair_map;
  /// A pair's local blocks of _pair_map: the upper side's, then the lower
  /// side's, each with dg / du_z (a_k, then -w_j).
  struct PairBlocks
  {
    std::vector<std::int32_t> block;
    std::vector<double> slope;
  };
  std::vector<PairBlocks> _pair_blocks;          ///< local blocks of _pair_map, per pair
  mutable std::unique_ptr<dolfinx::la::Vector<T>> _pair_u; ///< u on _pair_map
  std::vector<double> _dof_coordinates;
  std::map<std::string, std::shared_ptr<const dolfinx::fem::Function<T>>> _coefficients;
  std::shared_ptr<dolfinx::fem::Function<T>> _top_displacement; ///< the top face's prescribed values
  std::vector<std::int32_t> _top_blocks;  ///< owned and ghost
  std::vector<double> _top_weights;       ///< per top block, see set_approach_profile
  double _approach_m = 0;
  std::map<std::string, std::shared_ptr<const dolfinx::fem::Constant<T>>> _constants;
  std::shared_ptr<dolfinx::mesh::MeshTags<int>> _contact_tags;
  std::map<dolfinx::fem::IntegralType, const dolfinx::mesh::MeshTags<int>*> _subdomains;
  std::shared_ptr<dolfinx::fem::Form<T>> _residual, _jacobian, _energy, _contact_force;
  std::vector<std::shared_ptr<const dolfinx::fem::DirichletBC<T>>> _bcs;
  std::vector<std::int32_t> _top_z_dofs; ///< owned, unrolled
  int _z_component;
  Model _model;
  bool _reuse_within_solve = false;
  /// The largest initial residual of this problem's Krylov solves so far
  /// (their convergence test's norm): the load's scale that solve() stops them at.
  double _largest_initial_residual = 0;
  Mat _A = nullptr;
  KSP _ksp = nullptr;
  MatNullSpace _near_nullspace = nullptr;
  std::vector<std::string> _inserted_options; ///< from petsc_options, cleared at destruction
};
} // namespace rollcheck::fem
