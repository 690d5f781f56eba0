#include "study/life/loop_life.h"
#include "contact/ruling_load.h"
#include "core/error.h"
#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <numbers>

namespace rollcheck::study::life
{
namespace
{
void validate(const LoopLifeSettings& s)
{
  if (!(s.normal_load_n > 0) || !std::isfinite(s.normal_load_n))
    throw InputError(fmt::format("life: the normal load (N) must be positive and finite, got {}", s.normal_load_n));
  if (!(s.end_margin >= 0 && s.end_margin < 0.5))
    throw InputError(fmt::format("life: the end margin must be in [0, 0.5), got {}", s.end_margin));
  if (s.pieces < 1)
    throw InputError(fmt::format("life: pieces along the ruling must be at least 1, got {}", s.pieces));
}
} // namespace

namespace
{
/// One loaded ruling of the loop: its sample, its weight in sigma, its
/// length and its load under the rule (contact/ruling_load.h).
struct LoadedRuling
{
  const oracle::RollingSample& sample;
  double dsigma, length;
  contact::RulingLoad rule;
  double radius(double f) const { return (1 - f) * sample.start_radius_m + f * sample.end_radius_m; }
  double load(double f) const { return rule.line_load(length, f); }
};

void for_each_loaded_ruling(const oracle::RealRolling& run, const LoopLifeSettings& s,
                            const std::function<void(const LoadedRuling&)>& visit)
{
  validate(s);
  if (run.trajectory.mode != oracle::ContactMode::line)
    throw InputError("life: defined for line contact only");
  const double end = std::isfinite(run.first_loop_end_s) ? run.first_loop_end_s : run.scored_end_s;
  const auto& samples = run.trajectory.samples;
  // Trapezoid weights in sigma: each step's part inside the loop, half to either end.
  std::vector<double> weight(samples.size(), 0.0);
  for (std::size_t k = 0; k + 1 < samples.size(); ++k)
  {
    const double t0 = samples[k].time_s, t1 = samples[k + 1].time_s;
    const double inside = std::clamp((std::min(t1, end) - t0) / (t1 - t0), 0.0, 1.0);
    const double half = std::abs(samples[k + 1].turning_angle_rad - samples[k].turning_angle_rad) * inside / 2;
    weight[k] += half, weight[k + 1] += half;
  }
  // The rolling study's gravity (RollingBodyMass's default), as the robustness grid's.
  const contact::RollingBodyMass mass{run.mass.centre_of_mass_m, run.mass.mass_kg};
  for (std::size_t k = 0; k < samples.size(); ++k)
  {
    const oracle::RollingSample& x = samples[k];
    const contact::RulingLoad load = contact::ruling_load(x, s.load_rule, s.normal_load_n, mass);
    if (!(load.normal_n > 0) || !(weight[k] > 0))
      continue;
    visit({x, weight[k], (x.contact_end_m - x.contact_start_m).norm(), load});
  }
}

/// Line Hertz's element of a pass at line load q on radius r.
LoadedElement line_hertz(double area_m2, double q, double r, double e_star, double peak_factor = 1)
{
  return {area_m2, peak_factor * std::sqrt(q * e_star / (std::numbers::pi * r)),
          std::sqrt(4 * q * r / (std::numbers::pi * e_star))};
}
} // namespace

void for_each_loaded_element(const oracle::RealRolling& run, const LoopLifeSettings& s,
                             const std::function<void(const LoadedElement&)>& visit)
{
  for_each_loaded_ruling(run, s, [&](const LoadedRuling& u) {
    const double from = u.rule.from, h = (u.rule.to - from) / s.pieces, offset = h / (2 * std::sqrt(3.0));
    for (int piece = 0; piece < s.pieces; ++piece)
      for (const double f : {from + (piece + 0.5) * h - offset, from + (piece + 0.5) * h + offset})
      {
        const double held = contact::held_fraction(f, from, u.rule.to, s.end_margin), q = u.load(held);
        if (q > 0)
          visit(line_hertz(u.dsigma * u.length * u.radius(f) * h / 2, q, u.radius(held), s.effective_modulus_pa));
      }
  });
}

void for_each_loaded_end(const oracle::RealRolling& run, const LoopLifeSettings& s, const RoundedEnds& ends,
                         const std::function<void(const LoadedEnd&)>& visit)
{
  if (!(ends.edge_radius_m > 0) || !ends.ratios || !(ends.zone_over_half_width > 0))
    throw InputError(fmt::format("life: rounded ends need a positive edge radius and zone and an end table, got "
                                 "r_e = {} m, zone {} b",
                                 ends.edge_radius_m, ends.zone_over_half_width));
  for_each_loaded_ruling(run, s, [&](const LoadedRuling& u) {
    for (const double f : {0.0, 1.0})
    {
      const double q = u.load(f);
      if ((f == 0 && u.rule.from > 0) || (f == 1 && u.rule.to < 1) || !(q > 0))
        continue; // this end carries no load
      const double sheet = u.radius(f) / ends.edge_radius_m, r = std::max(u.radius(f), ends.edge_radius_m);
      LoadedElement e = line_hertz(0, q, r, s.effective_modulus_pa, (*ends.ratios)(sheet));
      e.area_m2 = ends.zone_over_half_width * e.half_width_m * r * u.dsigma;
      visit({e, ends.ratios->covers(sheet)});
    }
  });
}

LoopIntegrals loop_integrals(const oracle::RealRolling& run, const LoopLifeSettings& settings,
                             const LifeConstants& k, const std::array<const DepthIntegrals*, 2>& depth,
                             const std::array<double, 2>& ratio, const DepthIntegrals& dang_van,
                             const RoundedEnds* ends)
{
  LoopIntegrals out;
  const double c = k.stress_exponent, h = k.depth_exponent;
  std::array<double, 2> limit{}, lp_depth{};
  for (int i = 0; i < 2; ++i)
  {
    limit[i] = ratio[i] * depth[i]->peak() * k.fatigue_limit_contact_pa; // tau_u
    lp_depth[i] = depth[i]->integral(0, c);
  }
  auto add = [&](const LoadedElement& e, std::array<double, 2>& lp, std::array<double, 2>& ih) {
    const double scale = e.area_m2 * std::pow(e.half_width_m, 1 - h);
    for (int i = 0; i < 2; ++i)
    {
      const double tau_scale = ratio[i] * e.peak_pressure_pa;
      const double amplitude = std::pow(tau_scale, c) * scale;
      lp[i] += amplitude * lp_depth[i];
      ih[i] += amplitude * depth[i]->integral(limit[i] / tau_scale, c);
    }
  };
  for_each_loaded_element(run, settings, [&](const LoadedElement& e) {
    add(e, out.lundberg_palmgren, out.ioannides_harris);
    out.max_peak_pressure_pa = std::max(out.max_peak_pressure_pa, e.peak_pressure_pa);
  });
  out.max_dang_van_pa = dang_van.peak() * out.max_peak_pressure_pa;
  if (ends)
    for_each_loaded_end(run, settings, *ends, [&](const LoadedEnd& e) {
      add(e.element, out.end_lundberg_palmgren, out.end_ioannides_harris);
      ++out.ends, out.ends_outside_table += !e.inside_table;
    });
  return out;
}

double lundberg_palmgren_by_depth(const oracle::RealRolling& run, const LoopLifeSettings& settings,
                                  const LifeConstants& k, const DepthIntegrals& depth, double z_lo, double z_hi,
                                  int depths)
{
  if (!(z_lo > 0 && z_hi > z_lo) || depths < 2)
    throw InputError(fmt::format("life: a depth grid needs 0 < z_lo < z_hi and two depths, got [{}, {}] m, {}", z_lo,
                                 z_hi, depths));
  const double step = std::log(z_hi / z_lo) / (depths - 1);
  std::vector<double> weight(depths), z(depths);
  for (int i = 0; i < depths; ++i)
  {
    z[i] = z_lo * std::exp(i * step);
    // integral g dz = integral g z d ln(z), trapezoid rule.
    weight[i] = (i == 0 || i == depths - 1 ? 0.5 : 1.0) * step * std::pow(z[i], 1 - k.depth_exponent);
  }
  double total = 0;
  for_each_loaded_element(run, settings, [&](const LoadedElement& e) {
    double sum = 0;
    for (int i = 0; i < depths; ++i)
      if (const double f = depth.profile(z[i] / e.half_width_m); f > 0)
        sum += weight[i] * std::pow(f, k.stress_exponent);
    total += e.area_m2 * std::pow(e.peak_pressure_pa, k.stress_exponent) * sum;
  });
  return total;
}
} // namespace rollcheck::study::life
