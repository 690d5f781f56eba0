#pragma once
// Where a two-circle roller family's optimum lies, and what the family's
// (90, 1, 1) member is: the method of `rollcheck optimize` (docs/methods/optimize.md).
// A genome x = (theta_deg, offset d, ratio rho) is meshed (r1 = 1) with the
// same points per circle as every other body, or with the points per circle
// whose hull has the start's face count (matched face count), and scored by
// body_scores::score_body (CDS or SDS under the approximate or rigid-body oracle, U under
// real rolling). The flow is optimize.h's: the noise measured at the start,
// a search in the box, central-difference gradient and Hessian with their
// verdicts at the start and at the optimum, and sweeps along each axis
// through the start. The distinct points of one phase are evaluated in
// parallel (noise replicates, step pilots, stencils, sweeps); the search
// itself is sequential.
#include "study/optimize/optimize.h"
#include "study/body_scores/score_body.h"
#include <functional>
#include <future>
#include <map>
#include <mutex>
#include <nlohmann/json.hpp>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace rollcheck::study::optimize
{
enum class FamilyScore
{
  cds,       ///< the preprint's contact distribution score (approximate or rigid oracle)
  sds,       ///< the preprint's stress distribution score (approximate or rigid oracle)
  uniformity, ///< U of real rolling (oracle rolling)
  /// FEM-SDS over one loop of real rolling, its continuum value on the exact
  /// surface (oracle rolling; fem_sds_score): resolution-free, so genomes of
  /// different face counts compare.
  fem_sds,
  /// The same loop's FEM-SDS by the preprint's per-face template: about
  /// faces^-2, so at fixed points per circle it ranks genomes by their face
  /// count (the paper-compatible value).
  fem_sds_template
};

/// Where the gradient and Hessian are measured (each costs about 2n^2 + 1
/// scores in n = 3 parameters, and pilots for its steps): at the start and
/// at the optimum, at the start only (its verdict decides the title claim
/// when the search finds nothing better), or nowhere (the search alone).
enum class DerivativesAt
{
  start_and_optimum,
  start,
  none
};

/// both, start, none (for io::BoundSchema::choice).
const std::vector<std::pair<std::string, DerivativesAt>>& derivatives_at_names();

/// fem_sds or fem_sds_template: computed by fem_sds_score, one body at a time.
bool is_fem_sds(FamilyScore score);

/// A body's score computed outside this library (FEM-SDS lives in
/// rollcheck_study_fem: study/loop_scores/fem_sds_family.h fem_sds_scorer).
using BodyScore = std::function<double(const geometry::BodySpec&)>;

/// cds, sds, uniformity, fem-sds, fem-sds-template (for io::BoundSchema::choice).
const std::vector<std::pair<std::string, FamilyScore>>& family_score_names();

/// One finished run of body_scores::score_body: the genome, the replicate, the value.
struct OracleRun
{
  std::vector<double> x;
  int replicate = 0;
  double value = 0;
};

/// Runs kept outside the search, so that rerunning it after an interruption
/// reuses the finished ones (rollcheck optimize --out keeps them in a file:
/// io/evaluation_cache.h). The keeper answers only for runs under the same
/// settings. Both hooks empty: nothing is kept.
struct RunStore
{
  /// The value of run (x, replicate) if it was finished before.
  std::function<std::optional<double>(std::span<const double> x, int replicate)> recall;
  /// The runs of one phase, once all of them finished (on the calling thread).
  std::function<void(std::span<const OracleRun> runs)> record;
};

/// One parameter of the genome: its search interval and its start.
struct FamilyAxis
{
  double min, max, start;
};

struct FamilySearchSettings
{
  FamilyScore score = FamilyScore::cds;
  /// approximate (deterministic) or rigid (chaotic: each score the mean of
  /// `replicates` runs, see `replicates`) for cds and sds; rolling for uniformity and fem_sds.
  body_scores::Oracle oracle = body_scores::Oracle::approximate;
  bool paper_compat = false; ///< every switch of oracle/paper_compat.h as the reference code; else corrected
  geometry::RollerFamily family = geometry::RollerFamily::paper;
  int points = 100; ///< samples per generating circle: of every body, or of the start (match_face_count)
  /// Mesh each genome with the points per circle whose hull's face count is
  /// nearest the start's at `points` (ties: `points` itself, else the fewer
  /// points, so that a genome with the start's face count at `points`, the
  /// start included, is meshed as without matching): CDS falls about
  /// as N_faces^-2, and at fixed points per circle the face count moves with
  /// the genome. Off: every body meshed with `points` per circle.
  bool match_face_count = false;
  /// Wider than the preprint's grid {60..120} x {0.7..1.3} x {0.8..1.2}; start at the family's (90, 1, 1).
  FamilyAxis theta_deg{40, 140, 90}, offset{0.5, 1.5, 1}, ratio{0.6, 1.4, 1};
  Method method = Method::bobyqa;
  int max_evaluations = 60; ///< distinct genomes the search scores, the start included
  /// Noise replicates at the start (>= 2): replicate r > 0 moves the genome by
  /// `resolution` of each box width in a replicate-dependent direction
  /// (replicate_genome). Rigid oracle: every score is the mean of this many
  /// replicates. A 1e-12 rad/s spin nudge (study/body_scores/paper_quirks.h's band) is not
  /// used: over the 10 s runs it moves the preprint's body's scores by only
  /// 0.05 %, while a moved genome's runs lose the nominal trajectory and spread
  /// by about 11 % (docs/methods/optimize.md "The rigid-body noise"). FEM-SDS: the
  /// replicates also change the mesh (replicate_mesh_offset).
  int replicates = 4;
  /// Fraction of each box width the search resolves (its xtol); the
  /// deterministic oracles' noise is the score's spread over such moves.
  double resolution = 1e-3;
  double pilot_step = 0.05; ///< balanced_steps' pilots, fraction of each box width
  DerivativesAt derivatives = DerivativesAt::start_and_optimum;
  int sweep_points = 9; ///< per axis, from min to max through the start
  unsigned threads = 0; ///< evaluations in parallel (0: one per core)
  /// score fem_sds or fem_sds_template: the body's FEM-SDS of that kind. It is called on the calling thread,
  /// one body at a time (its FEM is collective over the MPI ranks).
  BodyScore fem_sds_score;
  /// Finished runs kept across interrupted searches: asked before each run, told after each phase.
  RunStore run_store;
  /// The oracles' options (steps, duration, rolling loops, contact parameters);
  /// its body, oracle, compat and metrics are set per genome.
  body_scores::ScoreBodySettings scoring;
};

/// InputError naming the setting (theta_min_deg, ..., the start outside its interval, ...).
void validate(const FamilySearchSettings& settings);

/// The body of genome x (theta_deg, offset, ratio) of the settings' family,
/// meshed with `points` per generating circle.
geometry::BodySpec family_body(const FamilySearchSettings& settings, std::span<const double> x, int points);

/// How one body is meshed: points per generating circle, and its hull's faces.
struct MeshResolution
{
  int points = 0;
  long faces = 0;
};
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(MeshResolution, points, faces)

/// The face count of family_body(settings, x, points)'s hull (Qhull alone:
/// no body checks, no scoring).
long hull_faces(const FamilySearchSettings& settings, std::span<const double> x, int points);

/// The points per circle whose hull's face count is nearest `target_faces`
/// (ties: settings.points itself, else the fewer points). The face count is
/// about proportional to the points but not monotone in them, so the points
/// around the proportional guess are tried, outwards until two more on either
/// side bring no gain.
MeshResolution matched_mesh(const FamilySearchSettings& settings, std::span<const double> x, long target_faces);

/// The mesh of every genome of one search: `points` per circle, or with
/// match_face_count the matched_mesh of the start's face count, found once
/// per genome. Safe to use from the threads of one phase.
class FamilyMeshes
{
public:
  explicit FamilyMeshes(const FamilySearchSettings& settings);
  /// The start's face count at `points`: every body's target under match_face_count.
  long target_faces() const { return target_faces_; }
  /// Points per circle genome x is meshed with.
  int points(std::span<const double> x);
  /// Those points and the hull's face count they give.
  MeshResolution resolution(std::span<const double> x);

private:
  const FamilySearchSettings& settings_;
  long target_faces_;
  std::mutex mutex_;
  std::map<std::vector<double>, std::shared_future<MeshResolution>> matched_;
};

/// The genome replicate `replicate` scores in place of x: x itself for 0, else
/// x moved by `resolution` of each box width along the Halton direction
/// (bases 2, 3, 5) of the replicate, clipped to the box.
std::vector<double> replicate_genome(const FamilySearchSettings& settings, std::span<const double> x, int replicate);

/// Points per circle replicate `replicate` adds to its body's mesh: FEM-SDS
/// 0, 2, -2, 4, -4, ... (the score moves by up to a third between meshes of
/// one genome: the true oloid at 96 to 104 points per circle scored 1.28e-05
/// to 1.97e-05, so its noise must include the mesh); other scores 0.
int replicate_mesh_offset(const FamilySearchSettings& settings, int replicate);

/// One evaluation of the score at replicate_genome(x, replicate), the body
/// meshed as `meshes` says for that genome, plus replicate_mesh_offset points.
double replicate_score(const FamilySearchSettings& settings, FamilyMeshes& meshes, std::span<const double> x,
                       int replicate);

/// The score the search minimises: replicate 0 (approximate, rolling), or the
/// mean of replicates 0 .. replicates-1 (rigid: a local average over the
/// moved genomes, which smooths the chaotic oracle).
double family_score(const FamilySearchSettings& settings, std::span<const double> x);

struct FamilySearchResult
{
  FamilySearchSettings settings;
  NoiseEstimate noise_replicates; ///< at the start
  double noise_sigma = 0;         ///< of family_score: the replicates' sd, or their mean's standard error (rigid)
  OptimizeResult search;
  Box box;
  /// Derivatives at the start and at the best point, or why there are none
  /// (the point lies on a bound: central differences need room).
  std::optional<StepChoice> start_steps, best_steps;
  std::optional<Derivatives> at_start, at_best;
  std::string start_derivatives_note, best_derivatives_note;
  std::vector<AxisSweep> sweeps;     ///< through the start
  long target_faces = 0;             ///< the start's hull faces at `points`
  MeshResolution start_mesh, best_mesh;
  long score_evaluations = 0;        ///< distinct genomes scored in all phases
  long oracle_runs = 0;              ///< body_scores::score_body calls (runs not recalled)
  long recalled_runs = 0;            ///< runs taken from settings.run_store
  double wall_s = 0;
};

/// The whole flow. InputError for bad settings; ComputationError naming the
/// genome where scoring fails.
FamilySearchResult optimize_family(const FamilySearchSettings& settings);

/// Named keys (docs/methods/optimize.md "rollcheck optimize").
nlohmann::json to_json(const FamilySearchResult& result);

/// One line for the log: the score and oracle, the start and the optimum
/// with their values, whether the optimum beats the start beyond the noise,
/// the verdict at the start, the meshes and the cost.
std::string summary_line(const FamilySearchResult& result);

/// The convergence of the FEM-SDS loops a search with --score fem-sds scored
/// (one status per body, loop_scores::fem_sds_scorer's): how many, and how
/// many of each status, "converged", "not converged" or the status itself
/// (singular, or why the body has no whole loop).
struct LoopStatusCounts
{
  std::size_t scored = 0;
  std::map<std::string, int> by_status;
  int not_converged() const;
};
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(LoopStatusCounts, scored, by_status)
LoopStatusCounts count_loop_statuses(std::span<const std::string> statuses);
} // namespace rollcheck::study::optimize
