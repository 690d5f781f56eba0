// FEM-SDS on the exact surface (study/loop_scores/fem_sds_continuum.h).
#include "study/loop_scores/fem_sds_continuum.h"
#include "core/json_number.h"
#include <algorithm>
#include <cmath>

namespace rollcheck::study::loop_scores
{
namespace
{
double accumulated_pressure_variance(const oracle::RollingTrajectory& trajectory, const oracle::RealRolling& run,
                                     const contact::ContinuumLoopSettings& s, contact::ContinuumLoopScores* all = nullptr)
{
  const double end = std::isfinite(run.first_loop_end_s) ? run.first_loop_end_s : run.scored_end_s;
  // fem-sds rolls the body under the rolling study's default gravity.
  const contact::RollingBodyMass mass{run.mass.centre_of_mass_m, run.mass.mass_kg,
                                      oracle::RollingStudyParameters{}.gravity_m_s2};
  const contact::ContinuumLoopScores scores
      = contact::continuum_loop_scores(trajectory, 0, end, run.surface_area_m2, mass, s);
  if (all)
    *all = scores;
  return scores.accumulated_pressure.whole;
}
} // namespace

ContinuumSds continuum_sds(MPI_Comm comm, const oracle::RealRolling& run, contact::ContinuumLoopSettings s,
                           fem::SliceScaling& table)
{
  ContinuumSds r;
  s.pressure_factor = nullptr;
  s.accumulated_pressure_only = true;
  contact::ContinuumLoopScores line;
  r.line_hertz = accumulated_pressure_variance(run.trajectory, run, s, &line);
  r.load_ratio_min = line.load_ratio_min;
  r.load_ratio_max = line.load_ratio_max;
  const double least = fem::SliceScaling::smallest_load_ratio;
  r.below_table = r.load_ratio_min < least;
  table.cover(comm, std::max(r.load_ratio_min, least), std::max(r.load_ratio_max, least));
  s.pressure_factor = [&table, least](double lambda) { return table.ratio(std::max(lambda, least)); };
  r.fem = accumulated_pressure_variance(run.trajectory, run, s);
  oracle::RollingTrajectory coarse = run.trajectory;
  coarse.samples.clear();
  for (std::size_t k = 0; k < run.trajectory.samples.size(); k += 2)
    coarse.samples.push_back(run.trajectory.samples[k]);
  if (run.trajectory.samples.size() % 2 == 0 && !run.trajectory.samples.empty())
    coarse.samples.push_back(run.trajectory.samples.back()); // the window's end stays covered
  s.pieces = std::max(1, s.pieces / 2);
  r.fem_coarse = accumulated_pressure_variance(coarse, run, s);
  return r;
}

nlohmann::json to_json(const ContinuumSds& c)
{
  return {{"line_hertz_sds_continuum", json_number(c.line_hertz)},
          {"fem_sds_continuum", json_number(c.fem)},
          {"fem_sds_continuum_change", json_number(c.change())},
          {"fem_sds_continuum_held_below_table", c.below_table}};
}
} // namespace rollcheck::study::loop_scores
