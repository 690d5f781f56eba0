// FEM-SDS on the exact surface (study/loop_scores/fem_sds_continuum.h).
#include "study/loop_scores/fem_sds_continuum.h"
#include "core/error.h"
#include "core/json_number.h"
#include "fem/first_failure.h"
#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <fmt/format.h>

namespace rollcheck::study::loop_scores
{
namespace
{
/// The loop's moments, each rank integrating its part of the window, summed over `comm`.
contact::ContinuumMoments loop_moments(MPI_Comm comm, const oracle::RollingTrajectory& trajectory,
                                       const oracle::RealRolling& run, const contact::ContinuumLoopSettings& s)
{
  int rank = 0, ranks = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &ranks);
  const double end = std::isfinite(run.first_loop_end_s) ? run.first_loop_end_s : run.scored_end_s;
  // fem-sds rolls the body under the rolling study's default gravity.
  const contact::RollingBodyMass mass{run.mass.centre_of_mass_m, run.mass.mass_kg,
                                      oracle::RollingStudyParameters{}.gravity_m_s2};
  // A part that fails on one rank only must not leave the others waiting in the sums.
  contact::ContinuumMoments m;
  int exit_code = 0;
  std::string failure;
  try
  {
    m = contact::continuum_loop_moments(trajectory, 0, end, mass, s, {rank, ranks});
  }
  catch (const InputError& e)
  {
    exit_code = 2, failure = e.what();
  }
  catch (const ComputationError& e)
  {
    exit_code = 1, failure = e.what();
  }
  if (const std::optional<fem::RankFailure> first = fem::first_failure(comm, exit_code, failure))
  {
    if (first->exit_code == 2)
      throw InputError(first->message);
    throw ComputationError(first->message);
  }
  constexpr int q = contact::ContinuumMoments::quantities;
  for (std::array<double, q>* sums : {&m.area, &m.first, &m.second})
    MPI_Allreduce(MPI_IN_PLACE, sums->data(), q, MPI_DOUBLE, MPI_SUM, comm);
  MPI_Allreduce(MPI_IN_PLACE, &m.swept, 1, MPI_DOUBLE, MPI_SUM, comm);
  MPI_Allreduce(MPI_IN_PLACE, &m.second_factor.first, 1, MPI_DOUBLE, MPI_SUM, comm);
  MPI_Allreduce(MPI_IN_PLACE, &m.second_factor.second, 1, MPI_DOUBLE, MPI_SUM, comm);
  MPI_Allreduce(MPI_IN_PLACE, m.max.data(), q, MPI_DOUBLE, MPI_MAX, comm);
  MPI_Allreduce(MPI_IN_PLACE, &m.second_factor.max, 1, MPI_DOUBLE, MPI_MAX, comm);
  MPI_Allreduce(MPI_IN_PLACE, &m.load_ratio_max, 1, MPI_DOUBLE, MPI_MAX, comm);
  MPI_Allreduce(MPI_IN_PLACE, &m.load_ratio_min, 1, MPI_DOUBLE, MPI_MIN, comm);
  return m;
}

double accumulated_pressure_variance(MPI_Comm comm, const oracle::RollingTrajectory& trajectory,
                                     const oracle::RealRolling& run, const contact::ContinuumLoopSettings& s,
                                     contact::ContinuumLoopScores* all = nullptr)
{
  const contact::ContinuumLoopScores scores
      = contact::continuum_loop_scores(loop_moments(comm, trajectory, run, s), run.surface_area_m2, s);
  if (all)
    *all = scores;
  return scores.accumulated_pressure.whole;
}
} // namespace

ContinuumSds continuum_sds(MPI_Comm comm, const oracle::RealRolling& run, contact::ContinuumLoopSettings s,
                           fem::SliceScaling& table, const ContinuumTableRefinement& refinement)
{
  ContinuumSds r;
  r.tolerance = refinement.tolerance;
  s.pressure_factor = nullptr; // line Hertz first: g = 1
  s.pressure_factors = nullptr;
  s.accumulated_pressure_only = true;
  contact::ContinuumLoopScores line;
  r.line_hertz = accumulated_pressure_variance(comm, run.trajectory, run, s, &line);
  r.load_ratio_min = line.load_ratio_min;
  r.load_ratio_max = line.load_ratio_max;
  const double least = fem::SliceScaling::smallest_load_ratio;
  r.below_table = r.load_ratio_min < least;
  while (true)
  {
    table.cover(comm, std::max(r.load_ratio_min, least), std::max(r.load_ratio_max, least));
    // The table and its half in one pass.
    s.pressure_factors = [&table, least](double lambda) { return table.ratios(std::max(lambda, least)); };
    contact::ContinuumLoopScores both;
    r.fem = accumulated_pressure_variance(comm, run.trajectory, run, s, &both);
    r.fem_half_table = both.accumulated_pressure_second_factor.whole;
    if (std::abs(r.table_change()) < refinement.tolerance
        || 2 * table.nodes_per_decade() > refinement.max_nodes_per_decade)
      break;
    table.double_nodes();
  }
  r.nodes_per_decade = table.nodes_per_decade();
  s.pressure_factors = nullptr;
  s.pressure_factor = [&table, least](double lambda) { return table.ratio(std::max(lambda, least)); };
  oracle::RollingTrajectory coarse = run.trajectory;
  coarse.samples.clear();
  for (std::size_t k = 0; k < run.trajectory.samples.size(); k += 2)
    coarse.samples.push_back(run.trajectory.samples[k]);
  if (run.trajectory.samples.size() % 2 == 0 && !run.trajectory.samples.empty())
    coarse.samples.push_back(run.trajectory.samples.back()); // the window's end stays covered
  s.pieces = std::max(1, s.pieces / 2);
  r.fem_coarse = accumulated_pressure_variance(comm, coarse, run, s);
  return r;
}

std::string ContinuumSds::status() const
{
  if (converged())
    return "converged";
  return fmt::format("not converged: halving the samples and pieces changes the continuum value by {:+.2f} %, "
                     "halving the FEM table by {:+.2f} % (tolerance {:.2g} %)",
                     100 * change(), 100 * table_change(), 100 * tolerance);
}

nlohmann::json to_json(const ContinuumSds& c)
{
  return {{"line_hertz_sds_continuum", json_number(c.line_hertz)},
          {"fem_sds_continuum", json_number(c.fem)},
          {"fem_sds_continuum_change", json_number(c.change())},
          {"fem_sds_continuum_table_change", json_number(c.table_change())},
          {"fem_sds_continuum_status", c.status()},
          {"fem_sds_continuum_held_below_table", c.below_table}};
}
} // namespace rollcheck::study::loop_scores
