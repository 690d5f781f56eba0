// The rim loop's samples under a load rule (study/rims/rule_loop_samples.h).
#include "study/rims/rule_loop_samples.h"
#include "contact/ruling_load.h"
#include "core/error.h"
#include "geometry/body.h"
#include "oracle/contact_density.h"
#include "oracle/rolling_body.h"
#include <algorithm>
#include <fmt/format.h>
#include <limits>

namespace rollcheck::study::rims
{
std::vector<RulingLoad> ruling_loads(const oracle::RealRolling& run, contact::LoadRule rule, double force_n,
                                     double gravity_m_s2)
{
  std::vector<RulingLoad> loads;
  const contact::RollingBodyMass mass{run.mass.centre_of_mass_m, run.mass.mass_kg, gravity_m_s2};
  for (const oracle::RollingSample& sample : run.trajectory.samples)
  {
    if (sample.time_s > run.scored_end_s)
      break;
    // The resultant without the no-tension rule: a rim point's load too.
    const contact::RulingLoad r = contact::ruling_resultant(sample, rule, force_n, mass);
    loads.push_back({r.normal_n, sample.contact_start_m + r.centre * (sample.contact_end_m - sample.contact_start_m)});
  }
  return loads;
}

loop_scores::LoopSamples map_rule_samples(MPI_Comm comm, const loop_scores::LoopSource& source,
                                          std::span<const RulingLoad> loads, const oracle::RollingBody& body,
                                          const oracle::FaceCones& cones, double effective_modulus_pa,
                                          const loop_scores::LoopSdsSettings& settings,
                                          std::vector<std::size_t>* ruling_sample)
{
  if (loads.size() != source.rotations.size() || source.rotations.empty())
    throw ComputationError(fmt::format("rim loop: {} loads for a loop of {} samples", loads.size(),
                                       source.rotations.size()));
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  const auto n_faces = body.face_areas.size();
  const Eigen::VectorXd no_point_pressure = Eigen::VectorXd::Zero(n_faces);
  loop_scores::LoopSamples out;
  out.samples = source.rotations.size();
  out.face_areas = body.face_areas;
  out.point_all = out.point_even = out.line_all = out.line_even = Eigen::VectorXd::Zero(n_faces);
  out.load_ratio_min = std::numeric_limits<double>::infinity();
  out.load_ratio_max = 0;
  for (std::size_t j = static_cast<std::size_t>(rank); j < source.rotations.size(); j += static_cast<std::size_t>(size))
  {
    // One sample, its force through its own point: the locus's "centre of
    // mass" is where the load acts (contact/contact_locus.h: only c uses it).
    loop_scores::LoopSource one{source.circles, loads[j].through_m, {source.rotations[j]}, {source.times_s[j]},
                                {}, source.description};
    if (!source.oracle_faces.empty())
      one.oracle_faces = {source.oracle_faces[j]};
    loop_scores::LoopSdsSettings own = settings;
    own.normal_load_n = loads[j].force_n;
    loop_scores::LoopSamples sample
        = loop_scores::map_loop_samples(MPI_COMM_SELF, one, body, no_point_pressure, cones, effective_modulus_pa, own);
    const bool even = j % 2 == 0;
    for (std::size_t c = 0; c < out.by_contact.size(); ++c)
      out.by_contact[c] += sample.by_contact[c];
    out.line_all += sample.line_all;
    if (even)
      out.line_even += sample.line_all;
    if (sample.ruling_count() > 0)
    {
      out.load_ratio_min = std::min(out.load_ratio_min, sample.load_ratio_min);
      out.load_ratio_max = std::max(out.load_ratio_max, sample.load_ratio_max);
    }
    for (loop_scores::RulingSample& ruling : sample.rulings)
    {
      ruling.even = even;
      out.rulings.push_back(std::move(ruling));
      if (ruling_sample)
        ruling_sample->push_back(j);
    }
    out.wall_s += sample.wall_s;
  }
  MPI_Allreduce(MPI_IN_PLACE, out.by_contact.data(), 4, MPI_UNSIGNED_LONG, MPI_SUM, comm);
  for (Eigen::VectorXd* sums : {&out.line_all, &out.line_even})
    MPI_Allreduce(MPI_IN_PLACE, sums->data(), static_cast<int>(sums->size()), MPI_DOUBLE, MPI_SUM, comm);
  MPI_Allreduce(MPI_IN_PLACE, &out.load_ratio_min, 1, MPI_DOUBLE, MPI_MIN, comm);
  MPI_Allreduce(MPI_IN_PLACE, &out.load_ratio_max, 1, MPI_DOUBLE, MPI_MAX, comm);
  MPI_Allreduce(MPI_IN_PLACE, &out.wall_s, 1, MPI_DOUBLE, MPI_MAX, comm);
  if (out.ruling_count() == 0)
    out.load_ratio_min = out.load_ratio_max = 0;
  return out;
}

std::vector<RuleSamples> rule_loop_samples(MPI_Comm comm, const loop_scores::FemSdsSettings& settings,
                                           const loop_scores::FemSdsResult& interior,
                                           std::span<const contact::LoadRule> rules)
{
  if (settings.oracle != loop_scores::OrientationOracle::rolling)
    throw InputError("rim --body: the load rules need the rolling oracle's loop (the rigid oracle has no rolling "
                     "motion)");
  // The loop fem-sds scored (study/loop_scores/fem_sds.cpp's rolling loop): the same run.
  oracle::RollingStudyParameters rolling;
  rolling.rolling_energy = settings.rolling_energy;
  rolling.samples_per_loop = settings.samples_per_loop;
  const oracle::RealRolling run = oracle::real_rolling(settings.body, rolling);
  loop_scores::LoopSource source{run.circles, run.mass.centre_of_mass_m, {}, {}, {}, "real rolling"};
  for (const oracle::RollingSample& sample : run.trajectory.samples)
    if (sample.time_s <= run.scored_end_s)
    {
      source.rotations.push_back(sample.rotation);
      source.times_s.push_back(sample.time_s);
    }
  if (source.rotations.size() != interior.loop.samples)
    throw ComputationError(fmt::format("rim loop: the rolling loop re-run has {} samples, fem-sds scored {}",
                                       source.rotations.size(), interior.loop.samples));
  const geometry::SurfaceMesh mesh = geometry::make_body(settings.body);
  const oracle::RollingBody body = oracle::make_rolling_body(
      mesh, settings.paper_compat ? oracle::PaperCompat::reference() : oracle::PaperCompat::corrected());
  const oracle::FaceCones cones = oracle::face_cones(mesh);
  std::vector<RuleSamples> by_rule;
  for (const contact::LoadRule rule : rules)
  {
    RuleSamples& r = by_rule.emplace_back();
    r.rule = rule;
    r.loads = ruling_loads(run, rule, settings.normal_load_n, rolling.gravity_m_s2);
    r.samples = map_rule_samples(comm, source, r.loads, body, cones, interior.effective_modulus_pa,
                                 loop_scores::loop_settings(settings), &r.ruling_sample);
    r.samples.point_all = interior.loop_samples.point_all;
    r.samples.point_even = interior.loop_samples.point_even;
    r.times_s = source.times_s;
  }
  return by_rule;
}
} // namespace rollcheck::study::rims
