// The rims over a body's rolling loop (study/rims/rim_loop.h).
#include "study/rims/rim_loop.h"
#include "contact/edge_on_elastic_block_exponent.h"
#include "contact/hertz.h"
#include "contact/wedge_exponent.h"
#include "core/error.h"
#include "core/json_number.h"
#include "fem/petsc_session.h"
#include "fem/mesh/scene_mesh.h"
#include "fem/scenes/slice_scaling.h"
#include "oracle/contact_density.h"
#include <algorithm>
#include <chrono>
#include <cmath>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <limits>
#include <numbers>
#include <span>
#include <spdlog/spdlog.h>

namespace rollcheck::study::rims
{
namespace
{
constexpr double degree = std::numbers::pi / 180;
/// The end model's range of interior angles (fem/scenes/rim_end_contact.h), 180 deg open.
constexpr double smallest_modelled_angle = 60 * degree, largest_modelled_angle = 179.5 * degree;
/// A rounded edge's largest: OpenCASCADE finds no edge to fillet between
/// faces this close to tangent (176 deg failed, 170 deg meshed); ends above
/// it are modelled at it, where the rounded end's ratio no longer changes
/// with the angle (the oloid's table: 1.945 and 1.939 at 142 and 161 deg).
constexpr double largest_rounded_angle = 170 * degree;

double largest_angle(const fem::RimEndSettings& end)
{
  return end.edge_radius_m > 0 ? largest_rounded_angle : largest_modelled_angle;
}

/// The bisection's tolerance on the angle where sharp edges turn singular.
constexpr double singular_angle_tolerance = 1e-10;

double sharp_edge_exponent(const fem::RimEndSettings& end, double interior_angle_rad)
{
  return end.counter_face == fem::CounterFace::rigid
             ? contact::edge_on_rigid_plane_exponent(interior_angle_rad)
             : contact::edge_on_elastic_block_exponent(interior_angle_rad, end.youngs_modulus_pa, end.poisson_ratio,
                                                       end.youngs_modulus_pa, end.poisson_ratio);
}

double median(std::vector<double> values)
{
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

/// Line Hertz's b of an end model's q and R against its counter-face.
double half_width(const fem::RimEndSettings& e)
{
  const double modulus
      = contact::effective_modulus(e.youngs_modulus_pa, e.poisson_ratio, e.counter_face == fem::CounterFace::block);
  return contact::line_contact(e.load_n_per_m, e.radius_m, modulus, e.poisson_ratio).half_width_m;
}

fem::RimEndSettings end_settings(const RimLoopSettings& s, double radius_m, double load_n_per_m, double angle_rad)
{
  fem::RimEndSettings e = s.end;
  e.radius_m = radius_m;
  e.load_n_per_m = load_n_per_m;
  e.interior_angle_rad = std::clamp(angle_rad, smallest_modelled_angle, largest_angle(s.end));
  e.youngs_modulus_pa = s.loop.youngs_modulus_pa;
  e.poisson_ratio = s.loop.poisson_ratio;
  e.xdmf_path.clear(); // one end's fields, not the loop's
  e.resolve_boundary_layer = true; // every end's ratio is a number of the end, not of the mesh
  // An end whose levels still differ gets a third, as a flat-rim node does:
  // the preprint's body's steel end table had 4 of 15 nodes at 3.3-6.4 %
  // per level (docs/rim-results.md).
  e.extra_levels = std::max(e.extra_levels, 1);
  // The fillet must fit in the block, and b varies from end to end: deepen
  // the block where the setting's H / b would be too shallow for this end's b.
  if (e.edge_radius_m > 0)
    e.depth_over_half_width
        = std::max(e.depth_over_half_width, s.depth_over_edge_radius * e.edge_radius_m / half_width(e));
  return e;
}

/// The end models at every loaded end of the directly solved orientations.
std::vector<RimLoopEnd> direct_ends(MPI_Comm comm, const RimLoopSettings& s, const loop_scores::FemSdsResult& interior)
{
  std::vector<RimLoopEnd> ends;
  // Each end's load control starts from the end before's converged approach
  // over its estimate, as the end table's nodes do: the estimate overshoots
  // a held block's approach by about 20 % whatever the end's q and R.
  double approach_over_estimate = 1;
  for (const loop_scores::FemSdsOrientation& r : interior.orientations)
  {
    if (!r.solved)
      continue;
    const oracle::Ruling& ruling = *r.locus.ruling;
    for (const int end : {0, 1})
    {
      const bool loaded = end == 0 ? r.locus.loaded_from == 0 : r.locus.loaded_to == 1;
      const double q = oracle::line_load(s.loop.normal_load_n, r.locus.centre_of_pressure, ruling.length_m, end);
      if (!loaded || !(q > 0))
        continue;
      RimLoopEnd e;
      e.orientation = r.index;
      e.end = end;
      e.interior_angle_rad = std::numbers::pi / 2 + r.rim_overhang_rad[static_cast<std::size_t>(end)];
      // A rounded part's finish leaves no radius below r_e (study/loop_scores/loop_sds.h loop_scores::end_aware_scores).
      const double hull_radius = end == 0 ? ruling.start_radius_m : ruling.end_radius_m;
      fem::RimEndSettings settings
          = end_settings(s, std::max(hull_radius, s.end.edge_radius_m), q, e.interior_angle_rad);
      settings.first_approach_scale = approach_over_estimate;
      e.modelled_angle_rad = settings.interior_angle_rad;
      const double b = half_width(settings);
      if (!(b < fem::largest_half_width_over_radius * settings.radius_m))
      {
        e.study.setup = settings;
        e.study.half_width_m = b;
        e.outside_model = fmt::format("b / R = {:.2f}: near its sheet's apex the contact is no line contact (the end "
                                      "model needs b / R < {:.1f})",
                                      b / settings.radius_m, fem::largest_half_width_over_radius);
        ends.push_back(std::move(e));
        continue;
      }
      e.study = fem::solve_rim_end(comm, settings);
      approach_over_estimate = e.study.approach_over_estimate();
      e.interior_peak_pa = r.fem_peak_pa;
      if (e.study.end_to_interior && e.study.resolved && !e.study.singular)
        e.end_peak_pa = *e.study.end_to_interior * e.study.levels.back().far_peak_pa;
      ends.push_back(std::move(e));
    }
  }
  return ends;
}

/// The flat-rim table over [from, the loop's flattest loaded end]: the
/// loop's own ends at those angles solved by half-space theory, the solves
/// shared out over the ranks (each is serial); from flat_rim_table_start's
/// node on when some are refused, `refused` then naming them.
struct FlatRimTable
{
  std::vector<FlatRimNode> nodes;
  std::string refused;
};
FlatRimTable flat_rim_table(MPI_Comm comm, const RimLoopSettings& s, const loop_scores::FemSdsResult& interior, double from);

/// Nodes evenly over [lo, hi], an odd number of them (every other one is a
/// table too), at most `step` apart; one where the range is a point.
std::vector<double> even_nodes(double lo, double hi, double step)
{
  if (!(hi - lo > 1e-9))
    return {lo};
  // Less 1e-9: a range of exactly 2 k steps (30 deg at 15, in radians) has k halves, not k + 1.
  const int halves = std::max(1, static_cast<int>(std::ceil((hi - lo) / (2 * step) - 1e-9)));
  std::vector<double> angles;
  for (int k = 0; k <= 2 * halves; ++k)
    angles.push_back(lo + (hi - lo) * k / (2 * halves));
  return angles;
}
FlatRimTable flat_rim_table(MPI_Comm comm, const RimLoopSettings& s, const loop_scores::FemSdsResult& interior, double from)
{
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  const FlattestLoopEnds found
      = flattest_loop_ends_below(interior.circles, interior.centre_of_mass_m, [&](double flattest) {
          std::vector<double> angles = even_nodes(std::min(from, flattest), flattest, s.flat_rim_step_rad);
          angles.pop_back(); // the flattest itself
          return angles;
        });
  std::vector<std::vector<LoopEnd>> ends;
  for (const std::array<LoopEnd, 2>& sides : found.at_angle)
  {
    const bool mirrored = std::abs(sides[0].centre_of_pressure_from_end() - sides[1].centre_of_pressure_from_end()) < 1e-6
                          && std::abs(sides[0].radius_m() - sides[1].radius_m()) < 1e-6 * sides[0].ruling.length_m;
    ends.push_back(mirrored ? std::vector<LoopEnd>{sides[0]} : std::vector<LoopEnd>{sides[0], sides[1]});
  }
  ends.push_back({found.flattest});

  FlatRimSettings setup;
  setup.normal_load_n = s.loop.normal_load_n;
  setup.edge_radius_m = s.end.edge_radius_m;
  setup.youngs_modulus_pa = s.loop.youngs_modulus_pa;
  setup.poisson_ratio = s.loop.poisson_ratio;
  setup.steel_counter_face = s.end.counter_face == fem::CounterFace::block;
  setup.tolerance = s.end.tolerance;
  // A node whose cells do not yet resolve its end gets a third level (the
  // U optimum's 178 deg side on steel, -8.44 % at b/8, -0.44 % at b/16; the
  // FEM-SDS optimum's vertex on steel, +3.98 % then -2.41 %: docs/flat-rim.md).
  setup.extra_levels = 1;
  // Each rank solves its share; the others' values stay 0, so a sum shares them.
  // The last value of a slot is the contact's largest slope, or -1 for a
  // failed solve: a node whose solve failed or whose contact meets slopes
  // too steep for half-space theory (an end beside a crease of the hull)
  // is refused alike on every rank.
  constexpr std::size_t per_end = 14;
  constexpr double largest_slope = 0.1;
  std::vector<double> values;
  int job = 0;
  for (const std::vector<LoopEnd>& node_ends : ends)
    for (const LoopEnd& end : node_ends)
    {
      std::array<double, per_end> v{};
      if (job++ % size == rank)
        try
        {
          FlatRimContact r = flat_rim_contact(setup, end);
          double window_peak = 0;
          if (needs_whole_ruling(setup, r))
          {
            // The fuller model: no window to shorten.
            window_peak = r.levels.back().peak_pressure_pa;
            FlatRimSettings whole = setup;
            whole.whole_ruling = true;
            const double window_wall_s = r.wall_s;
            r = flat_rim_contact(whole, end);
            r.wall_s += window_wall_s;
          }
          v = {r.centre_of_pressure, r.end_line_load_n_per_m, r.end_radius_m, r.levels.back().peak_pressure_pa,
               r.line_hertz_peak_pa, r.last_change, r.window_change, r.converged ? 1.0 : 0.0, r.wall_s,
               r.after_over_half_width, r.across_scale, r.whole_ruling ? 1.0 : 0.0, window_peak, r.largest_slope};
        }
        catch (const ComputationError& e)
        {
          // Logged where it failed: the slot carries only the fact.
          spdlog::warn("rim loop: flat-rim at {:.2f} deg failed: {}", end.interior_angle_rad / degree, e.what());
          v.back() = -1;
        }
      values.insert(values.end(), v.begin(), v.end());
    }
  MPI_Allreduce(MPI_IN_PLACE, values.data(), static_cast<int>(values.size()), MPI_DOUBLE, MPI_SUM, comm);
  std::vector<FlatRimNode> table;
  std::vector<bool> refused;
  std::vector<std::string> refused_angles;
  const double* v = values.data();
  for (const std::vector<LoopEnd>& node_ends : ends)
  {
    FlatRimNode& node = table.emplace_back();
    node.interior_angle_rad = node_ends.front().interior_angle_rad;
    bool failed = false;
    double slope = 0;
    for (std::size_t k = 0; k < node_ends.size(); ++k, v += per_end)
    {
      failed = failed || v[per_end - 1] < 0;
      slope = std::max(slope, v[per_end - 1]);
      node.sides.push_back({v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7] > 0.5, v[8], v[9], v[10], v[11] > 0.5, v[12]});
    }
    refused.push_back(failed || slope > largest_slope);
    if (refused.back())
      refused_angles.push_back(failed ? fmt::format("{:.2f} deg (its solve failed)", node.interior_angle_rad / degree)
                                      : fmt::format("{:.2f} deg (slope {:.3f})", node.interior_angle_rad / degree,
                                                    slope));
  }
  if (refused_angles.empty())
    return {std::move(table), ""};
  const std::string why = fmt::format("half-space theory refused at the ends of {} (it needs slopes of at most "
                                      "{} over the contact)",
                                      fmt::join(refused_angles, ", "), largest_slope);
  const std::optional<std::size_t> start = flat_rim_table_start(refused);
  if (!start)
    throw ComputationError(why);
  table.erase(table.begin(), table.begin() + static_cast<std::ptrdiff_t>(*start));
  std::string refused_nodes = fmt::format("{}; the table starts at {:.2f} deg, the FEM end table takes the ends below",
                                          why, table.front().interior_angle_rad / degree);
  return {std::move(table), std::move(refused_nodes)};
}
} // namespace

double FlatRimNode::peak_pa() const
{
  return std::ranges::max(sides, {}, &FlatRimSide::peak_pressure_pa).peak_pressure_pa;
}

double FlatRimNode::ratio() const
{
  const auto ratio_of = [](const FlatRimSide& side) { return side.peak_pressure_pa / side.line_hertz_peak_pa; };
  return ratio_of(std::ranges::max(sides, {}, ratio_of));
}

bool FlatRimNode::converged() const
{
  return std::ranges::all_of(sides, [](const FlatRimSide& side) { return side.converged; });
}

double singular_from_angle(const fem::RimEndSettings& end)
{
  if (end.edge_radius_m > 0)
    return std::numbers::pi;
  // Singular as the end model calls it (fem/scenes/rim_end_contact.h): any negative exponent.
  auto singular = [&](double a) { return sharp_edge_exponent(end, a) < 0; };
  double lo = smallest_modelled_angle, hi = largest_modelled_angle;
  if (singular(lo))
    return lo;
  if (!singular(hi))
    return std::numbers::pi;
  while (hi - lo > singular_angle_tolerance)
  {
    const double mid = 0.5 * (lo + hi);
    (singular(mid) ? hi : lo) = mid;
  }
  return hi;
}

std::optional<std::size_t> flat_rim_table_start(const std::vector<bool>& refused)
{
  const auto last_refused = std::find(refused.rbegin(), refused.rend(), true);
  if (last_refused == refused.rend())
    return 0;
  std::size_t start = refused.size() - static_cast<std::size_t>(last_refused - refused.rbegin());
  if ((refused.size() - start) % 2 == 0)
    ++start;
  if (start >= refused.size())
    return std::nullopt;
  return start;
}

std::vector<double> end_table_angles(double lo, double hi, double step_rad, double acute_step_rad)
{
  constexpr double square = std::numbers::pi / 2;
  if (!(acute_step_rad > 0) || lo >= square - 1e-9)
    return even_nodes(lo, hi, step_rad);
  if (hi <= square + 1e-9)
    return even_nodes(lo, hi, acute_step_rad);
  std::vector<double> angles = even_nodes(lo, square, acute_step_rad);
  const std::vector<double> obtuse = even_nodes(square, hi, step_rad);
  angles.insert(angles.end(), obtuse.begin() + 1, obtuse.end());
  return angles;
}

namespace
{
/// Linear interpolation over (x, value) nodes ascending in x, held at the ends.
double interpolate_held(const std::vector<std::pair<double, double>>& nodes, double x)
{
  if (nodes.size() == 1 || x <= nodes.front().first)
    return nodes.front().second;
  if (x >= nodes.back().first)
    return nodes.back().second;
  const auto right = std::upper_bound(nodes.begin(), nodes.end(), x,
                                      [](double a, const std::pair<double, double>& n) { return a < n.first; });
  const auto left = right - 1;
  const double t = (x - left->first) / (right->first - left->first);
  return (1 - t) * left->second + t * right->second;
}

/// Every stride-th of n nodes when there are 3 or more, else every one.
std::size_t own_stride(int stride, std::size_t n)
{
  return n >= 3 ? static_cast<std::size_t>(stride) : 1;
}

double flat_rim_peak(const std::vector<FlatRimNode>& table, int stride, double interior_angle_rad)
{
  std::vector<std::pair<double, double>> nodes;
  for (std::size_t k = 0; k < table.size(); k += static_cast<std::size_t>(stride))
    nodes.emplace_back(table[k].interior_angle_rad, table[k].peak_pa());
  return interpolate_held(nodes, interior_angle_rad);
}
} // namespace

std::optional<double> end_table_ratio(const std::vector<EndTableNode>& table, int stride, double singular_from_rad,
                                      double interior_angle_rad, double radius_m)
{
  if (interior_angle_rad > singular_from_rad)
    return std::nullopt;
  if (table.empty())
    throw ComputationError("rim loop: a non-singular loaded end, but the end table is empty");
  std::vector<std::span<const EndTableNode>> columns;
  for (auto first = table.begin(); first != table.end();)
  {
    const auto last = std::find_if(first, table.end(), [&](const EndTableNode& n) {
      return n.sheet_radius_m != first->sheet_radius_m;
    });
    columns.emplace_back(first, last);
    first = last;
  }
  if (columns.size() > 1 && !(radius_m > 0))
    throw ComputationError(fmt::format("rim loop: the end table's ratio needs R > 0, got {} m", radius_m));
  std::vector<std::pair<double, double>> across;
  for (std::size_t c = 0; c < columns.size(); c += own_stride(stride, columns.size()))
  {
    std::vector<std::pair<double, double>> nodes;
    for (std::size_t k = 0; k < columns[c].size(); k += own_stride(stride, columns[c].size()))
    {
      const EndTableNode& n = columns[c][k];
      if (!n.study.end_to_interior)
        throw ComputationError(fmt::format("rim loop: the end table's node at {:.2f} deg, R = {:.4g} m has no "
                                           "end/interior ratio (its rounded edge is not resolved)",
                                           n.interior_angle_rad / degree, n.sheet_radius_m));
      nodes.emplace_back(n.interior_angle_rad, *n.study.end_to_interior);
    }
    across.emplace_back(columns.size() > 1 ? std::log(columns[c].front().sheet_radius_m) : 0.0,
                        interpolate_held(nodes, interior_angle_rad));
  }
  return interpolate_held(across, columns.size() > 1 ? std::log(radius_m) : 0.0);
}

std::optional<double> EndRatios::operator()(int stride, const loop_scores::LoadedEnd& end) const
{
  if (!flat_table.empty() && end.interior_angle_rad >= flat_from_rad)
    return flat_rim_peak(flat_table, static_cast<int>(own_stride(stride, flat_table.size())), end.interior_angle_rad)
           / end.line_hertz_pa;
  return end_table_ratio(table, stride, singular_from_rad,
                         std::clamp(end.interior_angle_rad, smallest_modelled_angle, largest_modelled_rad),
                         end.radius_m);
}

std::optional<double> RimLoopResult::worst_end_to_interior() const
{
  std::optional<double> worst;
  for (const RimLoopEnd& e : ends)
    if (e.end_peak_pa)
      worst = std::max(worst.value_or(0.0), *e.end_peak_pa / e.interior_peak_pa);
  return worst;
}

std::optional<double> RimLoopResult::covered_end_to_interior() const
{
  if (loop.end_aware.empty() || loop.end_aware[0].singular_ends > 0 || !(loop.end_aware[0].peak_pa > 0)
      || !(loop.fem_peak_pa > 0))
    return std::nullopt;
  return loop.end_aware[0].peak_pa / loop.fem_peak_pa;
}

std::optional<double> RimLoopResult::covered_limit_change() const
{
  if (!covered_end_to_interior() || !(loop.end_aware[0].peak_within_half_limit_pa > 0))
    return std::nullopt;
  return loop.end_aware[0].peak_pa / loop.end_aware[0].peak_within_half_limit_pa - 1;
}

std::optional<double> RimLoopResult::loop_end_to_interior() const
{
  if (loop.end_aware.empty() || loop.end_aware[0].outside_model_ends > 0)
    return std::nullopt;
  return covered_end_to_interior();
}

std::string RimLoopResult::end_aware_status() const
{
  if (loop.loaded_ends == 0)
    return "no sample of the loop loads a rim end";
  if (loop.end_aware.empty())
    return "not computed";
  const loop_scores::EndAwareScores& all = loop.end_aware[0];
  if (all.singular_ends > 0)
    return fmt::format("singular: {} of the loop's {} loaded rim ends have a sharp edge of interior angle above "
                       "{:.2f} deg",
                       all.singular_ends, loop.loaded_ends, singular_from_rad / degree);
  if (all.outside_model_ends > 0)
    return fmt::format("undefined: {} of the loop's {} loaded rim ends lie where b / R >= {:.1f} (a ruling ending "
                       "near its sheet's apex, no line contact), where no end pressure is defined",
                       all.outside_model_ends, loop.loaded_ends, fem::largest_half_width_over_radius);
  const double tolerance = fem_sds.loop.tolerance;
  std::vector<std::string> why;
  if (!table_converged)
    why.push_back("a node of the end table or the flat-rim table did not converge");
  if (table_vs_direct && *table_vs_direct > end_setup.tolerance)
    why.push_back(
        fmt::format("the end table differs from the direct end models by {:.1f} %", 100 * *table_vs_direct));
  if (std::abs(all.sds.sample_change()) >= tolerance)
    why.push_back(fmt::format("halving the samples changes it by {:+.2f} %", 100 * all.sds.sample_change()));
  if (loop.end_aware.size() > 1 && all.sds.value && loop.end_aware[1].sds.value)
    if (const double change = *all.sds.value / *loop.end_aware[1].sds.value - 1; std::abs(change) >= tolerance)
      why.push_back(fmt::format("halving the end table's nodes changes it by {:+.2f} %", 100 * change));
  if (!loop.converged())
    why.push_back("the interior FEM-SDS is not converged");
  if (why.empty())
    return "converged";
  std::string text = "not converged:";
  for (std::size_t i = 0; i < why.size(); ++i)
    text += (i ? "; " : " ") + why[i];
  return text;
}

namespace
{
/// The range of R over the loaded ends the end table stands for: the loop's
/// (as loop_scores::finished_end has them, inside the end model, below `flat_from_rad`)
/// and the directly modelled ones; none without such ends.
std::optional<std::pair<double, double>> sheet_radius_range(MPI_Comm comm, const loop_scores::LoopSamples& samples,
                                                            const std::vector<RimLoopEnd>& direct,
                                                            double edge_radius_m, double flat_from_rad)
{
  double lo = std::numeric_limits<double>::infinity(), hi = 0;
  auto add = [&](double radius) {
    lo = std::min(lo, radius);
    hi = std::max(hi, radius);
  };
  for (const loop_scores::RulingSample& ruling : samples.rulings)
    for (const loop_scores::LoadedEnd& hull_end : ruling.ends)
    {
      const loop_scores::LoadedEnd end = loop_scores::finished_end(hull_end, edge_radius_m);
      if (end.interior_angle_rad < flat_from_rad
          && loop_scores::half_width_over_radius(end) < fem::largest_half_width_over_radius)
        add(end.radius_m);
    }
  for (const RimLoopEnd& e : direct)
    if (e.outside_model.empty() && e.interior_angle_rad < flat_from_rad)
      add(e.study.setup.radius_m);
  MPI_Allreduce(MPI_IN_PLACE, &lo, 1, MPI_DOUBLE, MPI_MIN, comm);
  MPI_Allreduce(MPI_IN_PLACE, &hi, 1, MPI_DOUBLE, MPI_MAX, comm);
  if (!(hi > 0))
    return std::nullopt;
  return std::pair{lo, hi};
}
} // namespace

RimLoopResult run_rim_loop(MPI_Comm comm, const RimLoopSettings& settings)
{
  // The interior's slices meet the same counter-face as the ends: on a steel
  // block, E* of the pair (half-space theory's reduction, as the end model's
  // block), so that the pressures, load ratios and b / R of the loop are the pair's.
  RimLoopSettings s = settings;
  s.loop.elastic_plane = s.end.counter_face == fem::CounterFace::block;
  if (!(s.end_table_step_rad > 0) || !std::isfinite(s.end_table_step_rad))
    throw InputError(fmt::format("rim --body: end_table_step_deg must be positive and finite, got {}",
                                 s.end_table_step_rad / degree));
  if (!(s.end_table_acute_step_rad >= 0) || !std::isfinite(s.end_table_acute_step_rad))
    throw InputError(fmt::format("rim --body: end_table_acute_step_deg must be 0 (the table's step) or positive, got {}",
                                 s.end_table_acute_step_rad / degree));
  if (!(s.depth_over_edge_radius * fem::largest_edge_radius_over_depth > 1) || !std::isfinite(s.depth_over_edge_radius))
    throw InputError(fmt::format("rim --body: depth_over_edge_radius must exceed {} (the fillet inside the block), "
                                 "got {}",
                                 1 / fem::largest_edge_radius_over_depth, s.depth_over_edge_radius));
  if (!(s.end_table_radius_step == 0 || s.end_table_radius_step > 1) || !std::isfinite(s.end_table_radius_step))
    throw InputError(fmt::format("rim --body: end_table_radius_step must be 0 (one column) or above 1, got {}",
                                 s.end_table_radius_step));
  const auto start = std::chrono::steady_clock::now();
  fem::ensure_petsc();
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  RimLoopResult result;
  fem::SliceScaling slices(loop_scores::slice_settings(s.loop), s.loop.table_nodes_per_decade);
  result.fem_sds = loop_scores::run_fem_sds(comm, s.loop, slices);
  result.ends = direct_ends(comm, s, result.fem_sds);
  result.end_setup = end_settings(s, s.end.radius_m, s.end.load_n_per_m, s.end.interior_angle_rad);
  result.singular_from_rad = singular_from_angle(result.end_setup);

  const loop_scores::LoopSds& interior = result.fem_sds.loop;
  // A rounded edge's flattest ends: the body's own, by half-space theory.
  if (s.end.edge_radius_m > 0 && interior.loaded_ends > 0 && interior.loaded_end_angle_max_rad >= s.flat_rim_from_rad
      && result.fem_sds.circles.size() == 2)
  {
    // Where half-space theory cannot stand for the body's flattest ends
    // (the hull not found, or steep beside the contact), the FEM end table
    // takes them, as for a body with no such ends; the JSON says why.
    try
    {
      FlatRimTable flat = flat_rim_table(comm, s, result.fem_sds, s.flat_rim_from_rad);
      result.flat_table = std::move(flat.nodes);
      result.flat_rim_refused = std::move(flat.refused);
      result.flat_from_rad
          = result.flat_rim_refused.empty() ? s.flat_rim_from_rad : result.flat_table.front().interior_angle_rad;
      if (!result.flat_rim_refused.empty() && rank == 0)
        spdlog::warn("rim loop: {}", result.flat_rim_refused);
    }
    catch (const std::runtime_error& e) // a failed solve, or no orientation at a node's angle (InputError)
    {
      result.flat_rim_refused = e.what();
      if (rank == 0)
        spdlog::warn("rim loop: no flat-rim table, the FEM end table takes every end: {}", e.what());
    }
    for (const FlatRimNode& node : result.flat_table)
    {
      result.table_converged = result.table_converged && node.converged();
      if (rank == 0)
        for (const FlatRimSide& side : node.sides)
          spdlog::info("rim loop: flat-rim at {:.2f} deg (c = {:.4f}, q = {:.5g} N/m, hull's R = {:.4g} m): peak {:.5g} "
                       "Pa, {:.4f} times line Hertz ({}: {:+.2f} % last level, {}; {:.0f} s)",
                       node.interior_angle_rad / degree, side.centre_of_pressure, side.end_line_load_n_per_m,
                       side.end_radius_m, side.peak_pressure_pa, side.peak_pressure_pa / side.line_hertz_peak_pa,
                       side.converged ? "converged" : "NOT converged", 100 * side.last_change,
                       side.whole_ruling ? fmt::format("the whole ruling, where the shortened window gave {:.5g} Pa",
                                                       side.window_peak_pa)
                                         : fmt::format("{:+.2f} % longer window", 100 * side.window_change),
                       side.wall_s);
    }
  }
  const bool flat = !result.flat_table.empty();
  const double lo = std::max(interior.loaded_end_angle_min_rad, smallest_modelled_angle);
  // The table's last node just below the singular angle, where the end model
  // still finds a (square) edge; or where the flat-rim table takes over.
  const double hi = std::min({interior.loaded_end_angle_max_rad,
                              result.singular_from_rad - 10 * singular_angle_tolerance, largest_angle(s.end),
                              result.flat_from_rad});
  std::vector<loop_scores::EndFactor> factors;
  if (interior.loaded_ends > 0 && interior.loaded_end_angle_min_rad <= result.singular_from_rad)
  {
    std::vector<double> loads, radii;
    for (const RimLoopEnd& e : result.ends)
      if (e.outside_model.empty())
      {
        loads.push_back(e.study.setup.load_n_per_m);
        radii.push_back(e.study.setup.radius_m);
      }
    if (loads.empty())
      throw InputError(fmt::format("rim --body: the loop loads {} rim ends, but none of the {} orientations solved "
                                   "directly loads one the end model stands for; raise orientations",
                                   interior.loaded_ends, s.loop.orientations));
    result.reference_load_n_per_m = median(loads);
    result.reference_radius_m = median(radii);
    std::vector<double> columns{result.reference_radius_m};
    const auto range = s.end.edge_radius_m > 0 && s.end_table_radius_step > 0
                           ? sheet_radius_range(comm, result.fem_sds.loop_samples, result.ends, s.end.edge_radius_m,
                                                result.flat_from_rad)
                           : std::nullopt;
    if (range)
    {
      columns.clear();
      for (const double log_radius :
           even_nodes(std::log(range->first), std::log(range->second), std::log(s.end_table_radius_step)))
        columns.push_back(std::exp(log_radius));
    }
    // Each node's load control starts from the node before's converged
    // approach over its estimate (neighbours differ in angle or R only): one
    // load step fewer than from the estimate, which overshoots by about 20 %;
    // the first node from the last direct end's.
    double approach_over_estimate = 1;
    for (const RimLoopEnd& e : result.ends)
      if (!e.study.levels.empty())
        approach_over_estimate = e.study.approach_over_estimate();
    for (const double radius : columns)
      for (const double angle : end_table_angles(std::min(lo, hi), hi, s.end_table_step_rad, s.end_table_acute_step_rad))
      {
        fem::RimEndSettings settings = end_settings(s, radius, result.reference_load_n_per_m, angle);
        settings.first_approach_scale = approach_over_estimate;
        EndTableNode node{angle, radius, fem::solve_rim_end(comm, settings)};
        approach_over_estimate = node.study.approach_over_estimate();
        result.table_converged = result.table_converged && node.study.converged;
        if (rank == 0)
          spdlog::info("rim loop: end table at {:.2f} deg, R = {:.4g} m (r_e / b = {:.3g}): end/interior {} ({})",
                       angle / degree, radius, s.end.edge_radius_m / node.study.half_width_m,
                       node.study.end_to_interior ? fmt::format("{:.4f}", *node.study.end_to_interior) : "none",
                       node.study.converged ? "converged" : "NOT converged");
        result.table.push_back(std::move(node));
      }
    for (RimLoopEnd& e : result.ends)
    {
      if (flat && e.interior_angle_rad >= result.flat_from_rad)
      {
        // Not a check of the end table: the flat-rim table stands for it.
        if (e.study.hertz_peak_pa > 0)
          e.table_ratio = flat_rim_peak(result.flat_table, 1, e.interior_angle_rad) / e.study.hertz_peak_pa;
        continue;
      }
      e.table_ratio
          = end_table_ratio(result.table, 1, result.singular_from_rad, e.modelled_angle_rad, e.study.setup.radius_m);
      if (e.table_ratio && e.study.end_to_interior && e.study.resolved && !e.study.singular)
        // Over the larger of the end's and the interior's pressure, as the end
        // model's own change: an acute end's ratio tends to 0.
        result.table_vs_direct
            = std::max(result.table_vs_direct.value_or(0.0),
                       std::abs(*e.table_ratio - *e.study.end_to_interior) / std::max(*e.study.end_to_interior, 1.0));
    }
    const EndRatios ratios{result.table, result.flat_table, result.flat_from_rad, result.singular_from_rad,
                           largest_angle(s.end)};
    for (const int stride : {1, 2})
      if (stride == 1 || result.table.size() >= 3 || result.flat_table.size() >= 3)
        factors.push_back([ratios, stride](const loop_scores::LoadedEnd& end) { return ratios(stride, end); });
  }
  else if (interior.loaded_ends > 0)
    factors.push_back([](const loop_scores::LoadedEnd&) { return std::optional<double>(); }); // every loaded end singular
  // The interior's scores with the ends', from the samples it mapped.
  result.loop = result.fem_sds.loop;
  result.loop.end_aware = loop_scores::end_aware_scores(comm, result.fem_sds.loop_samples, slices, loop_scores::loop_settings(s.loop), factors,
                                           s.end.edge_radius_m);
  result.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

nlohmann::json to_json(const RimLoopResult& r)
{
  auto end_json = [](const fem::RimEndStudy& study) {
    int load_steps = 0, newton_iterations = 0;
    for (const fem::RimEndLevel& l : study.levels)
    {
      load_steps += l.load_steps;
      newton_iterations += l.newton_iterations;
    }
    return nlohmann::json{{"load_n_per_m", study.setup.load_n_per_m},
                          {"sheet_radius_m", study.setup.radius_m},
                          {"depth_over_half_width", study.setup.depth_over_half_width},
                          {"half_width_m", study.half_width_m},
                          {"hertz_peak_pa", study.hertz_peak_pa},
                          {"singular", study.singular},
                          {"wedge_exponent", study.wedge_exponent},
                          {"measured_exponent", json_number(study.measured_exponent)},
                          {"end_to_interior", study.singular || !study.resolved ? nlohmann::json(nullptr)
                                                                                : json_number(study.end_to_interior)},
                          {"end_change", json_number(study.end_change)},
                          {"resolved", study.resolved},
                          {"converged", study.converged},
                          {"levels", study.levels.size()},
                          {"plane_strain_change", study.plane_strain_change},
                          {"load_steps", load_steps},
                          {"newton_iterations", newton_iterations},
                          {"wall_s", study.wall_s()}};
  };
  nlohmann::json ends = nlohmann::json::array();
  for (const RimLoopEnd& e : r.ends)
  {
    nlohmann::json j = end_json(e.study);
    j["orientation"] = e.orientation;
    j["end"] = e.end == 0 ? "start" : "end";
    j["interior_angle_deg"] = e.interior_angle_rad / degree;
    j["modelled_angle_deg"] = e.modelled_angle_rad / degree;
    j["interior_peak_pa"] = e.interior_peak_pa;
    j["end_peak_pa"] = json_number(e.end_peak_pa);
    j["end_peak_over_interior_peak"]
        = e.end_peak_pa ? json_number(*e.end_peak_pa / e.interior_peak_pa) : nlohmann::json(nullptr);
    j["table_ratio"] = json_number(e.table_ratio);
    j["outside_model"] = e.outside_model.empty() ? nlohmann::json(nullptr) : nlohmann::json(e.outside_model);
    ends.push_back(std::move(j));
  }
  nlohmann::json table = nlohmann::json::array();
  for (const EndTableNode& n : r.table)
  {
    nlohmann::json j = end_json(n.study);
    j["interior_angle_deg"] = n.interior_angle_rad / degree;
    table.push_back(std::move(j));
  }
  nlohmann::json flat_table = nlohmann::json::array();
  for (const FlatRimNode& n : r.flat_table)
  {
    nlohmann::json sides = nlohmann::json::array();
    for (const FlatRimSide& side : n.sides)
      sides.push_back({{"centre_of_pressure", side.centre_of_pressure},
                       {"end_line_load_n_per_m", side.end_line_load_n_per_m},
                       {"end_sheet_radius_m", side.end_radius_m},
                       {"peak_pressure_pa", side.peak_pressure_pa},
                       {"line_hertz_peak_pa", side.line_hertz_peak_pa},
                       {"last_change", side.last_change},
                       {"window_change", side.window_change},
                       {"converged", side.converged},
                       {"wall_s", side.wall_s},
                       {"after_over_half_width", side.after_over_half_width},
                       {"across_scale", side.across_scale},
                       {"whole_ruling", side.whole_ruling},
                       {"window_peak_pa", side.whole_ruling ? nlohmann::json(side.window_peak_pa) : nlohmann::json(nullptr)}});
    flat_table.push_back({{"interior_angle_deg", n.interior_angle_rad / degree},
                          {"peak_pressure_pa", n.peak_pa()},
                          {"ratio", n.ratio()},
                          {"converged", n.converged()},
                          {"sides", sides}});
  }
  // Where the two tables meet: the FEM end model (a straight rim under a
  // uniform load) against the body's own end (flat-rim).
  nlohmann::json seam = nullptr;
  if (!r.flat_table.empty() && !r.table.empty() && r.table.back().study.end_to_interior)
  {
    // At the R of the first flat-rim node's side with the largest ratio.
    const FlatRimSide& side = std::ranges::max(r.flat_table.front().sides, {}, [](const FlatRimSide& f) {
      return f.peak_pressure_pa / f.line_hertz_peak_pa;
    });
    const double radius = std::max(side.end_radius_m, r.end_setup.edge_radius_m);
    seam = {{"interior_angle_deg", r.flat_from_rad / degree},
            {"sheet_radius_m", radius},
            {"end_table_ratio", *end_table_ratio(r.table, 1, r.singular_from_rad, r.flat_from_rad, radius)},
            {"flat_rim_ratio", r.flat_table.front().ratio()}};
  }
  const fem::RimEndSettings& setup = r.end_setup;
  return {{"body", r.fem_sds.body},
          {"loop", r.fem_sds.source},
          {"counter_face", setup.counter_face == fem::CounterFace::rigid ? "rigid" : "steel"},
          {"edge_radius_m", setup.edge_radius_m},
          {"singular_from_deg", r.singular_from_rad / degree},
          {"ends", ends},
          {"worst_end_to_interior", json_number(r.worst_end_to_interior())},
          {"loop_end_to_interior", json_number(r.loop_end_to_interior())},
          {"covered_end_to_interior", json_number(r.covered_end_to_interior())},
          {"covered_limit_change", json_number(r.covered_limit_change())},
          {"outside_model_ends", r.loop.end_aware.empty() ? 0 : r.loop.end_aware[0].outside_model_ends},
          {"outside_model_samples", r.loop.end_aware.empty() ? 0 : r.loop.end_aware[0].outside_model_samples},
          {"finished_ends", r.loop.end_aware.empty() ? 0 : r.loop.end_aware[0].finished_ends},
          {"end_table", table},
          {"end_table_load_n_per_m", r.reference_load_n_per_m},
          // The table's R only when it has one column; its nodes carry their own.
          {"direct_ends_median_sheet_radius_m", r.reference_radius_m},
          {"end_table_converged", r.table_converged},
          {"flat_rim_from_deg", r.flat_table.empty() ? nlohmann::json(nullptr) : nlohmann::json(r.flat_from_rad / degree)},
          {"flat_rim_table", flat_table},
          {"flat_rim_refused", r.flat_rim_refused.empty() ? nlohmann::json(nullptr) : nlohmann::json(r.flat_rim_refused)},
          {"flat_rim_seam", seam},
          {"end_table_vs_direct", json_number(r.table_vs_direct)},
          {"end_aware_status", r.end_aware_status()},
          {"loop_scores", to_json(r.loop)},
          {"interior", to_json(r.fem_sds)},
          {"wall_s", r.wall_s}};
}
} // namespace rollcheck::study::rims
