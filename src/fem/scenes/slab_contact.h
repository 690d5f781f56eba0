#pragma once
// The fuller model behind the plane-strain slices of a line contact
// (fem/scenes/slice_contact.h): the 3D slab of the contact ruling (fem/mesh/slab_mesh.h
// build_slab_mesh), whose sections across the ruling are the slices' quarter
// discs of radius R(x), pressed onto the rigid plane with its top face (height
// R(x)) following the slices' own approaches, linear between slice centres
// and extrapolated linearly to the ends, and scaled by load control until the
// slab carries the slices' total force. Where the slices are right (plane
// strain: no shear transfer between neighbouring sections), the slab's peak
// pressure in the section of each slice equals the slice's, and the approach
// factor is 1.
//
// The slab also holds what slices cannot: the ends of the ruling, where the
// curved surface meets the free end face at a right-angled edge (the
// cylinder's rim). Against a rigid frictionless plane that edge is not
// singular: mirrored in the plane, the contact face becomes a plane of
// symmetry and the right-angled corner a straight free boundary, and a
// free-free wedge of angle 2 theta is singular only for 2 theta > pi (M. L.
// Williams, J. Appl. Mech. 19, 1952). The free end face makes the end more
// compliant, so the pressure falls towards it. The singular end pressure of
// a flat-ended roller (T. A. Harris, M. N. Kotzalas, "Rolling Bearing
// Analysis", 5th ed., 2007, ch. 6) needs an elastic counter-face, which the
// rigid-plane model does not have. An end face that overhangs by t > 0
// (an obtuse edge of 90 deg + t, fem/mesh/slab_mesh.h) mirrors into a re-entrant
// free-free wedge of 180 deg + 2 t, which is singular: its FEM end peak
// exceeds the middle's and grows under refinement. The end sections' peaks
// are reported at each level so that a study can see which case it is in.
//
// Mesh: the section is graded as the plane-strain scene (fem/scenes/hertz_setup.h
// mesh_grading), with the contact element size h_c = min(b / R) R(x) / (10
// 2^(refine / 2)) over the loaded slices, but growing twice as fast away from
// the contact (0.5 h per h instead of 0.25: a third of the nodes). Along the
// ruling the layers are as thick as the contact elements at each end (but
// not thinner than half those of the nearest loaded slice) and grow
// geometrically by 1.5 towards the middle, up to L / 24. One section serves the whole ruling, so b / R may vary at most
// 2-fold along it (slab_feasible).
#include "fem/scenes/slice_contact.h"
#include <array>
#include <cstdint>
#include <mpi.h>
#include <span>
#include <string>
#include <vector>

namespace rollcheck::fem
{
struct SlabSettings
{
  double youngs_modulus_pa = 200e9; ///< steel (the preprint's)
  double poisson_ratio = 0.3;       ///< steel (the preprint's)
  /// Section level, as HertzSettings::refine; -1: the 3D P1 default (default_refine).
  int refine = -1;
  double penalty_c = 100.0;         ///< HertzSettings::penalty_c, with h = the smallest h_c
  bool elastic_plane = false;       ///< HertzSettings::elastic_plane (the preprint's E*)
  /// Prefix "hertz_". Default MUMPS LU: the layers are up to 10^4 times
  /// longer than the contact elements are wide, and GMRES + GAMG (the 3D
  /// default) broke down on them (DIVERGED_BREAKDOWN, cylinder test).
  std::string petsc_options = "-hertz_ksp_type preonly -hertz_pc_type lu -hertz_pc_factor_mat_solver_type mumps";
};

struct SlabFem
{
  int refine = 0;                     ///< the section level used
  /// The slab's peak pressure in the section of each slice (the largest
  /// nodal pressure of the node planes either side, interpolated to the
  /// slice's position); 0 for slices without load.
  std::vector<double> slice_peak_pressure_pa;
  std::array<double, 2> end_peak_pressure_pa{}; ///< largest nodal pressure in the end sections x = 0, x = L
  std::vector<double> plane_position_m;      ///< node planes along the ruling
  std::vector<double> plane_peak_pressure_pa; ///< largest nodal pressure in each
  double approach_factor = 0;        ///< slab approach over the slices' at the same total force
  double force_n = 0;                ///< integrated contact pressure, whole slab
  double centre_of_pressure = 0;     ///< fraction of L, from the nodal contact forces
  double end_layer_m = 0;            ///< thickness of the end layers (the smaller end's)
  int layers = 0;
  std::int64_t dofs = 0;
  int newton_iterations = 0;
  int krylov_iterations = 0;
  double wall_s = 0;
};

/// The ruling's body: length L, radii R(0) and R(L), the force its line load
/// integrates to, and the overhang of its end faces (fem/mesh/slab_mesh.h).
struct SlabBody
{
  double length_m = 0;
  double start_radius_m = 0;
  double end_radius_m = 0;
  double force_n = 0;
  std::array<double, 2> end_overhang_rad{0.0, 0.0};
};

/// Whether one extruded section can resolve these slices (b / R within a
/// factor 2 over the loaded ones).
bool slab_feasible(std::span<const SliceFem> slices);

/// `slices` are the solved slices, ordered along the ruling; at least one
/// must carry load, and slab_feasible. ComputationError on a failed solve (every rank),
/// InputError for bad sizes.
SlabFem solve_slab(MPI_Comm comm, const SlabBody& body, std::span<const SliceFem> slices,
                   const SlabSettings& settings);
} // namespace rollcheck::fem
