#include "study/optimize/optimize_family.h"
#include "core/error.h"
#include "core/json_number.h"
#include "geometry/convex_hull.h"
#include "oracle/parallel_for.h"
#include "study/optimize/json_numbers.h"
#include "core/named_values.h"
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <limits>
#include <map>
#include <set>
#include <tuple>

namespace rollcheck::study::optimize
{
namespace
{
struct AxisNames
{
  const char *parameter, *min, *max, *start;
};
constexpr std::array<AxisNames, 3> axis_names{{{"theta_deg", "theta_min_deg", "theta_max_deg", "theta_start_deg"},
                                               {"offset", "offset_min", "offset_max", "offset_start"},
                                               {"ratio", "ratio_min", "ratio_max", "ratio_start"}}};

std::array<const FamilyAxis*, 3> axes(const FamilySearchSettings& s) { return {&s.theta_deg, &s.offset, &s.ratio}; }

std::vector<double> start_of(const FamilySearchSettings& s)
{
  return {s.theta_deg.start, s.offset.start, s.ratio.start};
}

Box box_of(const FamilySearchSettings& s)
{
  return {{s.theta_deg.min, s.offset.min, s.ratio.min}, {s.theta_deg.max, s.offset.max, s.ratio.max}};
}

/// Radical inverse of `index` in base `base`: the replicate's jitter direction, evenly spread.
double radical_inverse(int index, int base)
{
  double f = 1, r = 0;
  for (int i = index; i > 0; i /= base)
  {
    f /= base;
    r += f * (i % base);
  }
  return r;
}

std::string genome_text(std::span<const double> x) { return fmt::format("({})", fmt::join(x, ", ")); }

/// The runs (genome, replicate) of body_scores::score_body, each run once (or recalled from
/// the settings' store), and the search's score formed from them. Runs asked
/// for together are run in parallel.
class Evaluator
{
public:
  explicit Evaluator(const FamilySearchSettings& s)
      : s_(s), averaged_(s.oracle == body_scores::Oracle::rigid ? s.replicates : 1), meshes_(s)
  {
  }

  /// Runs replicates 0 .. replicates-1 of every point not run yet.
  void run(const std::vector<std::vector<double>>& points, int replicates)
  {
    std::vector<std::pair<std::vector<double>, int>> missing;
    for (const std::vector<double>& x : points)
      for (int r = 0; r < replicates; ++r)
      {
        if (runs_.contains({x, r}) || std::find(missing.begin(), missing.end(), std::pair{x, r}) != missing.end())
          continue;
        if (const std::optional<double> value = recall(x, r))
          runs_.emplace(std::pair{x, r}, *value);
        else
          missing.emplace_back(x, r);
      }
    std::vector<double> values(missing.size());
    // FEM-SDS solves are collective over the MPI ranks: one body at a time.
    const unsigned threads = is_fem_sds(s_.score) ? 1u : s_.threads;
    oracle::parallel_for(missing.size(), threads, [&](std::size_t k) {
      const auto& [x, r] = missing[k];
      try
      {
        values[k] = replicate_score(s_, meshes_, x, r);
      }
      catch (const std::exception& e)
      {
        throw ComputationError(fmt::format("scoring genome {} (replicate {}): {}", genome_text(x), r, e.what()));
      }
    });
    std::vector<OracleRun> finished;
    for (std::size_t k = 0; k < missing.size(); ++k)
    {
      runs_.emplace(missing[k], values[k]);
      finished.push_back({missing[k].first, missing[k].second, values[k]});
    }
    oracle_runs_ += static_cast<long>(finished.size());
    if (s_.run_store.record && !finished.empty())
      s_.run_store.record(finished);
  }

  double replicate(std::span<const double> x, int r)
  {
    const std::vector<double> p(x.begin(), x.end());
    run({p}, r + 1);
    return runs_.at({p, r});
  }

  /// family_score from the runs: the mean of the averaged replicates, in order.
  double score(std::span<const double> x)
  {
    const std::vector<double> p(x.begin(), x.end());
    run({p}, averaged_);
    double sum = 0;
    for (int r = 0; r < averaged_; ++r)
      sum += runs_.at({p, r});
    scored_.insert(p);
    return sum / averaged_;
  }

  void prefetch(const std::vector<std::vector<double>>& points) { run(points, averaged_); }
  long scored() const { return static_cast<long>(scored_.size()); }
  long oracle_runs() const { return oracle_runs_; }
  long recalled_runs() const { return recalled_runs_; }
  FamilyMeshes& meshes() { return meshes_; }

private:
  /// The store's value of run (x, r), if it has one.
  std::optional<double> recall(std::span<const double> x, int r)
  {
    std::optional<double> value = s_.run_store.recall ? s_.run_store.recall(x, r) : std::nullopt;
    recalled_runs_ += value.has_value();
    return value;
  }

  const FamilySearchSettings& s_;
  int averaged_;
  FamilyMeshes meshes_;
  long oracle_runs_ = 0, recalled_runs_ = 0;
  std::map<std::pair<std::vector<double>, int>, double> runs_;
  std::set<std::vector<double>> scored_;
};

/// The points balanced_steps evaluates (x +- p_i, x +- 2 p_i, its arithmetic).
std::vector<std::vector<double>> pilot_points(std::span<const double> x, const Box& box, std::span<const double> pilot)
{
  std::vector<std::vector<double>> points;
  for (std::size_t i = 0; i < x.size(); ++i)
  {
    const double room = std::min(x[i] - box.lower[i], box.upper[i] - x[i]);
    const double p = std::min(pilot[i], room / 2);
    for (const double a : {2.0, 1.0, -1.0, -2.0})
    {
      std::vector<double> q(x.begin(), x.end());
      q[i] += a * p;
      points.push_back(std::move(q));
    }
  }
  return points;
}

/// The points finite_differences evaluates (its arithmetic: x + a h_i e_i + b h_j e_j).
std::vector<std::vector<double>> stencil_points(std::span<const double> x, std::span<const double> h)
{
  const auto at = [&](std::size_t i, double a, std::size_t j, double b) {
    std::vector<double> p(x.begin(), x.end());
    p[i] += a * h[i];
    p[j] += b * h[j];
    return p;
  };
  std::vector<std::vector<double>> points{at(0, 0, 0, 0)};
  for (std::size_t i = 0; i < x.size(); ++i)
  {
    points.push_back(at(i, 1, i, 0));
    points.push_back(at(i, -1, i, 0));
    for (std::size_t j = 0; j < i; ++j)
      for (const double a : {1.0, -1.0})
        for (const double b : {1.0, -1.0})
          points.push_back(at(i, a, j, b));
  }
  return points;
}

/// The points sweep_axes evaluates.
std::vector<std::vector<double>> sweep_points(std::span<const double> x, const Box& box, int n)
{
  std::vector<std::vector<double>> points;
  for (std::size_t i = 0; i < x.size(); ++i)
    for (int k = 0; k < n && box.lower[i] < box.upper[i]; ++k)
    {
      std::vector<double> p(x.begin(), x.end());
      p[i] = box.lower[i] + (box.upper[i] - box.lower[i]) * k / (n - 1);
      points.push_back(std::move(p));
    }
  return points;
}

/// The parameter of x on a bound (fixed parameters included), if any: central differences need room.
std::optional<std::size_t> on_bound(std::span<const double> x, const Box& box)
{
  for (std::size_t i = 0; i < x.size(); ++i)
    if (x[i] <= box.lower[i] || x[i] >= box.upper[i])
      return i;
  return std::nullopt;
}

/// Steps balanced against the noise at x, then the gradient and Hessian there;
/// each phase's points scored in parallel first.
std::pair<StepChoice, Derivatives> derivatives_at(Evaluator& ev, const Score& score, std::span<const double> x,
                                                  const Box& box, double noise, double pilot_fraction)
{
  std::vector<double> pilot;
  for (std::size_t i = 0; i < x.size(); ++i)
    pilot.push_back(pilot_fraction * (box.upper[i] - box.lower[i]));
  ev.prefetch(pilot_points(x, box, pilot));
  StepChoice steps = balanced_steps(score, x, box, noise, pilot);
  ev.prefetch(stencil_points(x, steps.steps));
  Derivatives d = finite_differences(score, x, steps.steps, noise);
  return {std::move(steps), std::move(d)};
}

double score_of(const body_scores::BodyScores& r, FamilyScore score, std::span<const double> x)
{
  if (score == FamilyScore::uniformity)
    return r.rolling.uniformity;
  const std::optional<double>& v = score == FamilyScore::cds ? r.scores.cds : r.scores.sds;
  if (!v)
    throw ComputationError(fmt::format("no {} at genome {}", score == FamilyScore::cds ? "CDS" : "SDS",
                                       genome_text(x)));
  return *v;
}

std::string nuisance_text(const FamilySearchSettings& s)
{
  const std::string move = fmt::format("the genome moved by {:g} of each box width in a replicate-dependent direction "
                                       "(the spread between points the search cannot resolve)",
                                       s.resolution);
  if (s.oracle == body_scores::Oracle::rigid)
    return move + fmt::format("; the rigid-body runs of a moved genome have lost the nominal run's trajectory within "
                              "the run, so the replicates also sample the oracle's chaotic spread; each score is the "
                              "mean of {} replicates",
                              s.replicates);
  if (is_fem_sds(s.score))
    return move + "; and meshed with 2, -2, 4, -4, ... more points per circle (FEM-SDS's template moves by up to a "
                  "third between meshes of one genome: the true oloid at 96 to 104 points per circle scored 1.28e-05 "
                  "to 1.97e-05; the continuum value's share of that is its own mesh noise); the oracle is "
                  "deterministic: each score is one evaluation";
  return move + "; the oracle is deterministic: each score is one evaluation";
}
} // namespace

const std::vector<std::pair<std::string, FamilyScore>>& family_score_names()
{
  static const std::vector<std::pair<std::string, FamilyScore>> names{
      {"cds", FamilyScore::cds},
      {"sds", FamilyScore::sds},
      {"uniformity", FamilyScore::uniformity},
      {"fem-sds", FamilyScore::fem_sds},
      {"fem-sds-template", FamilyScore::fem_sds_template}};
  return names;
}

const std::vector<std::pair<std::string, DerivativesAt>>& derivatives_at_names()
{
  static const std::vector<std::pair<std::string, DerivativesAt>> names{
      {"both", DerivativesAt::start_and_optimum}, {"start", DerivativesAt::start}, {"none", DerivativesAt::none}};
  return names;
}

bool is_fem_sds(FamilyScore score) { return score == FamilyScore::fem_sds || score == FamilyScore::fem_sds_template; }

void validate(const FamilySearchSettings& s)
{
  // The body's own ranges: theta in (0, 180) deg, d >= 0, rho > 0.
  constexpr std::array<std::array<double, 2>, 3> range{{{0, 180}, {0, std::numeric_limits<double>::infinity()},
                                                        {0, std::numeric_limits<double>::infinity()}}};
  for (std::size_t i = 0; i < 3; ++i)
  {
    const FamilyAxis& a = *axes(s)[i];
    const AxisNames& n = axis_names[i];
    if (!std::isfinite(a.min) || !std::isfinite(a.max) || a.min > a.max)
      throw InputError(fmt::format("optimize: {} = {} must not exceed {} = {}", n.min, a.min, n.max, a.max));
    if (a.min < range[i][0] || (i != 1 && a.min == range[i][0]) || a.max >= range[i][1])
      throw InputError(fmt::format("optimize: {} .. {} = [{}, {}] leaves the family's range of {}", n.min, n.max,
                                   a.min, a.max, n.parameter));
    if (!(a.start >= a.min && a.start <= a.max))
      throw InputError(fmt::format("optimize: {} = {} lies outside [{} = {}, {} = {}]", n.start, a.start, n.min,
                                   a.min, n.max, a.max));
  }
  const bool rolls = s.score == FamilyScore::uniformity || is_fem_sds(s.score);
  if (rolls != (s.oracle == body_scores::Oracle::rolling))
    throw InputError("optimize: the scores uniformity, fem-sds and fem-sds-template need oracle rolling, and cds or "
                     "sds the approx or rigid oracle");
  if (is_fem_sds(s.score) && !s.fem_sds_score)
    throw InputError("optimize: the score fem-sds is computed by rollcheck-fem (study/loop_scores/fem_sds_family.h)");
  if (s.replicates < 2)
    throw InputError(fmt::format("optimize: replicates must be at least 2 for a noise estimate, got {}", s.replicates));
  if (s.points < 3)
    throw InputError(fmt::format("optimize: points must be at least 3, got {}", s.points));
  if (!(s.resolution > 0 && s.resolution < 0.5))
    throw InputError(fmt::format("optimize: resolution must lie in (0, 0.5), got {}", s.resolution));
  if (!(s.pilot_step > 0 && s.pilot_step <= 0.25))
    throw InputError(fmt::format("optimize: pilot_step must lie in (0, 0.25], got {}", s.pilot_step));
  if (s.sweep_points < 2)
    throw InputError(fmt::format("optimize: sweep_points must be at least 2, got {}", s.sweep_points));
}

geometry::BodySpec family_body(const FamilySearchSettings& s, std::span<const double> x, int points)
{
  geometry::BodySpec b;
  b.body = "roller";
  b.family = s.family;
  b.genome = {x[0], x[1], x[2], 2};
  b.points = points;
  return b;
}

long hull_faces(const FamilySearchSettings& s, std::span<const double> x, int points)
{
  const geometry::BodySpec b = family_body(s, x, points);
  return geometry::convex_hull(geometry::roller_points(b.genome, b.family, b.radius_m, b.points)).faces.rows();
}

MeshResolution matched_mesh(const FamilySearchSettings& s, std::span<const double> x, long target_faces)
{
  constexpr int least_points = 3, bracket = 2;
  // Each hull once: the guess's bracket often holds `points` itself.
  std::map<int, long> faces{{s.points, hull_faces(s, x, s.points)}};
  const auto mesh = [&](int points) {
    const auto [entry, added] = faces.try_emplace(points);
    if (added)
      entry->second = hull_faces(s, x, points);
    return MeshResolution{points, entry->second};
  };
  // Ties go to `points` itself: other point counts can give the same face
  // count, and the start, meshed at another of them, would change its score.
  const auto closer = [&](const MeshResolution& a, const MeshResolution& b) {
    return std::tuple(std::abs(a.faces - target_faces), a.points != s.points, a.points)
           < std::tuple(std::abs(b.faces - target_faces), b.points != s.points, b.points);
  };
  const int guess =
      std::max(least_points, static_cast<int>(std::lround(double(s.points) * target_faces / faces.at(s.points))));
  MeshResolution best = mesh(guess);
  for (int k = 1, improved_at = 0; k <= improved_at + bracket; ++k)
    for (const int points : {guess - k, guess + k})
    {
      if (points < least_points)
        continue;
      if (const MeshResolution m = mesh(points); closer(m, best))
      {
        best = m;
        improved_at = k;
      }
    }
  return best;
}

FamilyMeshes::FamilyMeshes(const FamilySearchSettings& s)
    : settings_(s), target_faces_(hull_faces(s, start_of(s), s.points))
{
}

int FamilyMeshes::points(std::span<const double> x)
{
  return settings_.match_face_count ? resolution(x).points : settings_.points;
}

MeshResolution FamilyMeshes::resolution(std::span<const double> x)
{
  if (!settings_.match_face_count)
    return {settings_.points, hull_faces(settings_, x, settings_.points)};
  // The first thread to ask for a genome matches it outside the lock, so that
  // a phase's genomes are matched in parallel; the others (a rigid score's
  // replicates of the same genome) wait for its answer.
  std::promise<MeshResolution> promise;
  std::shared_future<MeshResolution> matched;
  bool first;
  {
    const std::lock_guard lock(mutex_);
    const auto [entry, inserted] = matched_.try_emplace(std::vector<double>(x.begin(), x.end()),
                                                        promise.get_future().share());
    matched = entry->second;
    first = inserted;
  }
  if (first)
  {
    try
    {
      promise.set_value(matched_mesh(settings_, x, target_faces_));
    }
    catch (...)
    {
      promise.set_exception(std::current_exception());
    }
  }
  return matched.get();
}

std::vector<double> replicate_genome(const FamilySearchSettings& s, std::span<const double> x, int replicate)
{
  std::vector<double> p(x.begin(), x.end());
  if (replicate == 0)
    return p;
  constexpr std::array<int, 3> bases{2, 3, 5};
  const Box box = box_of(s);
  for (std::size_t i = 0; i < 3; ++i)
  {
    const double direction = 2 * radical_inverse(replicate, bases[i]) - 1;
    p[i] = std::clamp(p[i] + s.resolution * (box.upper[i] - box.lower[i]) * direction, box.lower[i], box.upper[i]);
  }
  return p;
}

int replicate_mesh_offset(const FamilySearchSettings& s, int replicate)
{
  if (!is_fem_sds(s.score) || replicate == 0)
    return 0;
  const int step = 2 * ((replicate + 1) / 2);
  return replicate % 2 == 1 ? step : -step;
}

double replicate_score(const FamilySearchSettings& s, FamilyMeshes& meshes, std::span<const double> x, int replicate)
{
  body_scores::ScoreBodySettings b = s.scoring;
  b.oracle = s.oracle;
  b.compat = s.paper_compat ? oracle::PaperCompat::reference() : oracle::PaperCompat::corrected();
  b.metrics = {false, false, false, false, false};
  b.metrics.cds = s.score == FamilyScore::cds;
  b.metrics.sds = s.score == FamilyScore::sds;
  b.convergence_every = 0;
  b.with_continuum = false; // score_of reads U, CDS or SDS only
  const std::vector<double> p = replicate_genome(s, x, replicate);
  b.body = family_body(s, p, std::max(3, meshes.points(p) + replicate_mesh_offset(s, replicate)));
  if (is_fem_sds(s.score))
    return s.fem_sds_score(b.body);
  return score_of(body_scores::score_body(b), s.score, p);
}

double family_score(const FamilySearchSettings& s, std::span<const double> x)
{
  return Evaluator(s).score(x);
}

FamilySearchResult optimize_family(const FamilySearchSettings& s)
{
  validate(s);
  const auto clock_start = std::chrono::steady_clock::now();
  FamilySearchResult r;
  r.settings = s;
  r.box = box_of(s);
  const std::vector<double> start = start_of(s);
  Evaluator ev(s);
  const Score score = [&ev](std::span<const double> x) { return ev.score(x); };

  ev.run({start}, s.replicates);
  r.noise_replicates = estimate_noise([&ev](std::span<const double> x, int k) { return ev.replicate(x, k); }, start,
                                      s.replicates);
  r.noise_sigma = s.oracle == body_scores::Oracle::rigid ? r.noise_replicates.standard_error
                                            : r.noise_replicates.standard_deviation;
  // Derivatives need a positive sigma: a score exact to rounding gets its rounding level.
  const double fd_noise = std::max({r.noise_sigma, 1e-13 * std::abs(r.noise_replicates.mean),
                                    std::numeric_limits<double>::min()});

  OptimizeSettings o;
  o.method = s.method;
  o.start = start;
  o.box = r.box;
  o.max_evaluations = s.max_evaluations;
  o.noise = r.noise_sigma;
  o.xtol = s.resolution;
  r.search = minimize(score, o);

  const std::string skipped = "not computed: --derivatives " + name_of(derivatives_at_names(), s.derivatives,
                                                                      "derivatives");
  if (s.derivatives == DerivativesAt::none)
    r.start_derivatives_note = skipped;
  else if (const auto i = on_bound(start, r.box))
    r.start_derivatives_note = fmt::format("not computed: {} lies on a bound of its box", axis_names[*i].parameter);
  else
    std::tie(r.start_steps, r.at_start) = derivatives_at(ev, score, start, r.box, fd_noise, s.pilot_step);
  if (s.derivatives != DerivativesAt::start_and_optimum)
    r.best_derivatives_note = skipped;
  else if (const auto i = on_bound(r.search.best_x, r.box))
    r.best_derivatives_note = fmt::format("not computed: {} lies on a bound of its box (a constrained optimum)",
                                          axis_names[*i].parameter);
  else
    std::tie(r.best_steps, r.at_best) = derivatives_at(ev, score, r.search.best_x, r.box, fd_noise, s.pilot_step);

  ev.prefetch(sweep_points(start, r.box, s.sweep_points));
  r.sweeps = sweep_axes(score, start, r.box, s.sweep_points);
  r.target_faces = ev.meshes().target_faces();
  r.start_mesh = ev.meshes().resolution(start);
  r.best_mesh = ev.meshes().resolution(r.search.best_x);
  r.score_evaluations = ev.scored();
  r.oracle_runs = ev.oracle_runs();
  r.recalled_runs = ev.recalled_runs();
  r.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - clock_start).count();
  return r;
}

namespace
{
nlohmann::json derivatives_json(const std::optional<StepChoice>& steps, const std::optional<Derivatives>& d,
                                const std::string& note)
{
  if (!d)
    return {{"verdict", nullptr}, {"note", note}};
  nlohmann::json j = to_json(*d);
  j["step_choice"] = to_json(*steps);
  return j;
}

nlohmann::json mesh_json(const FamilySearchResult& r)
{
  const bool faces = r.settings.match_face_count;
  return {{"matched_resolution", faces ? "faces" : "points"},
          {"points_per_circle", r.settings.points},
          {"target_faces", faces ? nlohmann::json(r.target_faces) : nlohmann::json()},
          {"start", r.start_mesh},
          {"optimum", r.best_mesh},
          {"radius_m", geometry::BodySpec{}.radius_m},
          {"note", faces ? "each body is meshed with the points per generating circle whose hull's face count is "
                           "nearest target_faces, the start's at points_per_circle (ties: points_per_circle itself, else the "
                           "fewer points)"
                         : "every body is meshed with points_per_circle per generating circle; its face count "
                           "moves with the genome"}};
}

nlohmann::json optimum_json(const FamilySearchResult& r)
{
  const OptimizeResult& o = r.search;
  std::vector<double> displacement;
  double distance = 0;
  for (std::size_t i = 0; i < o.best_x.size(); ++i)
  {
    displacement.push_back(o.best_x[i] - o.start[i]);
    const double width = r.box.upper[i] - r.box.lower[i];
    if (width > 0)
      distance += std::pow(displacement.back() / width, 2);
  }
  nlohmann::json j = {{"x", numbers(o.best_x)},
                      {"value", json_number(o.best_value)},
                      {"displacement_from_start", numbers(displacement)},
                      {"distance_from_start_box_units", json_number(std::sqrt(distance))},
                      {"improvement", json_number(o.start_value - o.best_value)},
                      {"significance_threshold", json_number(o.significance_threshold)},
                      {"beats_start", o.beats_start}};
  for (std::size_t i = 0; i < 3; ++i)
    j[axis_names[i].parameter] = json_number(o.best_x[i]);
  return j;
}
} // namespace

nlohmann::json to_json(const FamilySearchResult& r)
{
  const FamilySearchSettings& s = r.settings;
  nlohmann::json noise = to_json(r.noise_replicates);
  noise["sigma"] = json_number(r.noise_sigma);
  noise["nuisance"] = nuisance_text(s);
  nlohmann::json sweeps = to_json(r.sweeps);
  for (nlohmann::json& sweep : sweeps)
    sweep["parameter"] = axis_names[sweep["axis"].get<std::size_t>()].parameter;
  return {{"score", name_of(family_score_names(), s.score, "family score")},
          {"oracle", s.oracle == body_scores::Oracle::rigid ? "rigid" : s.oracle == body_scores::Oracle::approximate ? "approx" : "rolling"},
          {"paper_compat", s.paper_compat},
          {"family", s.family == geometry::RollerFamily::paper ? "paper" : "centre-line"},
          {"parameters", {"theta_deg", "offset", "ratio"}},
          {"mesh", mesh_json(r)},
          {"box", {{"lower", numbers(r.box.lower)}, {"upper", numbers(r.box.upper)}}},
          {"start", numbers(r.search.start)},
          {"start_value", json_number(r.search.start_value)},
          {"noise", noise},
          {"optimum", optimum_json(r)},
          {"verdict_at_start", r.at_start ? nlohmann::json(verdict_name(r.at_start->verdict)) : nlohmann::json()},
          {"derivatives_at_start", derivatives_json(r.start_steps, r.at_start, r.start_derivatives_note)},
          {"derivatives_at_optimum", derivatives_json(r.best_steps, r.at_best, r.best_derivatives_note)},
          {"sweeps", sweeps},
          {"search", to_json(r.search)},
          {"score_evaluations", r.score_evaluations},
          {"oracle_runs", r.oracle_runs},
          {"recalled_runs", r.recalled_runs},
          {"wall_s", r.wall_s}};
}
} // namespace rollcheck::study::optimize
