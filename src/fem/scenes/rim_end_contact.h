#pragma once
// One end of a loaded ruling, in 3D: the rim end scene (fem/mesh/scene_mesh.h
// build_rim_end_mesh) pressed onto the rigid frictionless plane, at several
// sizes of the elements along the edge.
//
// Load: the far side x = -L is a plane of symmetry, so the section there is
// in plane strain once L is long enough against the block's depth H. The top's
// approach is set by load control (fem/load_control.h) until the line load
// the far side carries, q_far (its contact force over the first depth H,
// weighted towards x = -L: rim_end_contact.cpp far_line_load), is the line
// load q the contact locus gives at the end (contact/line_contact.h). The model's
// unit is line Hertz's half-width for that q, b = sqrt(4 q R / (pi E*)), with
// E* = E / (1 - nu^2) against the rigid plane: H = 10 b and L = 3 H by
// default. That the far side is in plane strain is shown, not assumed: the
// centre-line pressure at x = -L / 2 against x = -L (`plane_strain_change`).
// A finer level starts from the coarser level's solution, interpolated onto
// its mesh (fem/interpolate_between_meshes.h), at that level's approach:
// the levels differ near the edge, so Newton is left the edge's correction.
//
// Edge: sharp (edge radius 0) or rounded. A sharp edge of interior angle a
// mirrors in the plane into the free-free wedge of 2 a (contact/wedge_exponent.h,
// M. L. Williams 1952): for a > 90 deg its stresses grow as r^(lambda - 1)
// towards the edge, and the edge's nodal pressure (a force over an element's
// area) grows as h_e^(lambda - 1) when the edge elements h_e shrink. The
// study halves h_e level by level and measures that exponent as the least
// squares slope of ln p_edge on ln h_e over the levels (fitted_exponent of
// core/refinement_series.h, whose series the levels are). A sharp
// edge of a > 90 deg is reported singular with both exponents and no peak
// value; a square edge (a = 90 deg, not singular on the rigid plane) has an
// edge pressure, a rounded edge an end peak, that must converge: its change
// between the last two levels below `tolerance`, or the study says it did not
// (after up to `extra_levels` more levels, added while it does not).
//
// A rounded edge leaves the sheet at x = -x_t, x_t = r_e tan((180 deg - a) / 2),
// with a jump of curvature from 0 to 1 / r_e. The contact reaches past it
// only by about the Hertz half-width of the fillet under the local pressure,
// s = 4 p0 r_e / (pi E*) (p0 / E* ~ 1e-3 at the preprint's load: s ~ r_e / 600).
// Until the edge elements resolve s the contact stops at x = -x_t and the
// pressure there grows under refinement as at a crack tip (measured: 5.1 to
// 6.6 times the interior from h_e = b / 32 to b / 64 at a = 90 deg,
// r_e = b / 2). The edge elements are therefore graded about the line
// x = -x_t (grading them over the whole fillet instead stalled gmsh's
// Delaunay for minutes), a rounded edge counts as resolved only once h_e <= s / 4 at the
// last level, and converged only when resolved.
//
// Steel counter-face (CounterFace::block): the body and a block of its own
// material are meshed together, each volume tetrahedralised alone on one
// surface mesh (together, gmsh failed below edge elements of about 2 um
// where a fillet lifts off the block), with the flat interface z = 0 (the sheet
// flattened, its height R - sqrt(R^2 - y^2) in each pair's initial gap:
// half-space theory's reduction for two bodies, used whatever R / H, since
// the flattened geometry differs from the cylinder only away from the
// contact strip) and E* = E / (2 (1 - nu^2)) in b and p0. Frictionless
// penalty contact by node pairs (fem/penalty_contact.h NodePair): node to
// node (P. Wriggers, Computational Contact Mechanics, 2nd ed., 2006, sec.
// 4.1) where each body node has a twin, for a sharp edge; a rounded edge's
// fillet lifts off the block's top beyond x = -x_t, so the body's contact
// face up to r_e / 8 above the block's top (the sheet and the fillet within
// about r_e / 2 of its start, some 20 s at a bearing's load) takes the
// mortar's weighted gap against the block's top facets instead, g0 the mean
// of the fillet's exact height plus the sheet's; a contact that reached
// above r_e / 16 would raise ComputationError. The block's top is graded
// under the fillet's start as the body is. Runs on any number of processes
// (pairs across them).
#include "core/named_values.h"
#include <array>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <mpi.h>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

namespace rollcheck::fem
{
enum class SheetModel
{
  automatic,
  cylinder,
  flat
};

/// What the body presses on: the rigid frictionless plane, or a block of the
/// body's own material (the preprint's steel on steel), a second elastic
/// body in frictionless contact (PenaltyContact::set_node_pairs), sharp or
/// rounded edges, one or several processes.
enum class CounterFace
{
  rigid,
  block
};

/// How the end is meshed: gmsh's Delaunay tetrahedra graded about the edge
/// and the strip (any end), the same by gmsh's HXT (fem/mesh/volume_mesher.h:
/// the same surface mesh and sizes, the volume meshed faster but not
/// reproducibly), or a structured grid built without gmsh
/// (fem/mesh/scene_mesh.h build_square_end_grid_mesh: a sharp square or
/// near-square end, within 15 deg of 90, on the flat sheet against the rigid
/// plane only), an independent discretisation to check the first by.
///
/// extruded: the section meshed by gmsh in 2D and extruded along the edge
/// (fem/mesh/rim_end_extruded_mesh.h: elements h_e across the edge and b /
/// contact_elements along it, and along the strip away from the edge
/// elements growing with the distance from it), any angle, sharp or
/// rounded, on the flat sheet against the rigid plane, the edge square to
/// the ruling; not yet the default: its far side reads line Hertz's p0,
/// gmsh's 3 % above it at the strip's b / 6, so their end/interior ratios
/// differ by that much (docs/methods/rims.md, "Where a rounded loop's time
/// goes"). automatic: extruded where it applies, Delaunay elsewhere.
enum class RimEndMesh
{
  delaunay,
  hxt,
  grid,
  extruded,
  automatic
};

/// The flat sheet is half-space theory's, for b << R: the largest b / R the
/// scene accepts (fem::solve_rim_end refuses beyond it).
constexpr double largest_half_width_over_radius = 0.2;

struct RimEndSettings
{
  /// R across the ruling at the end: the 10 mm cylinder of the Hertz scenes.
  double radius_m = 0.01;
  /// q at the end: the preprint's F = 100 N spread over a 10 mm ruling.
  double load_n_per_m = 1e4;
  /// a, between the contact sheet and the other face, [60, 180) deg; 90: a
  /// square end, below it an acute (undercut) rim.
  double interior_angle_rad = std::numbers::pi / 2;
  double edge_radius_m = 0;          ///< r_e; 0: sharp
  /// c, the angle in the contact plane between the ruling and the edge, (0,
  /// 90] deg (fem/mesh/rim_end_geometry.h RimEndGeometry::crossing_angle_rad):
  /// 90 the edge square to the ruling (the y >= 0 half by symmetry); below,
  /// interior_angle_rad is the section in the ruling's vertical plane, the
  /// wedge's angle the dihedral normal to the edge (fem/mesh/oblique_end_angle.h),
  /// and the model covers both sides of the ruling: on the rigid plane,
  /// gmsh's mesh, L / H > 1 + cot c, a rounded edge on the flat sheet (its
  /// peak read over the face: fem/scenes/rim_end_oblique_peak.h).
  double crossing_angle_rad = std::numbers::pi / 2;
  CounterFace counter_face = CounterFace::rigid;
  double youngs_modulus_pa = 200e9;  ///< steel (the preprint's)
  double poisson_ratio = 0.3;        ///< steel (the preprint's)
  double depth_over_half_width = 10; ///< H / b
  double length_over_depth = 3;      ///< L / H
  /// The contact sheet as OpenCASCADE's cylinder, or flattened onto z = 0
  /// with its height in the initial gap (fem/mesh/scene_mesh.h RimEndGeometry);
  /// automatic: flat where R >= 20 H (the sheet rises less than H / 40
  /// across the block) or R < H (the cylinder cannot hold the block), the
  /// cylinder between. The flat sheet needs b < R / 5 (half-space theory).
  SheetModel sheet = SheetModel::automatic;
  RimEndMesh mesh = RimEndMesh::delaunay;
  int contact_elements = 6;          ///< elements across b along the contact strip
  /// Edge elements at the first level, h_e / b; each further level halves them.
  double edge_element_over_half_width = 1.0 / 8;
  int levels = 3;                    ///< 1 to 6; convergence needs 2
  /// Levels beyond `levels`, 0 to 2, added one at a time while a
  /// non-singular end is not converged (its ratio changes by `tolerance` or
  /// more over the last level, or a fillet's boundary layer is not yet
  /// resolved); none after a single level. rim --body's end models take at
  /// least one, as its flat-rim table's nodes do.
  int extra_levels = 0;
  /// A rounded edge: where the last level's h_e would not resolve the
  /// boundary layer s (h_e <= s / 4, s / b = 2 r_e / (pi R)), the first
  /// level's is refined until it does (ends of large R against r_e: the rim
  /// loop's end models set it).
  bool resolve_boundary_layer = false;
  double tolerance = 0.03;           ///< the end/interior ratio's relative change per level that counts as converged
  /// kappa = c E / h(x), h(x) the element size there (fem/mesh/scene_mesh.h
  /// rim_end_element_size): at c = 100 (the other scenes') the nodal
  /// pressures along the strip scattered by 4-5 %, at c = 10 by 2.4 %.
  double penalty_c = 10.0;
  std::string petsc_options;         ///< prefix "hertz_" (default: see direct_solver_max_dofs)
  /// On gmsh's tetrahedra and the rigid plane, a level of at most this many
  /// unknowns is solved by MUMPS LU, a larger one by GMRES + GAMG
  /// (fem/solver_defaults.h; petsc_options naming a KSP or PC type win).
  /// LU's memory grows faster than the unknowns (one process: 0.65 GB at
  /// 93k, 1.26 GB at 193k; scripts/bench/bench_rim_solver.sh), GAMG's linearly.
  std::int64_t direct_solver_max_dofs = 300000;
  /// The last level's fields (fem/write_fields.h), if set: a .xdmf in a writable
  /// folder, written once the study has finished (a level that fails leaves none).
  std::filesystem::path xdmf_path;
  /// The first level's load control starts from this times line contact's
  /// approach with H as the radius (fem/load_control.h), which overshoots a
  /// held block's by about 20 %: 1, or a solved neighbour's
  /// RimEndStudy::approach_over_estimate (the rim loop's end table).
  double first_approach_scale = 1;
  /// If set, called on every rank as each level starts, with its index (0
  /// the first) and h_e: the rim loop's progress lines name the level.
  std::function<void(int, double)> on_level;
};

/// A surface node on the ruling's centre line y = 0: position along the
/// ruling and pressure.
struct CentreLineNode
{
  double x_m;
  double pressure_pa;
};

struct RimEndLevel
{
  double edge_element_m = 0;         ///< h_e
  double far_load_n_per_m = 0;       ///< q_far reached
  double far_peak_pa = 0;            ///< mean centre-line pressure over x in [-L, -L + H]
  double far_scatter = 0;            ///< their standard deviation over their mean
  double mid_peak_pa = 0;            ///< the same over x in [-L / 2 - H / 2, -L / 2 + H / 2]
  double mid_to_far_standard_error = 0; ///< of mid_peak_pa / far_peak_pa, from the nodes' scatter
  /// Largest centre-line pressure within 2 b + max(r_e, x_t) of the edge (each the
  /// mean over +-b / 4 along the ruling, a rounded edge's over at most half
  /// its boundary layer), and where (x).
  double end_peak_pa = 0, end_peak_x_m = 0;
  /// Where across the ruling: 0 on the centre line, except an oblique rounded
  /// edge's, read over the face near the fillet (fem/scenes/rim_end_oblique_peak.h).
  double end_peak_y_m = 0;
  /// Mean nodal pressure on a sharp edge's nodes with y <= b / 2 (0 when rounded).
  double edge_pressure_pa = 0;
  std::vector<CentreLineNode> centre_line;
  std::int64_t dofs = 0;
  double approach_m = 0;             ///< the top's approach that carries q_far
  double start_load_n_per_m = 0;     ///< q_far at the level's first approach (a finer level: the coarser's)
  double estimated_approach_m = 0;   ///< line contact's estimate of it (unscaled)
  int load_steps = 0, newton_iterations = 0, krylov_iterations = 0;
  double mesh_wall_s = 0;            ///< of wall_s, building and distributing the mesh
  double wall_s = 0;
};

struct RimEndStudy
{
  RimEndSettings setup;
  double effective_modulus_pa = 0;   ///< E* = E / (1 - nu^2)
  double half_width_m = 0;           ///< b of line Hertz
  double hertz_peak_pa = 0;          ///< p0 of line Hertz
  /// The wedge's angle normal to the edge: interior_angle_rad where the edge
  /// is square to the ruling, else the dihedral (fem/mesh/oblique_end_angle.h).
  double dihedral_angle_rad = 0;
  /// lambda - 1 of the mirrored wedge at dihedral_angle_rad (0: not singular; rounded edges 0).
  double wedge_exponent = 0;
  bool singular = false;             ///< a sharp edge with a > 90 deg
  double fillet_start_m = 0;         ///< x_t: the fillet leaves the sheet at x = -x_t (0 sharp)
  double boundary_layer_m = 0;       ///< s = 4 p0 r_e / (pi E*) (0 sharp)
  bool resolved = false;             ///< sharp, or h_e <= s / 4 at the last level
  bool flat_sheet = false;           ///< the sheet model used
  /// Growth exponent of the edge's nodal pressure over the levels (sharp edges, >= 2 levels).
  std::optional<double> measured_exponent;
  /// Not singular: the end's pressure (a sharp square or acute edge's own
  /// pressure, a rounded edge's end peak) over the far side's at the last
  /// level; that ratio's change between the last two levels over the larger
  /// of it and 1 (none with one level); and whether it is resolved and the
  /// change below the tolerance.
  std::optional<double> end_change;
  bool converged = false;
  std::optional<double> end_to_interior;
  double plane_strain_change = 0;    ///< |p(-L/2) / p(-L) - 1| at the last level
  double plane_strain_noise = 0;     ///< its standard error (the nodal pressures' scatter)
  std::vector<RimEndLevel> levels;
  /// The first level's converged approach over the unscaled estimate it
  /// started from: what starts a neighbouring end (same q, R, H) close to
  /// its own; 1 (the estimate) where no level solved an approach.
  double approach_over_estimate() const
  {
    return levels.empty() || !(levels.front().estimated_approach_m > 0)
               ? 1.0
               : levels.front().approach_m / levels.front().estimated_approach_m;
  }
  /// The wall time of every level together.
  double wall_s() const
  {
    double total = 0;
    for (const RimEndLevel& l : levels)
      total += l.wall_s;
    return total;
  }
};

/// What a non-singular end reports at a level: a sharp edge's own pressure,
/// or a rounded edge's end peak, over the far side's (the interior's) peak.
double end_to_interior(const RimEndLevel& level, bool sharp_edge);

/// The centre-line pressure at x_m (the edge at x = 0, the far side at -L),
/// linear between the two nodes either side: what the end model carries at
/// a distance -x_m from its edge. ComputationError outside the centre line.
double centre_line_pressure_at(const RimEndLevel& level, double x_m);

/// The rim end's change of its end/interior ratio from one level to the
/// next, the LevelChange its refinement series is judged by
/// (core/refinement_series.h): (last - before) / max(last, 1), over the
/// larger of its last value and 1. What `tolerance` judges.
double end_to_interior_ratio_change(double before, double last);

/// end_to_interior_ratio_change of end_to_interior from `before` to `last`.
double end_to_interior_change(const RimEndLevel& before, const RimEndLevel& last, bool sharp_edge);

/// The height (m) within which a node of the rim block scene lies on the
/// body-block interface z = 0 and is paired with its twin: 1e-9 H, and with
/// a rounded edge at most 1e-3 h_e^2 / (2 r_e). The fillet rises from the
/// interface as z = r_e (1 - cos(s / r_e)) ~ s^2 / (2 r_e) at the arc length
/// s from its start, and gmsh puts its nodes nearest the start a fraction of
/// the edge element h_e along it: on the preprint's body's 22.4 mm, 60 deg
/// end on steel (H = 4.2 mm, r_e = 0.4 mm) at h_e = 0.08 um one stood 58 nm
/// along, 4e-12 m high, within 1e-9 H, and was taken for an unpaired
/// interface node (test: RimEndContact.FilletNodesStandClearOfTheInterfaceTolerance).
/// ComputationError below 1e-13 H: gmsh leaves the interface's own nodes up
/// to 7e-15 H off the plane (the same test).
double rim_interface_tolerance(double depth_m, double edge_element_m, double edge_radius_m);

/// gmsh (Delaunay), hxt, grid, extruded, auto: the option's names, also the JSON's.
const NamedValues<RimEndMesh>& rim_end_mesh_names();

/// The mesh `study`'s levels are built on: `setup.mesh`, with automatic
/// resolved (extruded on a flat sheet square to the ruling, Delaunay
/// elsewhere) and the elastic block always gmsh's tetrahedra (HXT's if asked,
/// else Delaunay's).
RimEndMesh rim_end_mesh_used(const RimEndStudy& study);

/// Every rank gets the study. InputError for bad settings (naming the
/// setting), ComputationError for a failed solve or an unresolved contact.
RimEndStudy solve_rim_end(MPI_Comm comm, const RimEndSettings& setup);
} // namespace rollcheck::fem
