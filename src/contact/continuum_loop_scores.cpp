#include "contact/continuum_loop_scores.h"
#include "core/error.h"
#include "contact/ruling_load.h"
#include "core/named_values.h"
#include <algorithm>
#include <array>
#include <cmath>
#include <fmt/format.h>
#include <limits>
#include <numbers>
#include <vector>

namespace rollcheck::contact
{
namespace
{
constexpr int n_quantities = ContinuumMoments::quantities;
/// A sample's moments per unit time: the trapezoid rule sums them over the window.
using Rates = ContinuumMoments;

/// integral_0^1 ds / R(s) for R linear from r0 to r1.
double mean_reciprocal_radius(double r0, double r1)
{
  if (std::abs(r1 - r0) <= 1e-9 * std::max(r0, r1))
    return 2 / (r0 + r1);
  return std::log(r1 / r0) / (r1 - r0);
}

/// integral ds / R(s) over a piece of length h where R runs linearly from r0 to r1.
double piece_reciprocal_radius(double r0, double r1, double h) { return h * mean_reciprocal_radius(r0, r1); }

/// The geometric width's second moment of the contact time between two
/// samples, integral L / |sigma'| integral_0^1 ds / R dt: it has a
/// logarithmic singularity in time where a ruling end pivots on a rim
/// (R_0 -> 0), which the trapezoid rule between samples resolves slowly; the
/// samples' L, |sigma'|, R_0 and R_1 are interpolated linearly and the
/// midpoint rule taken on `steps` sub-intervals.
double rigid_time_second_moment(const oracle::RollingSample& a, const oracle::RollingSample& b, double rate_a,
                                double rate_b, double dt, int steps)
{
  const double la = (a.contact_end_m - a.contact_start_m).norm(), lb = (b.contact_end_m - b.contact_start_m).norm();
  double sum = 0;
  for (int k = 0; k < steps; ++k)
  {
    const double w = (k + 0.5) / steps;
    const double length = (1 - w) * la + w * lb, rate = (1 - w) * rate_a + w * rate_b;
    sum += length / rate
           * mean_reciprocal_radius((1 - w) * a.start_radius_m + w * b.start_radius_m,
                                    (1 - w) * a.end_radius_m + w * b.end_radius_m);
  }
  return sum * dt / steps;
}

void add_point(Rates& r, int quantity, double x, double area_weight)
{
  if (!(x > 0))
    return;
  r.area[quantity] += area_weight;
  r.first[quantity] += x * area_weight;
  r.second[quantity] += x * x * area_weight;
  r.max[quantity] = std::max(r.max[quantity], x);
}

/// The rates at one sample, sweeping at `rate` (|sigma'|, rad/s).
Rates sample_rates(const oracle::RollingSample& sample, double rate, const RollingBodyMass& body,
                   const ContinuumLoopSettings& s)
{
  Rates r;
  const double length = (sample.contact_end_m - sample.contact_start_m).norm();
  const double r0 = sample.start_radius_m, r1 = sample.end_radius_m;
  auto radius = [&](double f) { return (1 - f) * r0 + f * r1; };
  const double e_star = s.effective_modulus_pa;
  const bool hertz = s.width == oracle::ContactWidthModel::hertz;
  r.swept = length * rate * (r0 + r1) / 2;
  const RulingLoad load = ruling_load(sample, s.load_rule, s.normal_load_n, body);
  if (!(load.normal_n > 0))
    return r;
  const bool all_scores = !s.accumulated_pressure_only;
  // Contact time: the second moment and the touched area in closed form.
  if (all_scores)
  {
    if (hertz)
    {
      r.second[0] = 16 * load.normal_n / (std::numbers::pi * e_star * rate);
      r.area[0] = length * rate * (load.to - load.from) * radius((load.from + load.to) / 2);
    }
    else
    {
      r.first[0] = length;
      r.area[0] = r.swept; // the second moment: rigid_time_second_moment, between samples
    }
  }
  const double lo = load.from + s.end_margin, hi = load.to - s.end_margin;
  const bool held_ends = lo <= hi;
  auto held = [&](double f) { return held_fraction(f, load.from, load.to, s.end_margin); };
  // The loaded part in three parts, split where the held ends start, so
  // that each part's integrand is smooth; pieces in proportion to length.
  const std::array<double, 4> cuts
      = held_ends ? std::array<double, 4>{load.from, lo, hi, load.to}
                  : std::array<double, 4>{load.from, load.from, load.to, load.to};
  for (int part = 0; part < 3; ++part)
  {
    const double a = cuts[part], b = cuts[part + 1];
    if (!(b > a))
      continue;
    const int n = std::max(1, static_cast<int>(std::ceil(s.pieces * (b - a) / (load.to - load.from))));
    const double h = (b - a) / n, offset = h / (2 * std::sqrt(3.0));
    for (int k = 0; k < n; ++k)
    {
      const double s0 = a + k * h, s1 = s0 + h;
      double accumulated_squared = 0, second_squared = 0; // K^2 at the piece's Gauss points, averaged
      for (const double f : {s0 + h / 2 - offset, s0 + h / 2 + offset})
      {
        const double q = load.line_load(length, f);
        const double weight = h / 2 * length * radius(f) * rate; // dA / dt of this Gauss point
        if (!(q > 0))
          continue;
        if (all_scores && hertz)
        {
          const double rho = 2 * std::sqrt(4 * q * radius(f) / (std::numbers::pi * e_star)) / (rate * radius(f));
          r.first[0] += rho * weight;
          r.max[0] = std::max(r.max[0], rho);
        }
        else if (all_scores)
          r.max[0] = std::max(r.max[0], 1 / (rate * radius(f)));
        // Between the held ends (the middle part) a point is held where it is.
        const bool middle = held_ends && part == 1;
        const double f_held = middle ? f : held(f), r_held = radius(f_held);
        const double q_held = middle ? q : load.line_load(length, f_held);
        const double load_ratio = q_held / (e_star * r_held);
        r.load_ratio_min = std::min(r.load_ratio_min, load_ratio);
        r.load_ratio_max = std::max(r.load_ratio_max, load_ratio);
        const std::array<double, 2> g = s.pressure_factors ? s.pressure_factors(load_ratio)
                                        : std::array<double, 2>{s.pressure_factor ? s.pressure_factor(load_ratio) : 1.0, 1.0};
        const double p0_line = std::sqrt(q_held * e_star / (std::numbers::pi * r_held)), p0 = p0_line * g[0];
        // accumulated = K / (|sigma'| R(f)): its first moment is smooth in s,
        // its second carries 1 / R, integrated exactly over the piece below.
        const double b_held = hertz ? std::sqrt(4 * q_held * r_held / (std::numbers::pi * e_star)) : 0;
        auto accumulated = [&](double peak) { return hertz ? std::numbers::pi / 2 * peak * b_held : peak; };
        const double k_pass = accumulated(p0);
        r.first[2] += k_pass * h / 2 * length;
        r.area[2] += weight;
        r.max[2] = std::max(r.max[2], k_pass / (rate * radius(f)));
        accumulated_squared += k_pass * k_pass / 2;
        if (s.pressure_factors)
        {
          const double k_second = accumulated(p0_line * g[1]);
          r.second_factor.first += k_second * h / 2 * length;
          r.second_factor.max = std::max(r.second_factor.max, k_second / (rate * radius(f)));
          second_squared += k_second * k_second / 2;
        }
        if (!all_scores)
          continue;
        // Damage relative to that of a 100 MPa amplitude: V does not see the scale.
        add_point(r, 1, p0, weight);
        add_point(r, 3, std::pow(p0 / 2 / 100e6, -1 / s.basquin_exponent), weight);
      }
      const double reciprocal_radius = piece_reciprocal_radius(radius(s0), radius(s1), h);
      r.second[2] += accumulated_squared * length / rate * reciprocal_radius;
      if (s.pressure_factors)
        r.second_factor.second += second_squared * length / rate * reciprocal_radius;
    }
  }
  return r;
}

/// The scores of a quantity of integrals `first` (x dA), `second` (x^2 dA)
/// and largest value `max` over the touched area `touched_m2`.
ContinuumScore score_of(double first, double second, double max, double touched_m2, double surface_area_m2)
{
  ContinuumScore score;
  score.touched_area_m2 = touched_m2;
  if (!(first > 0))
    throw ComputationError("continuum loop scores: nothing is touched in the loop");
  // V >= 0 (Cauchy-Schwarz); a uniform x leaves rounding of either sign.
  auto variance = [&](double area) {
    const double v = area * second / (first * first) - 1;
    return v < 1e-9 ? 0.0 : v;
  };
  score.whole = variance(surface_area_m2);
  score.touched = variance(score.touched_area_m2);
  score.peak_to_mean = max * score.touched_area_m2 / first;
  return score;
}

ContinuumScore score_of(const Rates& total, int quantity, double surface_area_m2)
{
  return score_of(total.first[quantity], total.second[quantity], total.max[quantity], total.area[quantity],
                  surface_area_m2);
}

void require_positive_area(double surface_area_m2)
{
  if (!(surface_area_m2 > 0))
    throw InputError(fmt::format("continuum loop scores: needs a positive surface area, got {} m^2", surface_area_m2));
}

void validate(const oracle::RollingTrajectory& trajectory, double begin_s, double end_s, const ContinuumLoopSettings& s,
              WindowPart part)
{
  if (trajectory.mode != oracle::ContactMode::line)
    throw InputError("continuum loop scores: defined for line contact only");
  if (!(end_s > begin_s))
    throw InputError("continuum loop scores: needs end > begin");
  if (!(part.parts >= 1 && part.part >= 0 && part.part < part.parts))
    throw InputError(fmt::format("continuum loop scores: part {} of {} does not exist", part.part, part.parts));
  if (!(s.end_margin >= 0 && s.end_margin < 0.5))
    throw InputError(fmt::format("end margin must be in [0, 0.5), got {}", s.end_margin));
  if (!(s.normal_load_n > 0) || !std::isfinite(s.normal_load_n))
    throw InputError(fmt::format("normal load (N) must be positive and finite, got {}", s.normal_load_n));
  if (s.pieces < 1)
    throw InputError(fmt::format("pieces along the ruling must be at least 1, got {}", s.pieces));
  if (s.pressure_factor && s.pressure_factors)
    throw InputError("continuum loop scores: give a pressure factor or a pair of them, not both");
}
} // namespace

const NamedValues<TimeLaw>& time_law_names()
{
  static const NamedValues<TimeLaw> names = {{"free", TimeLaw::free_rolling}, {"uniform_rate", TimeLaw::uniform_rate}};
  return names;
}

ContinuumMoments& ContinuumMoments::operator+=(const ContinuumMoments& o)
{
  for (int i = 0; i < quantities; ++i)
    area[i] += o.area[i], first[i] += o.first[i], second[i] += o.second[i], max[i] = std::max(max[i], o.max[i]);
  swept += o.swept;
  second_factor.first += o.second_factor.first, second_factor.second += o.second_factor.second;
  second_factor.max = std::max(second_factor.max, o.second_factor.max);
  load_ratio_min = std::min(load_ratio_min, o.load_ratio_min);
  load_ratio_max = std::max(load_ratio_max, o.load_ratio_max);
  return *this;
}

ContinuumMoments continuum_loop_moments(const oracle::RollingTrajectory& trajectory, double begin_s, double end_s,
                                        const RollingBodyMass& body, const ContinuumLoopSettings& s, WindowPart part)
{
  validate(trajectory, begin_s, end_s, s, part);
  const auto& samples = trajectory.samples;
  // The uniform rate sweeps the same loop in the same time at constant sigma';
  // the window's intervals are [first, last).
  double swept_angle = 0, window = 0;
  std::size_t first = 0, last = 0;
  for (std::size_t k = 0; k + 1 < samples.size(); ++k)
  {
    const double t0 = std::max(samples[k].time_s, begin_s), t1 = std::min(samples[k + 1].time_s, end_s);
    if (!(t1 > t0))
      continue;
    swept_angle += std::abs(samples[k + 1].turning_angle_rad - samples[k].turning_angle_rad) * (t1 - t0)
                   / (samples[k + 1].time_s - samples[k].time_s);
    window += t1 - t0;
    if (last == 0)
      first = k;
    last = k + 1;
  }
  const double uniform_rate = swept_angle / window;
  const bool uniform = s.time_law == TimeLaw::uniform_rate;
  auto rate_of = [&](const oracle::RollingSample& x) { return uniform ? uniform_rate : std::abs(x.rolling_rate_rad_s); };
  // Each sample's rates once; then the trapezoid rule between samples.
  std::vector<Rates> at(samples.size());
  std::vector<bool> done(samples.size(), false);
  auto rates = [&](std::size_t k) -> const Rates& {
    if (!done[k])
      at[k] = sample_rates(samples[k], rate_of(samples[k]), body, s), done[k] = true;
    return at[k];
  };
  // This part's run of the window's intervals.
  const std::size_t intervals = last - first;
  const auto share = [&](int p) { return first + intervals * static_cast<std::size_t>(p) / static_cast<std::size_t>(part.parts); };
  Rates total;
  for (std::size_t k = share(part.part); k < share(part.part + 1); ++k)
  {
    const double t0 = std::max(samples[k].time_s, begin_s), t1 = std::min(samples[k + 1].time_s, end_s);
    if (!(t1 > t0))
      continue;
    const double fraction = (t1 - t0) / (samples[k + 1].time_s - samples[k].time_s);
    const double dt = uniform ? std::abs(samples[k + 1].turning_angle_rad - samples[k].turning_angle_rad) * fraction
                                    / uniform_rate
                              : t1 - t0;
    Rates a = rates(k);
    a += rates(k + 1);
    for (int i = 0; i < n_quantities; ++i)
      a.area[i] *= dt / 2, a.first[i] *= dt / 2, a.second[i] *= dt / 2;
    a.swept *= dt / 2;
    a.second_factor.first *= dt / 2, a.second_factor.second *= dt / 2;
    if (!s.accumulated_pressure_only && s.width == oracle::ContactWidthModel::rigid
        && (rates(k).first[0] > 0 || rates(k + 1).first[0] > 0))
      a.second[0] = rigid_time_second_moment(samples[k], samples[k + 1], rate_of(samples[k]), rate_of(samples[k + 1]),
                                             dt, 16);
    total += a;
  }
  return total;
}

ContinuumLoopScores continuum_loop_scores(const ContinuumMoments& total, double surface_area_m2,
                                          const ContinuumLoopSettings& s)
{
  require_positive_area(surface_area_m2);
  ContinuumLoopScores scores;
  scores.surface_area_m2 = surface_area_m2;
  scores.swept_area_m2 = total.swept;
  scores.accumulated_pressure = score_of(total, 2, surface_area_m2);
  if (s.pressure_factors)
    scores.accumulated_pressure_second_factor = score_of(total.second_factor.first, total.second_factor.second,
                                                         total.second_factor.max, total.area[2], surface_area_m2);
  if (!s.accumulated_pressure_only)
  {
    scores.contact_time = score_of(total, 0, surface_area_m2);
    scores.peak_pressure = score_of(total, 1, surface_area_m2);
    scores.damage = score_of(total, 3, surface_area_m2);
  }
  scores.peak_pressure_max_pa = total.max[1];
  scores.load_ratio_min = total.load_ratio_min;
  scores.load_ratio_max = total.load_ratio_max;
  return scores;
}

ContinuumLoopScores continuum_loop_scores(const oracle::RollingTrajectory& trajectory, double begin_s, double end_s,
                                          double surface_area_m2, const RollingBodyMass& body,
                                          const ContinuumLoopSettings& s)
{
  require_positive_area(surface_area_m2); // before the integration
  return continuum_loop_scores(continuum_loop_moments(trajectory, begin_s, end_s, body, s), surface_area_m2, s);
}
} // namespace rollcheck::contact
