#pragma once
// SDS over every sample of a rolling loop, under three pressure models that
// share the samples and the faces, so that they compare number for number:
//
//  - point Hertz, the preprint's: at each sample, the faces within its
//    threshold eps of the ground each add their point-Hertz peak pressure
//    (contact/face_pressure.h);
//  - line Hertz: the sample's contact ruling (contact/contact_locus.h) is
//    loaded by F through the centre of mass (no-tension linear rule); at
//    `map_points` points along its loaded part the plane-strain peak
//    p_hertz = sqrt(q E* / (pi R)) (Johnson 1985, eq. 4.45) is taken, held at
//    its value `end_margin` of the ruling inside each loaded end (the
//    slices stop short of the creases), and each face holding points adds
//    the largest of them;
//  - FEM: the same points with p_fem = p_hertz g(lambda), lambda = q / (E* R),
//    the plane-strain penalty FEM's correction (fem/scenes/slice_scaling.h: exact
//    by scaling, tabulated over the loop's range of lambda, held at the
//    table's least lambda below it; such points are counted).
//
// A sample whose contact is not a ruling in equilibrium is named and scored
// by what it is: on a rim point (the sharp edge of the hull) or on a flat
// end face, or tipping (the centre of mass's foot outside the ruling, so the
// load stands on the ruling's end, a rim point), the contact pressure of the
// sharp edge is singular. Those samples add their point-Hertz pressures
// (the preprint's formula is finite everywhere), and make the line-Hertz and
// FEM scores singular: reported as such, with the scores over the rulings
// beside them.
//
// FEM-FDS: the same FEM pressures as the preprint's FDS accumulates them
// (contact/trajectory_scores.h): each face adds the Miner damage of the
// amplitude p / 2 of its largest pressure (contact/fatigue.h), here at the
// loop's own load F (set F to the fatigue load to score fatigue).
//
// End-aware FEM scores (study/rims/rim_loop.h): a ruling sample whose load
// reaches a rim (loaded_from = 0 or loaded_to = 1) has a loaded end there,
// of interior angle 90 deg + the rim's lean (contact/rim_overhang.h). The
// caller's end factor gives the end's pressure over the plane-strain FEM
// pressure at the end (p_fem at the end's own load ratio, held inside the
// table's range), and the face at the end adds it as one more point; a
// factor of none marks a singular end, which makes those scores singular.
//
// The samples are located and mapped once (map_loop_samples: the contact
// locus of every sample, the costly part) and scored from what that keeps:
// loop_sds for the scores above, end_aware_scores for the end-aware ones,
// whose factors the caller may know only after loop_sds (study/rims/rim_loop.h).
//
// Convergence, both reported: the samples (every sample against every other
// one) and the FEM table (its nodes against every other node: K and 2K
// solves); the table is refined, doubling its nodes per decade, until the
// change is below `tolerance` or `max_nodes_per_decade` is reached.
#include "contact/contact_locus.h"
#include "contact/contact_parameters.h"
#include "fem/scenes/slice_scaling.h"
#include "oracle/contact_density.h"
#include "oracle/rolling_body.h"
#include <Eigen/Core>
#include <array>
#include <functional>
#include <map>
#include <mpi.h>
#include <nlohmann/json.hpp>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace rollcheck::study::loop_scores
{
/// The contact model a sample is scored with.
enum class SampleContact
{
  ruling,    ///< line contact in equilibrium: line Hertz and FEM along it
  rim_point, ///< standing on a point of a rim: sharp edge, singular
  flat_face, ///< lying on a flat end face: its sharp rim, singular
  tipping    ///< a ruling whose static load falls outside it: on its end, singular
};
const char* sample_contact_name(SampleContact contact);

/// The samples of one loop of one body: its exact circles and the orientations.
struct LoopSource
{
  std::vector<oracle::Circle> circles;
  Eigen::Vector3d centre_of_mass_m = Eigen::Vector3d::Zero();
  std::vector<Eigen::Matrix3d> rotations;    ///< body to world, one per sample
  std::vector<double> times_s;               ///< of each sample
  std::vector<std::vector<int>> oracle_faces; ///< the rigid oracle's own counts; empty: the threshold
  std::string description;
};

struct LoopSdsSettings
{
  double normal_load_n = 100.0;        ///< F, through the centre of mass (the preprint's)
  double end_margin = 0.05;         ///< fraction of the ruling held at each loaded end
  int map_points = 64;                 ///< points along each ruling mapped onto the faces
  contact::LocusSettings locus;
  double tolerance = 0.01;             ///< relative change that counts as converged
  int max_nodes_per_decade = 64;       ///< the FEM table's refinement stops here
  contact::FatigueParameters fatigue;  ///< FEM-FDS's S-N law (its load_n is not used: F is)
};

/// A point along a ruling sample's loaded part, as both pressure models need it.
struct MappedPoint
{
  int face = 0;
  double line_hertz_pa = 0;
  double load_ratio = 0;
};

/// A loaded rim end of a ruling sample: the face at the end, the line-Hertz
/// pressure and load ratio of the end itself, the rim's interior angle and
/// the sheet's radius across the ruling there.
struct LoadedEnd
{
  int face = 0;
  double line_hertz_pa = 0;
  double load_ratio = 0;
  double interior_angle_rad = 0;
  double radius_m = 0;
  /// The rim's angle normal to its edge (contact/rim_dihedral_angle.h), where
  /// interior_angle_rad is the section in the ruling's vertical plane.
  double dihedral_angle_rad = 0;
};

/// The end's b / R by line Hertz, sqrt(4 q / (pi E* R)) = sqrt(4 lambda / pi)
/// (lambda the load ratio): line contact holds while it is below
/// fem::largest_half_width_over_radius (the end model's own limit).
double half_width_over_radius(const LoadedEnd& end);

/// The end as a part finished with edge radius `edge_radius_m` has it: the
/// rolling-ball blend leaves no radius of the surface below r_e, so an end
/// whose sheet has R < r_e (near the sheet's apex, R -> 0) is taken at
/// R = r_e, line Hertz's pressure scaled by (R / r_e)^1/2 and its load ratio
/// by R / r_e (the hull's q: the blend's small rise over the apex, which
/// would unload it, is not modelled). Other ends are returned unchanged.
LoadedEnd finished_end(LoadedEnd end, double edge_radius_m);

/// A loaded rim end's pressure over the interior FEM's at the end (the
/// interior FEM's is line Hertz's peak times the slices' factor), from the
/// end as finished (finished_end: its interior angle, line Hertz's peak and
/// b at its q and R); none: the end is singular.
using EndFactor = std::function<std::optional<double>(const LoadedEnd& finished)>;

struct RulingSample
{
  std::vector<MappedPoint> points;
  std::vector<LoadedEnd> ends;
  bool even = false;
};

/// A loop's samples located and mapped onto the faces: the counts and sums
/// of every rank, and this rank's share of the ruling samples.
struct LoopSamples
{
  std::size_t samples = 0;
  std::array<std::size_t, 4> by_contact{}; ///< indexed by SampleContact
  Eigen::VectorXd face_areas;
  /// Per face, the point-Hertz and line-Hertz pressures summed over the
  /// samples and over the even-numbered ones.
  Eigen::VectorXd point_all, point_even, line_all, line_even;
  std::vector<RulingSample> rulings;       ///< this rank's share
  double load_ratio_min = 0, load_ratio_max = 0; ///< lambda over the mapped points
  double wall_s = 0;                       ///< loci and mapping
  std::size_t ruling_count() const { return by_contact[static_cast<std::size_t>(SampleContact::ruling)]; }
};

/// An SDS over the loop's samples and over every other sample.
struct ConvergedScore
{
  std::optional<double> value;         ///< none: singular, or nothing scored
  std::optional<double> half_samples;  ///< over the even-numbered samples
  double sample_change() const;        ///< value / half_samples - 1 (NaN if either is missing)
};

/// FEM-SDS and FEM-FDS of the ruling samples with their loaded ends' pressures.
struct EndAwareScores
{
  ConvergedScore sds, fds;             ///< none when an end is singular or outside the model
  std::size_t singular_ends = 0;       ///< loaded ends the factor calls singular
  /// Loaded ends where line contact fails, b / R = sqrt(4 q / (pi E* R)) at
  /// least fem::largest_half_width_over_radius (a ruling ending near its
  /// sheet's apex, R -> 0): no end pressure is defined there.
  std::size_t outside_model_ends = 0;
  std::size_t outside_model_samples = 0; ///< ruling samples with such an end
  /// Loaded ends whose sheet is sharper across the ruling than a rounded
  /// part's finish allows (R below its edge radius, near a sheet's apex),
  /// taken at R = r_e (end_aware_scores).
  std::size_t finished_ends = 0;
  /// Largest end pressure over those ends and over the others (0 when an
  /// end is singular), to show which sets the loop's peak.
  double finished_peak_pa = 0, unfinished_peak_pa = 0;
  /// Largest end pressure over the ends that have one (0 when an end is
  /// singular): with ends outside the model, over those it covers.
  double peak_pa = 0;
  /// The same over the ends with b / R below half the limit: where it
  /// differs from peak_pa, the largest pressure sits at the model's limit
  /// (line Hertz's grows as R^-1/2 towards a sheet's apex) and is no peak.
  double peak_within_half_limit_pa = 0;
};

struct LoopSds
{
  std::size_t samples = 0;
  std::map<std::string, std::size_t> samples_by_contact; ///< sample_contact_name -> count
  std::size_t singular_samples = 0;    ///< not on a ruling in equilibrium
  ConvergedScore point_hertz;          ///< every sample
  ConvergedScore line_hertz, fem;      ///< every sample; none when a sample is singular
  ConvergedScore line_hertz_rulings, fem_rulings; ///< the ruling samples alone
  ConvergedScore fem_fds_rulings;      ///< FEM-FDS of the ruling samples (interior only)
  /// Ruling samples whose load reaches a rim, their loaded ends, and the
  /// range of those ends' interior angles (rad).
  std::size_t loaded_end_samples = 0, loaded_ends = 0;
  double loaded_end_angle_min_rad = 0, loaded_end_angle_max_rad = 0;
  std::vector<EndAwareScores> end_aware; ///< one per end factor (end_aware_scores); none: not scored
  /// FEM-SDS (over the rulings) from the table with every other node: K solves.
  std::optional<double> fem_half_table;
  std::size_t fem_solves = 0;          ///< 2K: table nodes within the loop's range of lambda
  std::size_t fem_solves_half_table = 0; ///< K
  int nodes_per_decade = 0;
  double load_ratio_min = 0, load_ratio_max = 0; ///< lambda over the mapped points
  /// Largest pressure over the loop's mapped points (inside the end margins).
  double line_hertz_peak_pa = 0, fem_peak_pa = 0;
  /// Per face, summed over the ruling samples as fem_rulings and
  /// fem_fds_rulings score them (the interior points, the full table): the
  /// largest FEM pressure each sample puts on the face (Pa), and its Miner
  /// damage (contact/fatigue.h, dimensionless). Zero on every face when the
  /// loop has no ruling sample.
  Eigen::VectorXd accumulated_fem_pressure_pa, accumulated_fem_fatigue_damage;
  /// Mapped points of the ruling samples, and those whose load ratio lies
  /// below the table's least (fem::SliceScaling::smallest_load_ratio), given g there.
  std::size_t mapped_points = 0, points_below_table = 0;
  double worst_refinement_change = 0;  ///< over the nodes used: |g finer / g - 1|
  double tolerance = 0;
  double samples_wall_s = 0;           ///< loci and mapping
  double table_change() const;         ///< fem_rulings / fem_half_table - 1
  /// Both changes of the FEM-SDS (table, samples) below the tolerance.
  bool converged() const;
  /// "converged", "not converged (...)" or "singular (...)", in words.
  std::string status() const;
};

/// The samples of `source` on `body` (the mesh the faces belong to, with its
/// cones and the preprint's per-face point-Hertz pressures), located and
/// mapped with the slices' E*. Collective on `comm`: the ranks share the
/// samples.
LoopSamples map_loop_samples(MPI_Comm comm, const LoopSource& source, const oracle::RollingBody& body,
                             const Eigen::VectorXd& face_peak_pressure_pa, const oracle::FaceCones& cones,
                             double effective_modulus_pa, const LoopSdsSettings& settings);

/// The scores of the samples (with no end-aware ones), extending and
/// refining `table` as needed. Collective on `comm`: the ranks share the
/// table's nodes; every rank gets the result.
LoopSds loop_sds(MPI_Comm comm, const LoopSamples& samples, fem::SliceScaling& table, const LoopSdsSettings& settings);

/// One set of end-aware scores per factor (e.g. an end table and its every
/// other node), from `table` as loop_sds left it; none when the loop has no
/// ruling sample. Collective on `comm`.
///
/// `edge_radius_m` > 0: the part is finished with that edge radius (a ball
/// of radius r_e rolled inside the hull rounds every part of the surface it
/// cannot touch); every end is scored as finished_end has it.
std::vector<EndAwareScores> end_aware_scores(MPI_Comm comm, const LoopSamples& samples,
                                             const fem::SliceScaling& table, const LoopSdsSettings& settings,
                                             std::span<const EndFactor> end_factors, double edge_radius_m);

/// Fractions of the ruling mapped onto the faces: the midpoints of `points`
/// equal parts of [loaded_from, loaded_to].
std::vector<double> mapping_fractions(double loaded_from, double loaded_to, int points);

/// Line-contact Hertz peak sqrt(q E* / (pi R)) at fraction `f` of a ruling of
/// length L, radius R(f) linear from its start to its end radius, carrying
/// `force_n` with centre of pressure c (oracle::line_load); 0 where unloaded.
double line_hertz_peak(double force_n, double centre_of_pressure, const oracle::Ruling& ruling,
                       double effective_modulus_pa, double f);

nlohmann::json to_json(const LoopSds& loop);
/// The loop's headline under the keys of every record of a whole loop
/// (FEM-SDS's, the family table's rows): samples, singular_samples,
/// line_hertz_sds, fem_sds, fem_sds_status, fem_sds_table_change and
/// fem_sds_sample_change.
nlohmann::json headline_json(const LoopSds& loop);
} // namespace rollcheck::study::loop_scores
