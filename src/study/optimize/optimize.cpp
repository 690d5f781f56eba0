#include "study/optimize/optimize.h"
#include "core/json_number.h"
#include "core/error.h"
#include "study/body_scores/score_body.h"
#include "study/optimize/json_numbers.h"
#include "core/named_values.h"
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <cmath>
#include <exception>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <map>
#include <nlopt.hpp>

namespace rollcheck::study::optimize
{
namespace
{
std::string point_text(std::span<const double> x) { return fmt::format("({})", fmt::join(x, ", ")); }

/// score(x), with any failure turned into a ComputationError naming the point.
/// `what` says which evaluation it was (a replicate, ...) when not only x.
template <class Evaluate>
double guarded(Evaluate&& f, std::span<const double> x, const std::string& what = {})
{
  double value;
  try
  {
    value = f();
  }
  catch (const std::exception& e)
  {
    throw ComputationError(fmt::format("the score failed at x = {}{}: {}", point_text(x), what, e.what()));
  }
  if (std::isnan(value))
    throw ComputationError(fmt::format("the score is NaN at x = {}{}", point_text(x), what));
  return value;
}

double evaluate(const Score& score, std::span<const double> x)
{
  return guarded([&] { return score(x); }, x);
}

void check_box(const Box& box, std::size_t dimension, const std::string& context)
{
  if (box.lower.size() != dimension || box.upper.size() != dimension)
    throw InputError(fmt::format("{}: the box has {} lower and {} upper bounds for {} parameters", context,
                                 box.lower.size(), box.upper.size(), dimension));
  for (std::size_t i = 0; i < dimension; ++i)
    if (!std::isfinite(box.lower[i]) || !std::isfinite(box.upper[i]) || box.lower[i] > box.upper[i])
      throw InputError(fmt::format("{}: the box of parameter {} is [{}, {}]; give finite bounds, lower <= upper",
                                   context, i, box.lower[i], box.upper[i]));
}

void check_inside(std::span<const double> x, const Box& box, const std::string& context)
{
  check_box(box, x.size(), context);
  for (std::size_t i = 0; i < x.size(); ++i)
    if (!(x[i] >= box.lower[i] && x[i] <= box.upper[i]))
      throw InputError(fmt::format("{}: parameter {} = {} lies outside its box [{}, {}]", context, i, x[i],
                                   box.lower[i], box.upper[i]));
}

void check_noise(double noise, const std::string& context)
{
  if (!(noise > 0) || !std::isfinite(noise))
    throw InputError(fmt::format("{}: the noise sigma must be positive and finite, got {} (measure it with "
                                 "estimate_noise; for an exact score give its rounding level)",
                                 context, noise));
}

bool is_local(Method method)
{
  return method == Method::bobyqa || method == Method::nelder_mead || method == Method::sbplx;
}

nlopt::algorithm algorithm(Method method)
{
  switch (method)
  {
  case Method::bobyqa:
    return nlopt::LN_BOBYQA;
  case Method::nelder_mead:
    return nlopt::LN_NELDERMEAD;
  case Method::sbplx:
    return nlopt::LN_SBPLX;
  case Method::direct_l:
    return nlopt::GN_DIRECT_L;
  case Method::crs2_lm:
    return nlopt::GN_CRS2_LM;
  case Method::multistart:
    break;
  }
  throw std::logic_error("multistart is not one NLopt algorithm");
}

std::string result_name(nlopt::result result)
{
  switch (result)
  {
  case nlopt::STOPVAL_REACHED:
    return "stopval reached";
  case nlopt::FTOL_REACHED:
    return "ftol reached";
  case nlopt::XTOL_REACHED:
    return "xtol reached";
  case nlopt::MAXEVAL_REACHED:
    return "max evaluations reached";
  case nlopt::MAXTIME_REACHED:
    return "max time reached";
  default:
    return "success";
  }
}

/// Halton point `index` (>= 1) of the unit cube, radical inverses in the first primes.
std::vector<double> halton(int index, std::size_t dimension)
{
  constexpr std::array<int, 12> primes{2, 3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37};
  std::vector<double> u(dimension);
  for (std::size_t d = 0; d < dimension; ++d)
  {
    double f = 1, r = 0;
    for (int i = index; i > 0; i /= primes[d])
    {
      f /= primes[d];
      r += f * (i % primes[d]);
    }
    u[d] = r;
  }
  return u;
}

/// The search's record: the score over the free parameters (the fixed ones at
/// the start's values), each distinct point evaluated once, in order.
class Search
{
public:
  Search(const Score& score, const OptimizeSettings& s) : score_(score), start_(s.start), box_(s.box)
  {
    for (std::size_t i = 0; i < s.start.size(); ++i)
      if (s.box.lower[i] < s.box.upper[i])
        free_.push_back(i);
  }

  std::size_t free_dimension() const { return free_.size(); }

  /// The free parameters' box, or the point `u` of the unit cube mapped into it.
  std::vector<double> free_lower() const { return free_part(box_.lower); }
  std::vector<double> free_upper() const { return free_part(box_.upper); }
  std::vector<double> free_start() const { return free_part(start_); }
  std::vector<double> free_point(const std::vector<double>& u) const
  {
    std::vector<double> x(free_.size());
    for (std::size_t k = 0; k < free_.size(); ++k)
      x[k] = box_.lower[free_[k]] + u[k] * (box_.upper[free_[k]] - box_.lower[free_[k]]);
    return x;
  }

  double value(const std::vector<double>& free_x)
  {
    std::vector<double> x = start_;
    for (std::size_t k = 0; k < free_.size(); ++k)
      x[free_[k]] = free_x[k];
    if (const auto known = memo_.find(x); known != memo_.end())
      return known->second;
    const double f = evaluate(score_, x);
    memo_.emplace(x, f);
    history_.push_back({std::move(x), f});
    return f;
  }

  const std::vector<Evaluation>& history() const { return history_; }

private:
  std::vector<double> free_part(const std::vector<double>& full) const
  {
    std::vector<double> x;
    for (const std::size_t i : free_)
      x.push_back(full[i]);
    return x;
  }

  const Score& score_;
  std::vector<double> start_;
  Box box_;
  std::vector<std::size_t> free_;
  std::map<std::vector<double>, double> memo_;
  std::vector<Evaluation> history_;
};

/// One NLopt run of `method` from x (free parameters) with at most `budget`
/// objective calls; its stop reason. A failed score ends the search with its
/// ComputationError (NLopt's C++ wrapper would swallow it as a forced stop).
std::string run_nlopt(Search& search, Method method, std::vector<double> x, int budget, const OptimizeSettings& s)
{
  if (budget < 1) // NLopt reads maxeval 0 as "no limit"
    return "evaluation budget spent";
  nlopt::opt opt(algorithm(method), static_cast<unsigned>(search.free_dimension()));
  const std::vector<double> lower = search.free_lower(), upper = search.free_upper();
  std::vector<double> xtol(lower.size());
  for (std::size_t k = 0; k < lower.size(); ++k)
    xtol[k] = s.xtol * (upper[k] - lower[k]);
  opt.set_lower_bounds(lower);
  opt.set_upper_bounds(upper);
  opt.set_xtol_abs(xtol);
  opt.set_maxeval(budget);
  if (method == Method::crs2_lm)
    nlopt::srand(s.seed);

  struct Context
  {
    Search* search;
    std::exception_ptr failure;
  } context{&search, nullptr};
  opt.set_min_objective(
      [](const std::vector<double>& free_x, std::vector<double>&, void* data) {
        auto* c = static_cast<Context*>(data);
        try
        {
          return c->search->value(free_x);
        }
        catch (const ComputationError&)
        {
          c->failure = std::current_exception();
          throw nlopt::forced_stop();
        }
      },
      &context);
  double f = 0;
  try
  {
    return result_name(opt.optimize(x, f));
  }
  catch (const nlopt::forced_stop&)
  {
    if (context.failure)
      std::rethrow_exception(context.failure);
    throw;
  }
  catch (const nlopt::roundoff_limited&)
  {
    // The noise stopped the progress; the best point so far stands.
    return "roundoff limited";
  }
  catch (const std::exception& e)
  {
    throw ComputationError(fmt::format("NLopt {} failed: {}", method_name(method), e.what()));
  }
}

void validate(const OptimizeSettings& s)
{
  if (s.start.empty())
    throw InputError("optimize: no start point");
  check_inside(s.start, s.box, "optimize: start");
  if (s.max_evaluations < 1)
    throw InputError(fmt::format("optimize: max evaluations must be at least 1, got {}", s.max_evaluations));
  if (!(s.noise >= 0) || !std::isfinite(s.noise))
    throw InputError(fmt::format("optimize: the noise sigma must be >= 0 and finite, got {}", s.noise));
  if (!(s.xtol > 0) || !std::isfinite(s.xtol))
    throw InputError(fmt::format("optimize: xtol must be positive, got {}", s.xtol));
  if (s.method != Method::multistart)
    return;
  if (!is_local(s.local_method))
    throw InputError(fmt::format("optimize: multistart runs a local method (bobyqa, nelder-mead, sbplx), not {}",
                                 method_name(s.local_method)));
  if (s.starts < 1)
    throw InputError(fmt::format("optimize: multistart needs at least 1 start, got {}", s.starts));
  if (s.start.size() > 12)
    throw InputError(fmt::format("optimize: multistart's Halton points cover at most 12 parameters, got {}",
                                 s.start.size()));
}

/// Runs of the local method from the start, then from Halton points 1, 2, ...
/// of the box, sharing the remaining budget evenly.
std::string multistart(Search& search, const OptimizeSettings& s)
{
  std::vector<std::string> reasons;
  for (int run = 0; run < s.starts; ++run)
  {
    const std::vector<double> x
        = run == 0 ? search.free_start() : search.free_point(halton(run, search.free_dimension()));
    const int budget = (s.max_evaluations - static_cast<int>(search.history().size())) / (s.starts - run);
    reasons.push_back(fmt::format("{} from {}: {}", method_name(s.local_method), point_text(x),
                                  run_nlopt(search, s.local_method, x, budget, s)));
  }
  return fmt::format("{}", fmt::join(reasons, "; "));
}

nlohmann::json rows(const Eigen::MatrixXd& m)
{
  nlohmann::json j = nlohmann::json::array();
  for (Eigen::Index i = 0; i < m.rows(); ++i)
    j.push_back(numbers(Eigen::VectorXd(m.row(i).transpose())));
  return j;
}
} // namespace

const std::vector<std::pair<std::string, Method>>& method_names()
{
  static const std::vector<std::pair<std::string, Method>> names{
      {"bobyqa", Method::bobyqa},     {"nelder-mead", Method::nelder_mead}, {"sbplx", Method::sbplx},
      {"direct-l", Method::direct_l}, {"crs2-lm", Method::crs2_lm},         {"multistart", Method::multistart}};
  return names;
}

std::string method_name(Method method) { return name_of(method_names(), method, "optimisation method"); }

OptimizeResult minimize(const Score& score, const OptimizeSettings& s)
{
  validate(s);
  Search search(score, s);
  search.value(search.free_start()); // the start is the first evaluation, whatever the method
  std::string stop_reason;
  if (search.free_dimension() == 0)
    stop_reason = "no free parameter";
  else if (s.method == Method::multistart)
    stop_reason = multistart(search, s);
  else
    stop_reason = run_nlopt(search, s.method, search.free_start(), s.max_evaluations - 1, s);

  const std::vector<Evaluation>& history = search.history();
  const auto best = std::min_element(history.begin(), history.end(),
                                     [](const Evaluation& a, const Evaluation& b) { return a.value < b.value; });
  OptimizeResult r;
  r.method = s.method;
  r.start = s.start;
  r.start_value = history.front().value;
  r.best_x = best->x;
  r.best_value = best->value;
  r.evaluations = static_cast<int>(history.size());
  r.history = history;
  r.stop_reason = stop_reason;
  r.noise = s.noise;
  r.significance_threshold
      = s.noise * (2 * std::sqrt(2.0) + std::sqrt(2 * std::log(static_cast<double>(r.evaluations))));
  r.beats_start = r.start_value - r.best_value > r.significance_threshold;
  return r;
}

nlohmann::json to_json(const OptimizeResult& r)
{
  nlohmann::json history = nlohmann::json::array();
  for (const Evaluation& e : r.history)
    history.push_back({{"x", numbers(e.x)}, {"value", json_number(e.value)}});
  return {{"method", method_name(r.method)},
          {"start", numbers(r.start)},
          {"start_value", json_number(r.start_value)},
          {"best_x", numbers(r.best_x)},
          {"best_value", json_number(r.best_value)},
          {"improvement", json_number(r.start_value - r.best_value)},
          {"noise_sigma", json_number(r.noise)},
          {"significance_threshold", json_number(r.significance_threshold)},
          {"beats_start", r.beats_start},
          {"evaluations", r.evaluations},
          {"stop_reason", r.stop_reason},
          {"history", history}};
}

NoiseEstimate estimate_noise(const ReplicateScore& score, std::span<const double> x, int samples)
{
  if (samples < 2)
    throw InputError(fmt::format("noise estimate: at least 2 samples are needed for a spread, got {}", samples));
  NoiseEstimate e;
  e.x.assign(x.begin(), x.end());
  for (int replicate = 0; replicate < samples; ++replicate)
    e.values.push_back(
        guarded([&] { return score(x, replicate); }, x, fmt::format(", replicate {}", replicate)));
  const Eigen::Map<const Eigen::VectorXd> v(e.values.data(), samples);
  e.mean = v.mean();
  e.standard_deviation = std::sqrt((v.array() - e.mean).square().sum() / (samples - 1));
  e.standard_error = e.standard_deviation / std::sqrt(static_cast<double>(samples));
  return e;
}

nlohmann::json to_json(const NoiseEstimate& e)
{
  return {{"x", numbers(e.x)},
          {"values", numbers(e.values)},
          {"mean", json_number(e.mean)},
          {"standard_deviation", json_number(e.standard_deviation)},
          {"standard_error", json_number(e.standard_error)}};
}

std::string verdict_name(Verdict verdict)
{
  static const std::vector<std::pair<std::string, Verdict>> names{{"not stationary", Verdict::not_stationary},
                                                                  {"local minimum", Verdict::local_minimum},
                                                                  {"local maximum", Verdict::local_maximum},
                                                                  {"saddle", Verdict::saddle},
                                                                  {"undetermined", Verdict::undetermined}};
  return name_of(names, verdict, "verdict");
}

Derivatives finite_differences(const Score& score, std::span<const double> x, std::span<const double> steps,
                               double noise_sigma)
{
  const std::size_t n = x.size();
  if (n == 0 || steps.size() != n)
    throw InputError(fmt::format("finite differences: {} steps for {} parameters", steps.size(), n));
  for (std::size_t i = 0; i < n; ++i)
    if (!(steps[i] > 0) || !std::isfinite(steps[i]))
      throw InputError(fmt::format("finite differences: the step of parameter {} must be positive, got {}", i,
                                   steps[i]));
  check_noise(noise_sigma, "finite differences");

  Derivatives d;
  d.x.assign(x.begin(), x.end());
  d.steps.assign(steps.begin(), steps.end());
  d.noise = noise_sigma;
  // f at x + a h_i e_i + b h_j e_j.
  const auto f = [&](std::size_t i, double a, std::size_t j, double b) {
    std::vector<double> p = d.x;
    p[i] += a * steps[i];
    p[j] += b * steps[j];
    ++d.evaluations;
    return evaluate(score, p);
  };
  d.value = f(0, 0, 0, 0);
  d.gradient.resize(n);
  d.gradient_sigma.resize(n);
  d.hessian.resize(n, n);
  d.hessian_sigma.resize(n, n);
  const double sigma = noise_sigma;
  for (std::size_t i = 0; i < n; ++i)
  {
    const double h = steps[i], plus = f(i, 1, i, 0), minus = f(i, -1, i, 0);
    d.gradient[i] = (plus - minus) / (2 * h);
    d.gradient_sigma[i] = sigma * std::sqrt(2.0) / (2 * h);
    d.hessian(i, i) = (plus - 2 * d.value + minus) / (h * h);
    d.hessian_sigma(i, i) = sigma * std::sqrt(6.0) / (h * h);
    for (std::size_t j = 0; j < i; ++j)
    {
      const double hij = steps[i] * steps[j];
      const double corners = f(i, 1, j, 1) - f(i, 1, j, -1) - f(i, -1, j, 1) + f(i, -1, j, -1);
      d.hessian(i, j) = d.hessian(j, i) = corners / (4 * hij);
      d.hessian_sigma(i, j) = d.hessian_sigma(j, i) = sigma / (2 * hij);
    }
  }

  // Each eigenvalue is, to first order, v^T H v: a linear combination of the
  // evaluated values, whose coefficients give its sigma exactly. With
  // a_i = v_i^2 / h_i^2: f(x) enters with -2 sum a_i, f(x +- h_i e_i) with
  // a_i each, the four corners of (i, j) with +- sqrt(a_i a_j) / 2 each.
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(d.hessian);
  d.eigenvalues = eigen.eigenvalues();
  d.eigenvalue_sigma.resize(n);
  const Eigen::ArrayXd h = Eigen::Map<const Eigen::ArrayXd>(steps.data(), static_cast<Eigen::Index>(n));
  for (Eigen::Index k = 0; k < d.eigenvalues.size(); ++k)
  {
    const Eigen::ArrayXd a = eigen.eigenvectors().col(k).array().square() / h.square();
    const double cross = (a.sum() * a.sum() - a.square().sum()) / 2; // sum over i < j of a_i a_j
    d.eigenvalue_sigma[k] = sigma * std::sqrt(4 * a.sum() * a.sum() + 2 * a.square().sum() + cross);
  }

  const bool stationary = (d.gradient.array().abs() < 2 * d.gradient_sigma.array()).all();
  const bool positive = (d.eigenvalues.array() > 2 * d.eigenvalue_sigma.array()).any();
  const bool negative = (d.eigenvalues.array() < -2 * d.eigenvalue_sigma.array()).any();
  if (!stationary)
    d.verdict = Verdict::not_stationary;
  else if (d.eigenvalues[0] > 2 * d.eigenvalue_sigma[0])
    d.verdict = Verdict::local_minimum;
  else if (d.eigenvalues[n - 1] < -2 * d.eigenvalue_sigma[n - 1])
    d.verdict = Verdict::local_maximum;
  else if (positive && negative)
    d.verdict = Verdict::saddle;
  else
    d.verdict = Verdict::undetermined;
  return d;
}

nlohmann::json to_json(const Derivatives& d)
{
  return {{"x", numbers(d.x)},
          {"steps", numbers(d.steps)},
          {"value", json_number(d.value)},
          {"noise_sigma", json_number(d.noise)},
          {"gradient", numbers(d.gradient)},
          {"gradient_sigma", numbers(d.gradient_sigma)},
          {"hessian", rows(d.hessian)},
          {"hessian_sigma", rows(d.hessian_sigma)},
          {"hessian_eigenvalues", numbers(d.eigenvalues)},
          {"hessian_eigenvalue_sigma", numbers(d.eigenvalue_sigma)},
          {"verdict", verdict_name(d.verdict)},
          {"evaluations", d.evaluations}};
}

StepChoice balanced_steps(const Score& score, std::span<const double> x, const Box& box, double noise_sigma,
                          std::span<const double> pilot_steps)
{
  check_inside(x, box, "step choice: x");
  check_noise(noise_sigma, "step choice");
  if (pilot_steps.size() != x.size())
    throw InputError(fmt::format("step choice: {} pilot steps for {} parameters", pilot_steps.size(), x.size()));
  StepChoice c;
  for (std::size_t i = 0; i < x.size(); ++i)
  {
    const double room = std::min(x[i] - box.lower[i], box.upper[i] - x[i]);
    if (!(room > 0))
      throw InputError(fmt::format("step choice: parameter {} = {} lies on a bound of [{}, {}]; central "
                                   "differences need room on both sides",
                                   i, x[i], box.lower[i], box.upper[i]));
    if (!(pilot_steps[i] > 0))
      throw InputError(fmt::format("step choice: the pilot step of parameter {} must be positive, got {}", i,
                                   pilot_steps[i]));
    const double p = std::min(pilot_steps[i], room / 2);
    const auto f = [&](double a) {
      std::vector<double> q(x.begin(), x.end());
      q[i] += a * p;
      ++c.evaluations;
      return evaluate(score, q);
    };
    const double third = (f(2) - 2 * f(1) + 2 * f(-1) - f(-2)) / (2 * p * p * p);
    const double third_sigma = noise_sigma * std::sqrt(10.0) / (2 * p * p * p);
    const double curvature = std::max(std::abs(third), 2 * third_sigma);
    c.pilot_steps.push_back(p);
    c.third_derivative.push_back(third);
    c.third_derivative_sigma.push_back(third_sigma);
    c.steps.push_back(std::min(std::cbrt(3 * noise_sigma / (std::sqrt(2.0) * curvature)), room));
  }
  return c;
}

nlohmann::json to_json(const StepChoice& c)
{
  return {{"pilot_steps", numbers(c.pilot_steps)},
          {"third_derivative", numbers(c.third_derivative)},
          {"third_derivative_sigma", numbers(c.third_derivative_sigma)},
          {"steps", numbers(c.steps)},
          {"evaluations", c.evaluations}};
}

std::vector<AxisSweep> sweep_axes(const Score& score, std::span<const double> x, const Box& box, int points)
{
  check_inside(x, box, "sweep: x");
  if (points < 2)
    throw InputError(fmt::format("sweep: at least 2 points per axis, got {}", points));
  std::vector<AxisSweep> sweeps;
  for (std::size_t i = 0; i < x.size(); ++i)
  {
    if (box.lower[i] == box.upper[i])
      continue;
    AxisSweep s;
    s.axis = static_cast<int>(i);
    std::vector<double> p(x.begin(), x.end());
    for (int k = 0; k < points; ++k)
    {
      p[i] = box.lower[i] + (box.upper[i] - box.lower[i]) * k / (points - 1);
      s.coordinates.push_back(p[i]);
      s.values.push_back(evaluate(score, p));
    }
    sweeps.push_back(std::move(s));
  }
  return sweeps;
}

nlohmann::json to_json(const std::vector<AxisSweep>& sweeps)
{
  nlohmann::json j = nlohmann::json::array();
  for (const AxisSweep& s : sweeps)
    j.push_back({{"axis", s.axis}, {"coordinates", numbers(s.coordinates)}, {"values", numbers(s.values)}});
  return j;
}
} // namespace rollcheck::study::optimize
