#pragma once
// FEM-SDS: the SDS of a whole rolling loop under FEM contact stress, beside
// the preprint's point-Hertz SDS and the line-Hertz SDS of the same samples
// (docs/methods/fem-sds.md).
//
// The loop: one loop of real rolling (default) or the rigid-body oracle's
// samples. Every sample is scored (study/loop_scores/loop_sds.h) through the FEM
// slices' exact scaling (fem/scenes/slice_scaling.h); the table of FEM solves is
// refined until doubling it changes FEM-SDS by less than the tolerance.
// Beside it, K orientations drawn from the loop are solved directly, slice
// by slice at two mesh levels (fem/scenes/slice_contact.h): the check of the table
// against direct FEM, and the per-orientation table; optionally the whole
// ruling as one 3D slab (fem/scenes/slab_contact.h), the fuller model.
#include "contact/contact_locus.h"
#include "contact/contact_parameters.h"
#include "fem/scenes/slab_contact.h"
#include "fem/scenes/slice_contact.h"
#include "study/loop_scores/fem_sds_continuum.h"
#include "study/loop_scores/loop_sds.h"
#include "geometry/body.h"
#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <mpi.h>
#include <nlohmann/json.hpp>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace rollcheck::study::loop_scores
{
/// Where the orientations come from.
enum class OrientationOracle
{
  rolling, ///< real rolling without slipping: the body on a ruling at every instant
  rigid    ///< the preprint's rigid-body oracle, whose orientations mostly stand on a rim point
};

struct FemSdsSettings
{
  /// A hull of circles (oloid, paper-oloid, roller, cylinder), built from its
  /// spec: the contact locus needs its exact circles, not a mesh file.
  geometry::BodySpec body;
  OrientationOracle oracle = OrientationOracle::rolling;
  /// Samples of the rolling loop, every one scored; the loop is resampled so
  /// that each body's loop has this many whatever its period.
  long samples_per_loop = 16384;
  int table_nodes_per_decade = 2;  ///< FEM table's start (refined while not converged)
  double tolerance = 0.01;         ///< relative change of FEM-SDS that counts as converged
  /// Orientations solved directly (slices at two levels), one per equal
  /// stratum of the loop: the check of the table, and the per-orientation table.
  std::size_t orientations = 2;
  std::uint64_t seed = 1;          ///< of the stratified sampling
  double rolling_energy = 0.1;     ///< rolling oracle: kinetic energy / potential barrier - 1
  int runs = 3;                    ///< rigid oracle: runs with the reference's first initial spins
  /// eps: the faces the preprint's SDS counts at an orientation.
  double contact_threshold_m = contact::LocusSettings{}.contact_threshold_m;
  /// The preprint's face pressures (PaperCompat::reference()) for the analytic
  /// SDS; otherwise every quirk corrected.
  bool paper_compat = false;
  double youngs_modulus_pa = contact::HertzParameters{}.youngs_modulus_pa;
  double poisson_ratio = contact::HertzParameters{}.poisson_ratio;
  /// F, through the centre of mass onto the rigid plane.
  double normal_load_n = contact::HertzParameters{}.normal_load_n;
  int fem_slices = 9;              ///< plane-strain slices per orientation, over the loaded ruling
  /// Fraction of the ruling kept clear at each end of the loaded contact: the
  /// FEM peaks are taken away from the creases.
  double end_margin = 0.05;
  int map_points = 64;             ///< points along each ruling mapped onto the faces
  int refine = fem::SliceSettings{}.refine;       ///< the slices' level; the error estimate runs one finer
  double penalty_c = fem::SliceSettings{}.penalty_c;
  /// The first N solved orientations that slab_feasible() admits are also
  /// solved as one 3D slab of the whole ruling; 0: none.
  std::size_t slab_orientations = 0;
  int slab_refine = 0;             ///< the slab's section level; the second solve is one finer
  bool elastic_plane = false;      ///< the E* of two identical bodies instead of a rigid plane
  // The continuum value (fem_sds_continuum.h) of a rolling loop: its
  // modelling choices (contact/continuum_loop_scores.h). The template keeps
  // F through the centre of mass, the paper-compatible column.
  /// dynamic: N and the centre of pressure of the same rolling motion, so
  /// that the load agrees with the time law; static: F through the centre of
  /// mass; uniform: F / L along the ruling.
  contact::LoadRule load_rule = contact::LoadRule::dynamic;
  /// geometric: each pass adds its peak pressure, as the template's samples
  /// do; hertz: the pressure-time integral over the patch.
  oracle::ContactWidthModel contact_width = oracle::ContactWidthModel::rigid;
  /// free_rolling: the loop's own time law; uniform_rate: sigma' constant over
  /// the same loop (the limit of a fast roll).
  contact::TimeLaw time_law = contact::TimeLaw::free_rolling;
  int continuum_pieces = 64;       ///< Gauss pieces along each ruling
};

struct FemSdsOrientation
{
  std::size_t index = 0;                   ///< among the sampled orientations
  contact::ContactLocus locus;
  double point_hertz_peak_pa = 0;          ///< the preprint's: largest p_f over its faces
  bool solved = false;                     ///< a ruling in equilibrium: slices solved
  std::vector<fem::SliceFem> slices;
  double fem_peak_pa = 0, fem_peak_refined_pa = 0, line_hertz_peak_pa = 0;
  double line_hertz_end_peak_pa = 0;       ///< slice formula at the loaded ends (the crease's nominal value)
  double contact_length_m = 0, contact_width_m = 0;
  std::int64_t dofs = 0;
  int newton_iterations = 0, krylov_iterations = 0;
  double wall_s = 0;
  /// Largest |table / direct - 1| of the slices' FEM peaks: the scaled table
  /// (fem/scenes/slice_scaling.h) against the slices solved as they are.
  double table_vs_direct = 0;
  std::vector<fem::SlabFem> slab;          ///< the 3D check at two section levels, if run
  /// Lean of the body's rims at the ruling's start and end (contact/rim_overhang.h):
  /// > 0 an obtuse edge, singular against the rigid plane where loaded.
  std::array<double, 2> rim_overhang_rad{};

  int obtuse_loaded_rims() const;
  /// The slab's peak over the slices' positions against the slices' peak,
  /// minus 1: the orientation's peak under the fuller model.
  double slab_peak_difference(const fem::SlabFem& level) const;
  /// Largest |slab / slice - 1| over the loaded slices: the outermost show
  /// the free end's compliance that plane strain leaves out.
  double slab_slice_difference(const fem::SlabFem& level) const;
};

struct FemSdsResult
{
  std::string body;                        ///< geometry::body_label
  OrientationOracle oracle = OrientationOracle::rolling;
  std::string source;                      ///< the oracle run, in words
  std::vector<FemSdsOrientation> orientations;
  std::size_t fem_solved = 0, reaching_crease = 0, standing_on_crease = 0, reaching_obtuse_rim = 0;
  LoopSds loop;                            ///< the scores over every sample of the loop
  /// The loop's samples as mapped for `loop` (this rank's share of the
  /// rulings; not in the JSON): end-aware scores reuse them (study/rims/rim_loop.h).
  LoopSamples loop_samples;
  bool contact_held = true;                ///< rolling: false when a rim lifted before the loop closed
  /// The body's generating circles and centre of mass (body frame; not in
  /// the JSON): the rims' half-space end models solve the loop's own ends.
  std::vector<oracle::Circle> circles;
  Eigen::Vector3d centre_of_mass_m = Eigen::Vector3d::Zero();
  std::vector<fem::SliceScaling::Node> table; ///< the FEM solves every sample's pressures come from
  double table_wall_s = 0;                 ///< FEM time of the table
  std::size_t table_nodes_read = 0;        ///< its nodes another process of the job solved (slice_table_store.h)
  double table_vs_direct_worst = 0;        ///< over the directly solved orientations
  double worst_refinement_change = 0;      ///< largest |FEM finer / FEM - 1| over solved orientations
  double max_orientation_wall_s = 0;
  std::size_t slab_checked = 0, slab_skipped = 0;
  double slab_worst_peak_difference = 0;
  double normal_load_n = 0;                 ///< F, the settings'
  double effective_modulus_pa = 0;          ///< of the FEM and the line-Hertz slices
  double analytic_effective_modulus_pa = 0; ///< of the preprint's face pressures
  std::int64_t n_faces = 0;
  /// The continuum value; none for the rigid oracle or a loop a rim cut short.
  std::optional<ContinuumSds> continuum;
  double wall_s = 0;
};

/// What of a body's loop score_body_loop computes: a search scoring one
/// FEM-SDS value skips the others (U: the contact density's pass over the
/// mesh; the face template: the mesh, its faces' pressures and the mapping
/// of every sample onto them; the continuum value: its passes over the loop).
struct BodyLoopParts
{
  bool uniformity = true;
  bool face_template = true;
  bool continuum = true;
};
/// One body's whole loop scored, with a FEM table the caller may share
/// between bodies (the family table): the scores of run_fem_sds without the
/// directly solved orientations, and U of the loop's contact density.
struct BodyLoop
{
  std::string body;                 ///< geometry::body_label
  std::string source;               ///< the loop, in words
  bool contact_held = true;         ///< false: a rim lifted before the loop closed
  std::int64_t n_faces = 0;
  LoopSds loop;
  std::optional<double> uniformity; ///< U (oracle/uniformity_score.h), rolling oracle only
  std::optional<ContinuumSds> continuum; ///< rolling oracle, a whole loop only
  BodyLoopParts parts;                   ///< what was computed
  /// The status of the value scored: the template's (LoopSds::status), or
  /// the continuum's (ContinuumSds::status) when the template was left out.
  std::string status() const;
};
/// The parts left out stay empty (`loop` default, no U, no continuum; with
/// the rolling oracle and neither the template nor U, no mesh and so no faces).
BodyLoop score_body_loop(MPI_Comm comm, const FemSdsSettings& settings, fem::SliceScaling& table,
                         const BodyLoopParts& parts = {});

/// The slices' FEM settings of `settings`: what a shared table is built with.
fem::SliceSettings slice_settings(const FemSdsSettings& settings);
/// The loop's scoring settings of `settings`: what its samples are mapped
/// and scored with (end_aware_scores of FemSdsResult::loop_samples too).
LoopSdsSettings loop_settings(const FemSdsSettings& settings);
/// The continuum value's settings of `settings` (its end margin is end_margin).
contact::ContinuumLoopSettings continuum_settings(const FemSdsSettings& settings);

/// Runs the method on the ranks of `comm` (every rank gets the whole result
/// but for its share of loop_samples; rank 0 logs each orientation). InputError naming the setting for a mesh
/// file or a body that is not a hull of circles; ComputationError from the FEM.
FemSdsResult run_fem_sds(MPI_Comm comm, const FemSdsSettings& settings);
/// The same with the caller's FEM table (extended as needed), to share it.
FemSdsResult run_fem_sds(MPI_Comm comm, const FemSdsSettings& settings, fem::SliceScaling& table);

nlohmann::json to_json(const FemSdsOrientation& orientation);
nlohmann::json to_json(const FemSdsResult& result);
/// The continuum keys of fem_sds_continuum.h's to_json, null where there is none.
nlohmann::json continuum_json(const std::optional<ContinuumSds>& continuum);
/// The Markdown table of the directly solved orientations, and of their 3D
/// slab check where it ran (the folder's table.md).
std::string markdown_table(const FemSdsResult& result);
/// The run in words for the log: the body, the table, the loop's scores with
/// their convergence and the table's check against direct FEM.
std::string report(const FemSdsResult& result);

// The steps of the method, exposed for tests.

/// "rolling" or "rigid".
const char* oracle_name(OrientationOracle oracle);
/// "point", "segment", "polygon" or "disc".
const char* support_name(oracle::CircleSupportKind kind);

/// Fractions of the ruling where the slices go: `slices` evenly from
/// loaded_from + margin to loaded_to - margin, both included.
std::vector<double> slice_fractions(double loaded_from, double loaded_to, double end_margin, int slices);

} // namespace rollcheck::study::loop_scores
