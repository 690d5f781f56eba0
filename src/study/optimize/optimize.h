#pragma once
// Wing of the study layer (study/optimize): the search of the two-circle family,
// this optimiser and the family's bodies, meshes and scores it searches
// (optimize_family.h). Light: NLopt, no FEM library.
//
// Where a body family's optimum is, and what a point of it is. A score (CDS,
// SDS, ... of a two-circle roller) is a noisy function of the family's
// parameters: the rigid-body oracle is chaotic and the mesh changes with the
// parameters, so nearby points differ by a noise of their own. This file owns
//  - minimize(): derivative-free search with NLopt (local: BOBYQA, Nelder-Mead,
//    Subplex; global: DIRECT-L, CRS2, a multistart of a local method) in a box,
//    judged against the start beyond the noise;
//  - estimate_noise(): the score's spread under replicates with perturbed
//    nuisance inputs (the initial spin);
//  - finite_differences(): central-difference gradient and Hessian with their
//    uncertainty propagated from the noise, and a verdict (minimum, saddle, ...);
//    balanced_steps() picks steps whose truncation and noise errors balance;
//  - sweep_axes(): the score along each parameter axis through a point.
// The library half of `rollcheck optimize` (docs/methods/optimize.md). A score must be
// a deterministic function of its point (the oracles are: the chaos is in the
// parameters), so a point evaluated twice is evaluated once.
#include <Eigen/Core>
#include <functional>
#include <nlohmann/json.hpp>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace rollcheck::study::optimize
{
/// The score of a point of the family, e.g. (theta_deg, d, rho).
using Score = std::function<double(std::span<const double>)>;
/// The score of a point with the nuisance inputs of replicate `replicate`
/// (e.g. the point moved by less than the search resolves, in a replicate-dependent direction).
using ReplicateScore = std::function<double(std::span<const double>, int replicate)>;

/// The search box; a parameter with lower == upper is fixed (not searched).
struct Box
{
  std::vector<double> lower, upper;
};

enum class Method
{
  bobyqa,      ///< NLopt LN_BOBYQA: local, quadratic models in a trust region
  nelder_mead, ///< NLopt LN_NELDERMEAD: local simplex
  sbplx,       ///< NLopt LN_SBPLX: local, Nelder-Mead on subspaces (Subplex)
  direct_l,    ///< NLopt GN_DIRECT_L: global, dividing rectangles (ignores the start)
  crs2_lm,     ///< NLopt GN_CRS2_LM: global, controlled random search (seeded)
  multistart   ///< the local method from the start, then from Halton points of the box
};

/// Each method's name in options and JSON: bobyqa, nelder-mead, sbplx,
/// direct-l, crs2-lm, multistart (for io::BoundSchema::choice).
const std::vector<std::pair<std::string, Method>>& method_names();
std::string method_name(Method method);

struct OptimizeSettings
{
  Method method = Method::bobyqa;
  Method local_method = Method::bobyqa; ///< of each multistart run: bobyqa, nelder-mead or sbplx
  int starts = 4;                       ///< multistart runs: the start, then Halton points 1, 2, ...
  std::vector<double> start;            ///< first point evaluated, and the reference the best must beat
  Box box;
  int max_evaluations = 200; ///< distinct score evaluations, the start's and every run's included
  double noise = 0;          ///< absolute noise sigma of the score (estimate_noise); 0: exact
  double xtol = 1e-3;        ///< stop when a step moves each parameter less than this fraction of its box width
  unsigned seed = 1;         ///< CRS2's random generator (NLopt's global one)
};

struct Evaluation
{
  std::vector<double> x;
  double value;
};

struct OptimizeResult
{
  Method method = Method::bobyqa;
  std::vector<double> start;
  double start_value = 0;
  std::vector<double> best_x; ///< the best point evaluated
  double best_value = 0;
  int evaluations = 0;
  std::vector<Evaluation> history; ///< every distinct evaluation, in order; the start first
  std::string stop_reason;         ///< NLopt's (per run, for multistart)
  double noise = 0;
  /// start_value - best_value must exceed this to beat the start: 2 sigma of a
  /// difference of two values (2 sqrt(2) noise), plus the selection bias of
  /// the best of n noisy values (sqrt(2 ln n) noise).
  double significance_threshold = 0;
  bool beats_start = false;
};

/// Minimises `score` over settings.box from settings.start. InputError for a
/// bad box, start or setting (naming it); ComputationError naming the point
/// where the score throws or returns NaN.
OptimizeResult minimize(const Score& score, const OptimizeSettings& settings);

nlohmann::json to_json(const OptimizeResult& result);

struct NoiseEstimate
{
  std::vector<double> x;
  std::vector<double> values; ///< one per replicate 0, 1, ...
  double mean = 0;
  double standard_deviation = 0; ///< of one evaluation (sample, n - 1): the noise sigma
  double standard_error = 0;     ///< of the mean: standard_deviation / sqrt(n)
};

/// The score at x under replicates 0 .. samples-1 (samples >= 2).
NoiseEstimate estimate_noise(const ReplicateScore& score, std::span<const double> x, int samples);

nlohmann::json to_json(const NoiseEstimate& estimate);

enum class Verdict
{
  not_stationary, ///< some |g_i| >= 2 sigma_g_i
  local_minimum,  ///< stationary, smallest Hessian eigenvalue > 2 of its sigma
  local_maximum,  ///< stationary, largest eigenvalue < -2 of its sigma
  saddle,         ///< stationary, eigenvalues of both signs beyond 2 sigma
  undetermined    ///< stationary, but the curvature's sign is within the noise
};

std::string verdict_name(Verdict verdict);

struct Derivatives
{
  std::vector<double> x, steps;
  double value = 0;
  double noise = 0;
  Eigen::VectorXd gradient, gradient_sigma;
  Eigen::MatrixXd hessian, hessian_sigma;
  Eigen::VectorXd eigenvalues, eigenvalue_sigma; ///< of the Hessian, ascending
  Verdict verdict = Verdict::undetermined;
  int evaluations = 0; ///< 2 n^2 + 1
};

/// Central differences at x with steps h_i (x +- h_i e_i +- h_j e_j are
/// evaluated): g_i, H_ii, H_ij, each with the sigma propagated from the
/// noise (g: noise sqrt(2) / (2 h_i); H_ii: noise sqrt(6) / h_i^2; H_ij:
/// noise / (2 h_i h_j)), the eigenvalues' sigma to first order, and the
/// verdict. noise_sigma must be positive: for an exact score give its rounding
/// level. InputError for bad steps or noise.
Derivatives finite_differences(const Score& score, std::span<const double> x, std::span<const double> steps,
                               double noise_sigma);

nlohmann::json to_json(const Derivatives& derivatives);

struct StepChoice
{
  std::vector<double> pilot_steps; ///< as used, clipped to the box
  std::vector<double> third_derivative, third_derivative_sigma; ///< f''' per axis at the pilot steps
  std::vector<double> steps; ///< for finite_differences
  int evaluations = 0;       ///< 4 per axis
};

/// Steps that balance a central difference's truncation error h^2 |f'''| / 6
/// against its noise error noise / (sqrt(2) h): h_i = (3 noise / (sqrt(2)
/// |f'''_i|))^(1/3), with f'''_i measured at pilot step p_i (x +- p_i, x +-
/// 2 p_i) and taken as at least 2 of its sigma (so an unresolved f''' gives
/// h_i ~ 0.9 p_i); every step kept inside the box. InputError if x lies on a
/// bound of a parameter (central differences need room on both sides).
StepChoice balanced_steps(const Score& score, std::span<const double> x, const Box& box, double noise_sigma,
                          std::span<const double> pilot_steps);

nlohmann::json to_json(const StepChoice& choice);

struct AxisSweep
{
  int axis = 0;
  std::vector<double> coordinates; ///< of the axis, evenly from its lower to its upper bound
  std::vector<double> values;
};

/// The score at `points` (>= 2) evenly spaced values of each free parameter of
/// the box, the others held at x.
std::vector<AxisSweep> sweep_axes(const Score& score, std::span<const double> x, const Box& box, int points);

nlohmann::json to_json(const std::vector<AxisSweep>& sweeps);
} // namespace rollcheck::study::optimize
