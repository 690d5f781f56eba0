// SDS over a whole rolling loop (study/loop_scores/loop_sds.h).
#include "study/loop_scores/loop_sds.h"
#include "contact/fatigue.h"
#include "contact/load_ratio.h"
#include "contact/ruling_load.h"
#include "contact/rim_dihedral_angle.h"
#include "contact/rim_overhang.h"
#include "core/error.h"
#include "core/json_number.h"
#include "fem/scenes/rim_end_contact.h"
#include "oracle/distribution_score.h"
#include <algorithm>
#include <chrono>
#include <fmt/format.h>
#include <cmath>
#include <limits>
#include <numbers>

namespace rollcheck::study::loop_scores
{
double half_width_over_radius(const LoadedEnd& end)
{
  return std::sqrt(4 * end.load_ratio / std::numbers::pi);
}

LoadedEnd finished_end(LoadedEnd end, double edge_radius_m)
{
  if (end.radius_m < edge_radius_m)
  {
    const double sharper = end.radius_m / edge_radius_m;
    end.line_hertz_pa *= std::sqrt(sharper);
    end.load_ratio *= sharper;
    end.radius_m = edge_radius_m;
  }
  return end;
}

namespace
{
SampleContact classify(const contact::ContactLocus& locus)
{
  if (locus.ruling)
    return locus.in_equilibrium ? SampleContact::ruling : SampleContact::tipping;
  return locus.support.kind == oracle::CircleSupportKind::point ? SampleContact::rim_point : SampleContact::flat_face;
}

/// Adds what each face holds, transform(its largest pressure among
/// `points`), to `all`, and to `even` if the sample is even.
template <typename Transform>
void add_face_peaks(const std::vector<std::pair<int, double>>& points, bool even_sample, Transform transform,
                    Eigen::VectorXd& all, Eigen::VectorXd& even)
{
  std::vector<std::pair<int, double>> peaks;
  for (const auto& [face, pressure] : points)
  {
    const auto it = std::find_if(peaks.begin(), peaks.end(), [&](const auto& fp) { return fp.first == face; });
    if (it == peaks.end())
      peaks.emplace_back(face, pressure);
    else
      it->second = std::max(it->second, pressure);
  }
  for (const auto& [face, peak] : peaks)
  {
    const double value = transform(peak);
    all[face] += value;
    if (even_sample)
      even[face] += value;
  }
}

RulingSample map_ruling(std::span<const oracle::Circle> circles, const contact::ContactLocus& locus,
                        const oracle::FaceCones& cones, double effective_modulus_pa, bool even,
                        const LoopSdsSettings& s)
{
  const oracle::Ruling& ruling = *locus.ruling;
  auto radius_at = [&](double f) { return (1 - f) * ruling.start_radius_m + f * ruling.end_radius_m; };
  auto load_at = [&](double f) { return oracle::line_load(s.normal_load_n, locus.centre_of_pressure, ruling.length_m, f); };
  const std::vector<double> along = mapping_fractions(locus.loaded_from, locus.loaded_to, s.map_points);
  const std::vector<int> faces = contact::faces_along_ruling(cones, locus, along);
  RulingSample sample;
  sample.even = even;
  for (std::size_t k = 0; k < along.size(); ++k)
  {
    const double f = contact::held_fraction(along[k], locus.loaded_from, locus.loaded_to, s.end_margin);
    const double q = load_at(f);
    if (!(q > 0) || !(radius_at(f) > 0))
      throw ComputationError("loop SDS: a mapping point inside the loaded ruling has no load or no radius");
    sample.points.push_back({faces[k],
                             line_hertz_peak(s.normal_load_n, locus.centre_of_pressure, ruling, effective_modulus_pa, f),
                             contact::load_ratio(q, radius_at(f), effective_modulus_pa)});
  }
  const bool start_loaded = locus.loaded_from == 0, end_loaded = locus.loaded_to == 1;
  if (!start_loaded && !end_loaded)
    return sample;
  const std::array<double, 2> lean
      = contact::rim_overhang(circles, locus.support.circles[0], locus.support.circles[1], ruling);
  const std::array<double, 2> dihedral
      = contact::rim_dihedral_angle(circles, locus.support.circles[0], locus.support.circles[1], ruling);
  for (const int end : {0, 1})
  {
    if (!(end == 0 ? start_loaded : end_loaded))
      continue;
    const double f = end;
    // The face of the sheet at the end, not of the face beyond the rim
    // (the cylinder's flat cap) that shares the rim point.
    const double fractions[1] = {end == 0 ? 1e-9 : 1 - 1e-9};
    sample.ends.push_back(
        {contact::faces_along_ruling(cones, locus, fractions)[0],
         line_hertz_peak(s.normal_load_n, locus.centre_of_pressure, ruling, effective_modulus_pa, f),
         contact::load_ratio(load_at(f), radius_at(f), effective_modulus_pa), std::numbers::pi / 2 + lean[end],
         radius_at(f), dihedral[end]});
  }
  return sample;
}

/// This rank's share of the samples: their sums not yet summed over the ranks.
LoopSamples share_of_samples(MPI_Comm comm, const LoopSource& source, const oracle::RollingBody& body,
                             const Eigen::VectorXd& face_peak_pressure_pa, const oracle::FaceCones& cones,
                             double effective_modulus_pa, const LoopSdsSettings& s)
{
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  const auto n_faces = body.face_areas.size();
  LoopSamples share;
  share.samples = source.rotations.size();
  share.face_areas = body.face_areas;
  share.point_all = share.point_even = share.line_all = share.line_even = Eigen::VectorXd::Zero(n_faces);
  share.load_ratio_min = std::numeric_limits<double>::infinity();
  for (std::size_t j = static_cast<std::size_t>(rank); j < source.rotations.size(); j += static_cast<std::size_t>(size))
  {
    const std::vector<int>* counted = source.oracle_faces.empty() ? nullptr : &source.oracle_faces[j];
    const contact::ContactLocus locus
        = contact::contact_locus(source.circles, source.centre_of_mass_m, body, source.rotations[j], s.locus, counted);
    const bool even = j % 2 == 0;
    for (const int f : locus.oracle_faces)
    {
      share.point_all[f] += face_peak_pressure_pa[f];
      if (even)
        share.point_even[f] += face_peak_pressure_pa[f];
    }
    const SampleContact contact = classify(locus);
    ++share.by_contact[static_cast<std::size_t>(contact)];
    if (contact != SampleContact::ruling)
      continue;
    RulingSample ruling = map_ruling(source.circles, locus, cones, effective_modulus_pa, even, s);
    std::vector<std::pair<int, double>> line_hertz;
    for (const MappedPoint& p : ruling.points)
    {
      share.load_ratio_min = std::min(share.load_ratio_min, p.load_ratio);
      share.load_ratio_max = std::max(share.load_ratio_max, p.load_ratio);
      line_hertz.emplace_back(p.face, p.line_hertz_pa);
    }
    add_face_peaks(line_hertz, even, [](double p) { return p; }, share.line_all, share.line_even);
    share.rulings.push_back(std::move(ruling));
  }
  return share;
}

void sum_over_ranks(MPI_Comm comm, Eigen::VectorXd& v)
{
  MPI_Allreduce(MPI_IN_PLACE, v.data(), static_cast<int>(v.size()), MPI_DOUBLE, MPI_SUM, comm);
}

/// The SDS of per-face sums over every sample and over the even ones.
ConvergedScore score_sums(const Eigen::VectorXd& all, const Eigen::VectorXd& even, const Eigen::VectorXd& areas,
                          bool any)
{
  if (!any)
    return {};
  return {oracle::distribution_score(all, areas), oracle::distribution_score(even, areas)};
}

/// The load ratio the table is read at: held at its least (slice_scaling.h).
double tabulated(double load_ratio) { return std::max(load_ratio, fem::SliceScaling::smallest_load_ratio); }

/// fem_scores' result: the scores and the per-face sums over every sample
/// they score, summed over the ranks.
struct FemFaceScores
{
  EndAwareScores scores;
  Eigen::VectorXd pressure_pa, fatigue_damage;
};

/// FEM-SDS and FEM-FDS over the ruling samples with the table of `stride`,
/// and with their loaded ends' pressures if `end_factor` is given: the load
/// ratio of an end held within the range the table covers for the points,
/// an end sharper across than `edge_radius_m` taken at it (end_aware_scores).
FemFaceScores fem_scores(MPI_Comm comm, const LoopSamples& samples, const fem::SliceScaling& table, int stride,
                          const LoopSdsSettings& s, const EndFactor* end_factor, double edge_radius_m = 0)
{
  const Eigen::VectorXd& areas = samples.face_areas;
  EndAwareScores out;
  Eigen::VectorXd sds_all = Eigen::VectorXd::Zero(areas.size()), sds_even = sds_all, fds_all = sds_all,
                  fds_even = sds_all;
  auto fem_pressure = [&](double line_hertz_pa, double load_ratio) {
    return line_hertz_pa * table.ratio(tabulated(load_ratio), stride);
  };
  // The preprint's amplitude of a contact stress cycle, corrected: p / 2.
  auto damage = [&](double p) { return contact::miner_damage_per_cycle(p / 2, s.fatigue); };
  for (const RulingSample& ruling : samples.rulings)
  {
    std::vector<std::pair<int, double>> points;
    for (const MappedPoint& p : ruling.points)
      points.emplace_back(p.face, fem_pressure(p.line_hertz_pa, p.load_ratio));
    bool outside_model = false;
    if (end_factor)
      for (const LoadedEnd& hull_end : ruling.ends)
      {
        const bool finished = hull_end.radius_m < edge_radius_m;
        out.finished_ends += finished;
        const LoadedEnd end = finished_end(hull_end, edge_radius_m);
        const double width_ratio = half_width_over_radius(end);
        if (!(width_ratio < fem::largest_half_width_over_radius))
        {
          ++out.outside_model_ends;
          outside_model = true;
          continue;
        }
        const std::optional<double> factor = (*end_factor)(end);
        if (!factor)
        {
          ++out.singular_ends;
          continue;
        }
        const double p = *factor * fem_pressure(end.line_hertz_pa, std::clamp(end.load_ratio, samples.load_ratio_min,
                                                                               samples.load_ratio_max));
        out.peak_pa = std::max(out.peak_pa, p);
        double& peak_of_kind = finished ? out.finished_peak_pa : out.unfinished_peak_pa;
        peak_of_kind = std::max(peak_of_kind, p);
        if (width_ratio < fem::largest_half_width_over_radius / 2)
          out.peak_within_half_limit_pa = std::max(out.peak_within_half_limit_pa, p);
        points.emplace_back(end.face, p);
      }
    out.outside_model_samples += outside_model;
    add_face_peaks(points, ruling.even, [](double p) { return p; }, sds_all, sds_even);
    add_face_peaks(points, ruling.even, damage, fds_all, fds_even);
  }
  for (std::size_t* count :
       {&out.singular_ends, &out.outside_model_ends, &out.outside_model_samples, &out.finished_ends})
    MPI_Allreduce(MPI_IN_PLACE, count, 1, MPI_UNSIGNED_LONG, MPI_SUM, comm);
  for (double* peak : {&out.peak_pa, &out.peak_within_half_limit_pa, &out.finished_peak_pa, &out.unfinished_peak_pa})
  {
    MPI_Allreduce(MPI_IN_PLACE, peak, 1, MPI_DOUBLE, MPI_MAX, comm);
    if (out.singular_ends > 0)
      *peak = 0;
  }
  // An end with no pressure leaves the scores undefined, not smaller.
  const bool defined = out.singular_ends == 0 && out.outside_model_ends == 0;
  for (Eigen::VectorXd* sums : {&sds_all, &sds_even, &fds_all, &fds_even})
    sum_over_ranks(comm, *sums);
  out.sds = score_sums(sds_all, sds_even, areas, defined);
  out.fds = score_sums(fds_all, fds_even, areas, defined);
  return {out, std::move(sds_all), std::move(fds_all)};
}

/// Nodes of the table with stride `stride` that interpolation over [lo, hi] uses.
std::size_t nodes_used(const fem::SliceScaling& table, double lo, double hi, int stride, double& worst_change)
{
  const double n = table.nodes_per_decade();
  const int first = stride * static_cast<int>(std::floor(n * std::log10(lo) / stride));
  const int last = stride * static_cast<int>(std::ceil(n * std::log10(hi) / stride));
  std::size_t count = 0;
  for (const auto& [k, node] : table.nodes())
    if (k >= first && k <= last && k % stride == 0)
    {
      ++count;
      worst_change = std::max(worst_change, std::abs(node.refined_ratio / node.ratio - 1));
    }
  return count;
}
} // namespace

const char* sample_contact_name(SampleContact contact)
{
  static const char* names[] = {"ruling", "rim point", "flat face", "tipping ruling"};
  return names[static_cast<int>(contact)];
}

double ConvergedScore::sample_change() const
{
  return value && half_samples ? *value / *half_samples - 1 : std::numeric_limits<double>::quiet_NaN();
}

double LoopSds::table_change() const
{
  return fem_rulings.value && fem_half_table ? *fem_rulings.value / *fem_half_table - 1
                                             : std::numeric_limits<double>::quiet_NaN();
}

bool LoopSds::converged() const
{
  return std::abs(table_change()) < tolerance && std::abs(fem_rulings.sample_change()) < tolerance;
}

std::string LoopSds::status() const
{
  if (singular_samples > 0)
  {
    std::string kinds;
    for (const auto& [name, count] : samples_by_contact)
      if (name != sample_contact_name(SampleContact::ruling))
        kinds += fmt::format("{}{} on a {}", kinds.empty() ? "" : ", ", count, name);
    return fmt::format("singular: {} of {} samples stand on a sharp edge ({})", singular_samples, samples, kinds);
  }
  if (converged())
    return "converged";
  return fmt::format("not converged: doubling the FEM table changes FEM-SDS by {:+.2f} %, halving the samples by "
                     "{:+.2f} % (tolerance {:.2g} %)",
                     100 * table_change(), 100 * fem_rulings.sample_change(), 100 * tolerance);
}

std::vector<double> mapping_fractions(double loaded_from, double loaded_to, int points)
{
  std::vector<double> along;
  for (int k = 0; k < points; ++k)
    along.push_back(loaded_from + (loaded_to - loaded_from) * (k + 0.5) / points);
  return along;
}

double line_hertz_peak(double force_n, double centre_of_pressure, const oracle::Ruling& ruling,
                       double effective_modulus_pa, double f)
{
  const double q = oracle::line_load(force_n, centre_of_pressure, ruling.length_m, f);
  const double radius = (1 - f) * ruling.start_radius_m + f * ruling.end_radius_m;
  return q > 0 ? std::sqrt(q * effective_modulus_pa / (std::numbers::pi * radius)) : 0.0;
}

LoopSamples map_loop_samples(MPI_Comm comm, const LoopSource& source, const oracle::RollingBody& body,
                             const Eigen::VectorXd& face_peak_pressure_pa, const oracle::FaceCones& cones,
                             double effective_modulus_pa, const LoopSdsSettings& s)
{
  if (source.rotations.empty())
    throw ComputationError("loop SDS: the loop has no samples");
  const auto start = std::chrono::steady_clock::now();
  LoopSamples samples = share_of_samples(comm, source, body, face_peak_pressure_pa, cones, effective_modulus_pa, s);
  MPI_Allreduce(MPI_IN_PLACE, samples.by_contact.data(), 4, MPI_UNSIGNED_LONG, MPI_SUM, comm);
  for (Eigen::VectorXd* sums : {&samples.point_all, &samples.point_even, &samples.line_all, &samples.line_even})
    sum_over_ranks(comm, *sums);
  MPI_Allreduce(MPI_IN_PLACE, &samples.load_ratio_min, 1, MPI_DOUBLE, MPI_MIN, comm);
  MPI_Allreduce(MPI_IN_PLACE, &samples.load_ratio_max, 1, MPI_DOUBLE, MPI_MAX, comm);
  if (samples.ruling_count() == 0)
    samples.load_ratio_min = samples.load_ratio_max = 0;
  samples.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  MPI_Allreduce(MPI_IN_PLACE, &samples.wall_s, 1, MPI_DOUBLE, MPI_MAX, comm);
  return samples;
}

LoopSds loop_sds(MPI_Comm comm, const LoopSamples& samples, fem::SliceScaling& table, const LoopSdsSettings& s)
{
  LoopSds r;
  r.samples = samples.samples;
  r.tolerance = s.tolerance;
  for (std::size_t c = 0; c < samples.by_contact.size(); ++c)
    if (samples.by_contact[c] > 0)
      r.samples_by_contact[sample_contact_name(static_cast<SampleContact>(c))] = samples.by_contact[c];
  const std::size_t rulings = samples.ruling_count();
  r.singular_samples = r.samples - rulings;
  const Eigen::VectorXd& areas = samples.face_areas;
  r.point_hertz = score_sums(samples.point_all, samples.point_even, areas, true);
  r.line_hertz_rulings = score_sums(samples.line_all, samples.line_even, areas, rulings > 0);
  r.samples_wall_s = samples.wall_s;
  r.accumulated_fem_pressure_pa = r.accumulated_fem_fatigue_damage = Eigen::VectorXd::Zero(areas.size());
  if (rulings > 0)
  {
    r.load_ratio_min = samples.load_ratio_min;
    r.load_ratio_max = samples.load_ratio_max;
    while (true)
    {
      table.cover(comm, tabulated(samples.load_ratio_min), tabulated(samples.load_ratio_max));
      FemFaceScores interior = fem_scores(comm, samples, table, 1, s, nullptr);
      r.fem_rulings = interior.scores.sds;
      r.fem_fds_rulings = interior.scores.fds;
      r.accumulated_fem_pressure_pa = std::move(interior.pressure_pa);
      r.accumulated_fem_fatigue_damage = std::move(interior.fatigue_damage);
      r.fem_half_table = fem_scores(comm, samples, table, 2, s, nullptr).scores.sds.value;
      if (std::abs(r.table_change()) < s.tolerance || 2 * table.nodes_per_decade() > s.max_nodes_per_decade)
        break;
      table.double_nodes();
    }
    for (const RulingSample& ruling : samples.rulings)
      for (const MappedPoint& p : ruling.points)
      {
        r.line_hertz_peak_pa = std::max(r.line_hertz_peak_pa, p.line_hertz_pa);
        r.fem_peak_pa = std::max(r.fem_peak_pa, p.line_hertz_pa * table.ratio(tabulated(p.load_ratio)));
        r.points_below_table += p.load_ratio < fem::SliceScaling::smallest_load_ratio;
        ++r.mapped_points;
      }
    MPI_Allreduce(MPI_IN_PLACE, &r.line_hertz_peak_pa, 1, MPI_DOUBLE, MPI_MAX, comm);
    MPI_Allreduce(MPI_IN_PLACE, &r.fem_peak_pa, 1, MPI_DOUBLE, MPI_MAX, comm);
    MPI_Allreduce(MPI_IN_PLACE, &r.points_below_table, 1, MPI_UNSIGNED_LONG, MPI_SUM, comm);
    MPI_Allreduce(MPI_IN_PLACE, &r.mapped_points, 1, MPI_UNSIGNED_LONG, MPI_SUM, comm);
    r.nodes_per_decade = table.nodes_per_decade();
    r.loaded_end_angle_min_rad = std::numeric_limits<double>::infinity();
    r.loaded_end_angle_max_rad = -r.loaded_end_angle_min_rad;
    for (const RulingSample& ruling : samples.rulings)
    {
      r.loaded_end_samples += !ruling.ends.empty();
      r.loaded_ends += ruling.ends.size();
      for (const LoadedEnd& end : ruling.ends)
      {
        r.loaded_end_angle_min_rad = std::min(r.loaded_end_angle_min_rad, end.interior_angle_rad);
        r.loaded_end_angle_max_rad = std::max(r.loaded_end_angle_max_rad, end.interior_angle_rad);
      }
    }
    MPI_Allreduce(MPI_IN_PLACE, &r.loaded_end_samples, 1, MPI_UNSIGNED_LONG, MPI_SUM, comm);
    MPI_Allreduce(MPI_IN_PLACE, &r.loaded_ends, 1, MPI_UNSIGNED_LONG, MPI_SUM, comm);
    MPI_Allreduce(MPI_IN_PLACE, &r.loaded_end_angle_min_rad, 1, MPI_DOUBLE, MPI_MIN, comm);
    MPI_Allreduce(MPI_IN_PLACE, &r.loaded_end_angle_max_rad, 1, MPI_DOUBLE, MPI_MAX, comm);
    if (r.loaded_ends == 0)
      r.loaded_end_angle_min_rad = r.loaded_end_angle_max_rad = 0;
    const double lo = tabulated(samples.load_ratio_min), hi = tabulated(samples.load_ratio_max);
    r.fem_solves = nodes_used(table, lo, hi, 1, r.worst_refinement_change);
    r.fem_solves_half_table = nodes_used(table, lo, hi, 2, r.worst_refinement_change);
  }
  if (r.singular_samples == 0)
  {
    r.line_hertz = r.line_hertz_rulings;
    r.fem = r.fem_rulings;
  }
  return r;
}

std::vector<EndAwareScores> end_aware_scores(MPI_Comm comm, const LoopSamples& samples,
                                             const fem::SliceScaling& table, const LoopSdsSettings& s,
                                             std::span<const EndFactor> end_factors, double edge_radius_m)
{
  if (!(edge_radius_m >= 0) || !std::isfinite(edge_radius_m))
    throw InputError(fmt::format("loop SDS: the edge radius must be >= 0 and finite, got {}", edge_radius_m));
  std::vector<EndAwareScores> scores;
  if (samples.ruling_count() == 0)
    return scores;
  for (const EndFactor& factor : end_factors)
    scores.push_back(fem_scores(comm, samples, table, 1, s, &factor, edge_radius_m).scores);
  return scores;
}

nlohmann::json to_json(const LoopSds& loop)
{
  auto score = [&](const ConvergedScore& c) {
    return nlohmann::json{{"value", json_number(c.value)},
                          {"half_samples", json_number(c.half_samples)},
                          {"sample_change", json_number_or_null(c.sample_change())}};
  };
  nlohmann::json end_aware = nlohmann::json::array();
  for (const EndAwareScores& e : loop.end_aware)
    end_aware.push_back({{"fem_sds", score(e.sds)},
                         {"fem_fds", score(e.fds)},
                         {"singular_ends", e.singular_ends},
                         {"outside_model_ends", e.outside_model_ends},
                         {"outside_model_samples", e.outside_model_samples},
                         {"finished_ends", e.finished_ends},
                         {"finished_end_peak_pa", e.finished_peak_pa},
                         {"unfinished_end_peak_pa", e.unfinished_peak_pa},
                         {"end_peak_within_half_limit_pa",
                          e.singular_ends > 0 ? nlohmann::json(nullptr) : json_number(e.peak_within_half_limit_pa)},
                         {"end_peak_pa", e.singular_ends > 0 ? nlohmann::json(nullptr) : json_number(e.peak_pa)}});
  nlohmann::json by_contact = nlohmann::json::object();
  for (const auto& [name, count] : loop.samples_by_contact)
    by_contact[name] = count;
  nlohmann::json out = {{"samples", loop.samples},
          {"samples_by_contact", by_contact},
          {"singular_samples", loop.singular_samples},
          {"point_hertz_sds", score(loop.point_hertz)},
          {"line_hertz_sds", score(loop.line_hertz)},
          {"fem_sds", score(loop.fem)},
          {"line_hertz_sds_rulings", score(loop.line_hertz_rulings)},
          {"fem_sds_rulings", score(loop.fem_rulings)},
          {"fem_fds_rulings", score(loop.fem_fds_rulings)},
          {"loaded_end_samples", loop.loaded_end_samples},
          {"loaded_ends", loop.loaded_ends},
          {"loaded_end_angle_min_deg", loop.loaded_end_angle_min_rad * 180 / std::numbers::pi},
          {"loaded_end_angle_max_deg", loop.loaded_end_angle_max_rad * 180 / std::numbers::pi},
          {"fem_sds_half_table", json_number(loop.fem_half_table)},
          {"fem_sds_table_change", json_number_or_null(loop.table_change())},
          {"fem_solves", loop.fem_solves},
          {"fem_solves_half_table", loop.fem_solves_half_table},
          {"table_nodes_per_decade", loop.nodes_per_decade},
          {"load_ratio_min", json_number(loop.load_ratio_min)},
          {"load_ratio_max", json_number(loop.load_ratio_max)},
          {"fem_worst_refinement_change", json_number(loop.worst_refinement_change)},
          {"line_hertz_peak_pa", json_number(loop.line_hertz_peak_pa)},
          {"fem_peak_pa", json_number(loop.fem_peak_pa)},
          {"mapped_points", loop.mapped_points},
          {"points_below_table", loop.points_below_table},
          {"smallest_table_load_ratio", json_number(fem::SliceScaling::smallest_load_ratio)},
          {"tolerance", json_number(loop.tolerance)},
          {"converged", loop.converged()},
          {"status", loop.status()},
          {"samples_wall_s", json_number(loop.samples_wall_s)}};
  if (!loop.end_aware.empty())
    out["end_aware"] = end_aware;
  return out;
}

nlohmann::json headline_json(const LoopSds& loop)
{
  return {{"samples", loop.samples},
          {"singular_samples", loop.singular_samples},
          {"line_hertz_sds", json_number(loop.line_hertz.value)},
          {"fem_sds", json_number(loop.fem.value)},
          {"fem_sds_status", loop.status()},
          {"fem_sds_table_change", json_number_or_null(loop.table_change())},
          {"fem_sds_sample_change", json_number_or_null(loop.fem_rulings.sample_change())}};
}
} // namespace rollcheck::study::loop_scores
