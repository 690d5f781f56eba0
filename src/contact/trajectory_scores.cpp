#include "contact/trajectory_scores.h"
#include "contact/fatigue.h"
#include "contact/sliding_speed.h"
#include "contact/wear.h"
#include "core/comma_list.h"
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
  bool any = false;
  for (const std::string_view name : comma_list_items(list))
  {
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

/// One pass over a trajectory: the per-face accumulators of every metric, the
/// per-sample peaks and the sliding speeds, filled sample by sample.
class TrajectoryPass
{
public:
  TrajectoryPass(const ScoreInputs& in, const MetricSet& metrics, const ContactParameters& parameters,
                 const oracle::PaperCompat& compat);
  /// Adds the contacts of one sample.
  void add_sample(const oracle::Sample& sample, const int* contacts_begin, const int* contacts_end);
  /// Scores of the accumulators so far, as the convergence entry after `done` samples.
  void snapshot(long done, const oracle::ScoreTemplate& score, ScoreVector& out) const;
  /// The scores and statistics of the whole pass.
  void summarize(const oracle::ScoreTemplate& score, ScoreVector& out) const;

private:
  /// Heat and wear of face f sliding at the sample's angular velocity.
  void add_sliding(const oracle::Sample& sample, const Eigen::Vector3d& support, int f);

  const ScoreInputs& in_;
  const MetricSet& metrics_;
  const ContactParameters& parameters_;
  const oracle::PaperCompat& compat_;
  const Eigen::VectorXd& areas_;
  const Eigen::VectorXd& p_;
  // The fatigue amplitude and damage of a contact depend on the face only:
  // formed once per face (Basquin's power law is the costly part).
  Eigen::VectorXd amplitude_, damage_per_cycle_;
  Eigen::VectorXd counts_, stress_, damage_, heat_, wear_volume_, wear_depth_;
  std::vector<double> peaks_, fatigue_peaks_, slides_;
  long events_ = 0, above_endurance_ = 0;
};

TrajectoryPass::TrajectoryPass(const ScoreInputs& in, const MetricSet& metrics, const ContactParameters& parameters,
                               const oracle::PaperCompat& compat)
    : in_(in), metrics_(metrics), parameters_(parameters), compat_(compat), areas_(in.body.face_areas),
      p_(in.pressure.peak_pressure_pa)
{
  const Eigen::Index n_faces = areas_.size();
  const double load_scale = std::cbrt(parameters.fatigue.load_n / parameters.hertz.normal_load_n);
  const double amplitude_factor = compat.peak_pressure_as_stress_amplitude ? 1.0 : 0.5;
  counts_ = Eigen::VectorXd::Zero(n_faces);
  stress_ = damage_ = heat_ = wear_volume_ = wear_depth_ = counts_;
  amplitude_.resize(n_faces);
  damage_per_cycle_.resize(n_faces);
  for (Eigen::Index f = 0; f < n_faces; ++f)
  {
    amplitude_[f] = p_[f] * load_scale * amplitude_factor;
    damage_per_cycle_[f] = miner_damage_per_cycle(amplitude_[f], parameters.fatigue);
  }
}

void TrajectoryPass::add_sample(const oracle::Sample& sample, const int* contacts_begin, const int* contacts_end)
{
  Eigen::Vector3d support = Eigen::Vector3d::Zero();
  if (metrics_.needs_sliding() && !compat_.sliding_velocity_about_body_origin)
    support = oracle::rotate(sample.rotation, in_.body.vertices, static_cast<std::size_t>(sample.support_vertex));
  double peak = 0, fatigue_peak = 0;
  for (const int* it = contacts_begin; it != contacts_end; ++it)
  {
    const int f = *it;
    counts_[f] += 1;
    stress_[f] += p_[f];
    peak = std::max(peak, p_[f]);
    if (metrics_.fds)
    {
      damage_[f] += damage_per_cycle_[f];
      fatigue_peak = std::max(fatigue_peak, amplitude_[f]);
      ++events_;
      if (amplitude_[f] > parameters_.fatigue.endurance_limit_pa)
        ++above_endurance_;
    }
    if (metrics_.needs_sliding())
      add_sliding(sample, support, f);
  }
  if (peak > 0)
    peaks_.push_back(peak);
  if (fatigue_peak > 0)
    fatigue_peaks_.push_back(fatigue_peak);
}

void TrajectoryPass::add_sliding(const oracle::Sample& sample, const Eigen::Vector3d& support, int f)
{
  Eigen::Vector3d lever = oracle::rotate(sample.rotation, in_.body.centroids, static_cast<std::size_t>(f));
  if (compat_.sliding_velocity_about_body_origin)
    lever[2] -= sample.ground_height_m;
  else
    lever -= support;
  const double v = horizontal_speed(sample.angular_velocity, lever);
  slides_.push_back(v);
  heat_[f] += parameters_.thermal.friction_coefficient * p_[f] * v;
  const double depth = archard_depth(p_[f], v, parameters_.wear);
  if (compat_.wear_depth_per_face_area)
  {
    wear_volume_[f] += depth;
    wear_depth_[f] += depth / areas_[f];
  }
  else
  {
    const double a = in_.pressure.contact_radius_m[f];
    wear_depth_[f] += depth;
    wear_volume_[f] += depth * (std::numbers::pi * a * a);
  }
}

void TrajectoryPass::snapshot(long done, const oracle::ScoreTemplate& score, ScoreVector& out) const
{
  auto entry = [&](const char* key, const Eigen::VectorXd& accumulator) {
    out.convergence[key].emplace_back(done, score(accumulator));
  };
  if (metrics_.cds) entry("cds", counts_);
  if (metrics_.sds) entry("sds", stress_);
  if (metrics_.fds) entry("fds", damage_);
  if (metrics_.tds) entry("tds", heat_);
  if (metrics_.wds) entry("wds_vol", wear_volume_), entry("wds_depth", wear_depth_);
}

void TrajectoryPass::summarize(const oracle::ScoreTemplate& score, ScoreVector& out) const
{
  if (metrics_.cds)
  {
    out.contact = oracle::summarize_distribution(counts_, areas_);
    out.cds = out.contact.score;
    out.per_face["contact_counts"] = counts_;
  }
  if (metrics_.sds)
  {
    out.sds = score(stress_);
    out.peak_pressure_pa = oracle::value_statistics(peaks_);
    out.per_face["stress_pa"] = stress_;
  }
  if (metrics_.fds)
  {
    out.fds = score(damage_);
    out.damage_ratio = positive_ratio(damage_);
    const double worst = damage_.size() ? damage_.maxCoeff() : 0.0;
    // In the reference's order: damage per cycle of the worst face, inverted.
    const double worst_per_cycle = worst / static_cast<double>(out.n_samples);
    out.first_failure_cycles = worst_per_cycle > 0 ? 1.0 / worst_per_cycle : infinity;
    out.fatigue_stress_pa = oracle::value_statistics(fatigue_peaks_);
    out.fraction_above_endurance = static_cast<double>(above_endurance_) / static_cast<double>(std::max(events_, 1L));
    out.per_face["fatigue_damage"] = damage_;
  }
  if (metrics_.tds)
  {
    out.tds = score(heat_);
    out.heat_ratio = positive_ratio(heat_);
    out.per_face["heat"] = heat_;
  }
  if (metrics_.needs_sliding())
  {
    out.sliding_speed_m_s = oracle::value_statistics(slides_);
    if (out.sliding_speed_m_s.mean == 0)
      out.sliding_speed_m_s.cv = 0; // the reference's value for a body that never slides
  }
  if (metrics_.wds)
  {
    out.wds_vol = score(wear_volume_);
    out.wds_depth = score(wear_depth_);
    out.wear_depth_ratio = positive_ratio(wear_depth_);
    out.per_face["wear_volume"] = wear_volume_;
    out.per_face["wear_depth"] = wear_depth_;
  }
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
  TrajectoryPass pass(in, metrics, parameters, compat);
  const oracle::ScoreTemplate score(in.body.face_areas);
  ScoreVector out;
  out.n_samples = static_cast<long>(trajectory.size());
  out.effective_modulus_pa = in.pressure.effective_modulus_pa;
  for (std::size_t s = 0; s < trajectory.size(); ++s)
  {
    pass.add_sample(trajectory.samples[s], trajectory.contacts_begin(s), trajectory.contacts_end(s));
    const long done = static_cast<long>(s) + 1;
    if (convergence_every > 0 && done % convergence_every == 0)
      pass.snapshot(done, score, out);
  }
  pass.summarize(score, out);
  return out;
}
} // namespace rollcheck::contact
