#pragma once
// The discrete penalty-contact problem of one scene: displacement field,
// Dirichlet conditions (symmetry planes, prescribed approach of the top face),
// and a semismooth Newton solver with an energy line search.
//
// Newton: the penalty term <-g>_+ is piecewise linear, so within one set of
// penetrating quadrature points the problem is linear and Newton ends one
// step after that set stops changing. The total energy is convex, and a step
// that raises it is halved (Armijo backtracking on the energy), which makes
// the iteration globally convergent. Every linear solve's KSPConvergedReason
// is checked: a diverged solve raises ComputationError, never a result.
//
// Linear solver: KSP with options prefix "hertz_". Defaults, overridable by
// PETSC_OPTIONS or HertzSettings::petsc_options: 2D MUMPS LU; 3D GMRES (rtol
// 1e-10) with GAMG on an aij matrix with the rigid-body near-nullspace.
#include "fem/contact_forms.h"
#include "fem/scene_mesh.h"
#include <dolfinx/fem/Constant.h>
#include <dolfinx/fem/DirichletBC.h>
#include <dolfinx/fem/Form.h>
#include <dolfinx/fem/Function.h>
#include <dolfinx/fem/FunctionSpace.h>
#include <dolfinx/la/Vector.h>
#include <functional>
#include <petscksp.h>

namespace rollcheck::fem
{
struct NewtonReport
{
  int newton_iterations = 0;
  int krylov_iterations = 0;
  int line_search_halvings = 0;
  double final_relative_increment = 0;
  double assembly_s = 0;
  double solve_s = 0;
};

/// Frictionless contact between two elastic bodies meshed together, node to
/// node: a node of the upper body's contact face and its twin of the lower
/// body's at the same place (the mesh carries the interface flattened, the
/// bodies' profile in `initial_gap_m`). Gap g = g0 + u_z(upper) - u_z(lower),
/// pressure p = kappa <-g>_+, the force p A on each, opposite
/// (P. Wriggers, Computational Contact Mechanics, 2nd ed., 2006, sec. 4.1:
/// the node-to-node penalty, exact for matching meshes and small slip).
struct NodePair
{
  std::int32_t upper, lower;     ///< local dof blocks (one process)
  double area_m2;                ///< the upper node's lumped contact area
  double initial_gap_m;          ///< g0
  double stiffness_pa_per_m;     ///< kappa
};

class PenaltyContact;

/// The upper body's interface nodes (those with contact area: on its contact
/// facets, at height 0) paired with their twins of the lower body at the
/// same place (coordinates equal to `tol`); gaps and stiffnesses are left
/// for the caller. ComputationError where a contact node has no twin.
std::vector<NodePair> interface_node_pairs(const PenaltyContact& problem, double tol);

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
  /// Sets the top face's prescribed displacement to -approach_m (times the
  /// profile's weight) and nothing else: the first Newton step then is the tangent (Euler) predictor, the
  /// linear response of the current state to the change of approach.
  void set_approach(double approach_m);
  double approach_m() const { return _approach_m; }
  /// The top face's vertical displacement becomes -approach_m * weight(x) at
  /// each of its nodes (1 before this is called): a top face that follows a
  /// prescribed profile, e.g. the approaches of plane-strain slices along a
  /// ruling (fem/slab_contact.h). Applies from the next set_approach.
  void set_approach_profile(const std::function<double(const double* x)>& weight);

  /// The penalty stiffness becomes penalty_stiffness * scale(x) in the cell
  /// whose midpoint is x (1 before this is called): graded with the mesh, the
  /// penalty stays as stiff against its elements where they are small.
  void set_penalty_scale(const std::function<double(const double* x)>& scale);

  /// The gap to the plane becomes z + u_z + gap(x) (0 before this is
  /// called): a surface the mesh carries flattened onto z = 0.
  void set_initial_gap(const std::function<double(const double* x)>& gap);

  /// Contact between two bodies by node pairs, besides (or instead of: set
  /// the penalty scale to 0) the rigid plane's. The Jacobian's sparsity is
  /// rebuilt to hold the pairs. One process only (the twins must both be local).
  void set_node_pairs(std::vector<NodePair> pairs);
  /// p = kappa <-g>_+ of each pair at the current state.
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

private:
  void assemble_residual(dolfinx::la::Vector<T>& b) const;
  void assemble_jacobian();
  double energy() const;

  SceneMesh _scene;
  ContactForms _forms;
  std::shared_ptr<dolfinx::fem::FunctionSpace> _V;
  std::shared_ptr<dolfinx::fem::Function<T>> _u;
  std::shared_ptr<dolfinx::fem::Function<T>> _penalty_scale; ///< DG0
  std::shared_ptr<dolfinx::fem::Function<T>> _initial_gap;   ///< P1
  std::vector<NodePair> _pairs;
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
  Mat _A = nullptr;
  KSP _ksp = nullptr;
  MatNullSpace _near_nullspace = nullptr;
  std::vector<std::string> _inserted_options; ///< from petsc_options, cleared at destruction
};
} // namespace rollcheck::fem
