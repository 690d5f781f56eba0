#include "contact/trajectory_scores.h"
#include "contact/fatigue.h"
#include "contact/sliding_speed.h"
#include "contact/wear.h"
#include "core/error.h"
#include "oracle/heights.h"
#include <cmath>
#include <fmt/format.h>
#include <limits>
#include <numbers>

namespace rollcheck::contact
{
MetricSet MetricSet::parse(std::string_view list, std::string_view origin)
{
  if (list == "all")
    return {};
  MetricSet m{false, false, false, false, false};
  std::size_t start = 0;
  bool any = false;
  while (start <= list.size())
  {
    std::size_t end = list.find(',', start);
    if (end == std::string_view::npos)
      end = list.size();
    const std::string_view name = list.substr(start, end - start);
    start = end + 1;
    if (name.empty())
      continue;
    bool* flag = name == "cds"   ? &m.cds
                 : name == "sds" ? &m.sds
                 : name == "tds" ? &m.tds
                 : name == "wds" ? &m.wds
                 : name == "fds" ? &m.fds
                                 : nullptr;
    if (!flag)
      throw InputError(fmt::format("{}: unknown metric '{}' (known: cds, sds, tds, wds, fds, or all)", origin, name));
    *flag = any = true;
  }
  if (!any)
    throw InputError(fmt::format("{}: no metric given (cds, sds, tds, wds, fds, or all)", origin));
  return m;
}

namespace
{
constexpr double infinity = std::numeric_limits<double>::infinity();

/// max / min over the entries that are > 0 (+inf when there are none).
double positive_ratio(const Eigen::VectorXd& x)
{
  double lo = infinity, hi = 0;
  for (Eigen::Index i = 0; i < x.size(); ++i)
    if (x[i] > 0)
    {
      lo = std::min(lo, x[i]);
      hi = std::max(hi, x[i]);
    }
  return lo < infinity ? hi / lo : infinity;
}

} // namespace

ScoreVector score_trajectory(const ScoreInputs& in, const oracle::Trajectory& trajectory, const MetricSet& metrics,
                             const ContactParameters& parameters, const oracle::PaperCompat& compat,
                             long convergence_every)
{
  validate(parameters);
  if (metrics.needs_sliding() && !trajectory.has_angular_velocity)
    throw InputError("tds and wds need angular velocities, which only the rigid-body oracle has "
                     "(use --oracle rigid, or --metrics cds,sds,fds)");
  const Eigen::VectorXd& areas = in.body.face_areas;
  const Eigen::Index n_faces = areas.size();
  const Eigen::VectorXd& p = in.pressure.peak_pressure_pa;
  const double load_scale = std::cbrt(parameters.fatigue.load_n / parameters.hertz.normal_load_n);
  const double amplitude_factor = compat.peak_pressure_as_stress_amplitude ? 1.0 : 0.5;
  const WearParameters& wear = parameters.wear;

  Eigen::VectorXd counts = Eigen::VectorXd::Zero(n_faces), stress = counts, damage = counts, heat = counts,
                  wear_volume = counts, wear_depth = counts;
  // The fatigue amplitude and damage of a contact depend on the face only:
  // formed once per face (Basquin's power law is the costly part).
  Eigen::VectorXd amplitude(n_faces), damage_per_cycle(n_faces);
  for (Eigen::Index f = 0; f < n_faces; ++f)
  {
    amplitude[f] = p[f] * load_scale * amplitude_factor;
    damage_per_cycle[f] = miner_damage_per_cycle(amplitude[f], parameters.fatigue);
  }
  std::vector<double> peaks, fatigue_peaks, slides;
  long events = 0, above_endurance = 0;
  const oracle::ScoreTemplate score(areas);
  ScoreVector out;
  out.n_samples = static_cast<long>(trajectory.size());
  out.effective_modulus_pa = in.pressure.effective_modulus_pa;

  for (std::size_t s = 0; s < trajectory.size(); ++s)
  {
    const oracle::Sample& sample = trajectory.samples[s];
    const Eigen::Matrix3d& r = sample.rotation;
    Eigen::Vector3d support = Eigen::Vector3d::Zero();
    if (metrics.needs_sliding() && !compat.sliding_velocity_about_body_origin)
      support = oracle::rotate(r, in.body.vertices, static_cast<std::size_t>(sample.support_vertex));
    double peak = 0, fatigue_peak = 0;
    for (const int* it = trajectory.contacts_begin(s); it != trajectory.contacts_end(s); ++it)
    {
      const int f = *it;
      counts[f] += 1;
      stress[f] += p[f];
      peak = std::max(peak, p[f]);
      if (metrics.fds)
      {
        damage[f] += damage_per_cycle[f];
        fatigue_peak = std::max(fatigue_peak, amplitude[f]);
        ++events;
        if (amplitude[f] > parameters.fatigue.endurance_limit_pa)
          ++above_endurance;
      }
      if (metrics.needs_sliding())
      {
        Eigen::Vector3d lever = oracle::rotate(r, in.body.centroids, static_cast<std::size_t>(f));
        if (compat.sliding_velocity_about_body_origin)
          lever[2] -= sample.ground_height_m;
        else
          lever -= support;
        const double v = horizontal_speed(sample.angular_velocity, lever);
        slides.push_back(v);
        heat[f] += parameters.thermal.friction_coefficient * p[f] * v;
        const double depth = archard_depth(p[f], v, wear);
        if (compat.wear_depth_per_face_area)
        {
          wear_volume[f] += depth;
          wear_depth[f] += depth / areas[f];
        }
        else
        {
          const double a = in.pressure.contact_radius_m[f];
          wear_depth[f] += depth;
          wear_volume[f] += depth * (std::numbers::pi * a * a);
        }
      }
    }
    if (peak > 0)
      peaks.push_back(peak);
    if (fatigue_peak > 0)
      fatigue_peaks.push_back(fatigue_peak);
    const long done = static_cast<long>(s) + 1;
    if (convergence_every > 0 && done % convergence_every == 0)
    {
      auto snapshot = [&](const char* key, const Eigen::VectorXd& acc) {
        out.convergence[key].emplace_back(done, score(acc));
      };
      if (metrics.cds) snapshot("cds", counts);
      if (metrics.sds) snapshot("sds", stress);
      if (metrics.fds) snapshot("fds", damage);
      if (metrics.tds) snapshot("tds", heat);
      if (metrics.wds) snapshot("wds_vol", wear_volume), snapshot("wds_depth", wear_depth);
    }
  }

  if (metrics.cds)
  {
    out.contact = oracle::summarize_distribution(counts, areas);
    out.cds = out.contact.score;
    out.per_face["contact_counts"] = counts;
  }
  if (metrics.sds)
  {
    out.sds = score(stress);
    out.peak_pressure_pa = oracle::value_statistics(peaks);
    out.per_face["stress_pa"] = stress;
  }
  if (metrics.fds)
  {
    out.fds = score(damage);
    out.damage_ratio = positive_ratio(damage);
    const double worst = damage.size() ? damage.maxCoeff() : 0.0;
    // In the reference's order: damage per cycle of the worst face, inverted.
    const double worst_per_cycle = worst / static_cast<double>(out.n_samples);
    out.first_failure_cycles = worst_per_cycle > 0 ? 1.0 / worst_per_cycle : infinity;
    out.fatigue_stress_pa = oracle::value_statistics(fatigue_peaks);
    out.fraction_above_endurance = static_cast<double>(above_endurance) / static_cast<double>(std::max(events, 1L));
    out.per_face["fatigue_damage"] = damage;
  }
  if (metrics.tds)
  {
    out.tds = score(heat);
    out.heat_ratio = positive_ratio(heat);
    out.per_face["heat"] = heat;
  }
  if (metrics.needs_sliding())
  {
    out.sliding_speed_m_s = oracle::value_statistics(slides);
    if (out.sliding_speed_m_s.mean == 0)
      out.sliding_speed_m_s.cv = 0; // the reference's value for a body that never slides
  }
  if (metrics.wds)
  {
    out.wds_vol = score(wear_volume);
    out.wds_depth = score(wear_depth);
    out.wear_depth_ratio = positive_ratio(wear_depth);
    out.per_face["wear_volume"] = wear_volume;
    out.per_face["wear_depth"] = wear_depth;
  }
  return out;
}
} // namespace rollcheck::contact
