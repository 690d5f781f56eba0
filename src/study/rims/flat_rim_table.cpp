// The rim loop's flat-rim table (study/rims/flat_rim_table.h).
#include "study/rims/flat_rim_table.h"
#include "core/degree.h"
#include "core/error.h"
#include "study/rims/flattest_loop_ends.h"
#include "study/rims/table_nodes.h"
#include <algorithm>
#include <array>
#include <cmath>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <numbers>
#include <spdlog/spdlog.h>

namespace rollcheck::study::rims
{
namespace
{
/// A side's solve travels between the ranks as these doubles (FlatRimSide's
/// members in order, then the contact's largest slope, or -1 for a failed
/// solve).
constexpr std::size_t packed_side = 14;
/// The steepest slope over the contact that half-space theory takes.
constexpr double largest_slope = 0.1;

/// The ends of each node, in ascending angle: the loop's orientations at
/// each angle from `from_rad` below the flattest, one per side of it (one
/// where the sides are mirror images), then the flattest alone.
std::vector<std::vector<LoopEnd>> node_ends(std::span<const oracle::Circle> circles,
                                            const Eigen::Vector3d& centre_of_mass_m, double from_rad, double step_rad)
{
  const FlattestLoopEnds found = flattest_loop_ends_below(circles, centre_of_mass_m, [&](double flattest) {
    std::vector<double> angles = even_nodes(std::min(from_rad, flattest), flattest, step_rad);
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
  return ends;
}

/// One end solved by flat-rim, packed: over its whole loaded ruling where
/// its window does not converge (the fuller model: no window to shorten).
std::array<double, packed_side> solve_side(const FlatRimSettings& setup, const LoopEnd& end,
                                           const contact::RoundedEndProgress& progress)
{
  FlatRimContact r = flat_rim_contact(setup, end, progress);
  double window_peak = 0;
  if (needs_whole_ruling(setup, r))
  {
    window_peak = r.levels.back().peak_pressure_pa;
    FlatRimSettings whole = setup;
    whole.whole_ruling = true;
    const double window_wall_s = r.wall_s;
    r = flat_rim_contact(whole, end, [&](const std::string& what) { progress("its whole ruling: " + what); });
    r.wall_s += window_wall_s;
  }
  return {r.centre_of_pressure, r.end_line_load_n_per_m, r.end_radius_m, r.levels.back().peak_pressure_pa,
          r.line_hertz_peak_pa, r.last_change, r.window_change, r.converged ? 1.0 : 0.0, r.wall_s,
          r.after_over_half_width, r.across_scale, r.whole_ruling ? 1.0 : 0.0, window_peak, r.largest_slope};
}

FlatRimSide unpack_side(const double* v)
{
  return {v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7] > 0.5, v[8], v[9], v[10], v[11] > 0.5, v[12]};
}

/// Every node's ends solved, packed in order, each rank its share: the
/// others' values stay 0, so a sum shares them. A failed solve is logged
/// where it failed and refused alike on every rank (its slot's slope -1).
std::vector<double> solve_sides(MPI_Comm comm, const FlatRimSettings& setup,
                                const std::vector<std::vector<LoopEnd>>& ends, ProgressBeat* beat)
{
  std::size_t sides = 0;
  for (const std::vector<LoopEnd>& node_ends : ends)
    sides += node_ends.size();
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  std::vector<double> values;
  int job = 0;
  for (const std::vector<LoopEnd>& node_ends : ends)
    for (const LoopEnd& end : node_ends)
    {
      std::array<double, packed_side> v{};
      if (job++ % size == rank)
        try
        {
          const std::string side = fmt::format("flat-rim side {} of {} at {:.2f} deg", job, sides,
                                               end.interior_angle_rad / degree);
          v = solve_side(setup, end, [&](const std::string& what) {
            if (beat)
              beat->step(side + ", " + what);
          });
        }
        catch (const ComputationError& e)
        {
          spdlog::warn("rim loop: flat-rim at {:.2f} deg failed: {}", end.interior_angle_rad / degree, e.what());
          v.back() = -1;
        }
      values.insert(values.end(), v.begin(), v.end());
    }
  MPI_Allreduce(MPI_IN_PLACE, values.data(), static_cast<int>(values.size()), MPI_DOUBLE, MPI_SUM, comm);
  return values;
}
} // namespace

FlatRimTable flat_rim_table(MPI_Comm comm, const FlatRimSettings& setup, std::span<const oracle::Circle> circles,
                            const Eigen::Vector3d& centre_of_mass_m, double from_rad, double step_rad,
                            ProgressBeat* beat)
{
  const std::vector<std::vector<LoopEnd>> ends = node_ends(circles, centre_of_mass_m, from_rad, step_rad);
  const std::vector<double> values = solve_sides(comm, setup, ends, beat);
  std::vector<FlatRimNode> table;
  std::vector<bool> refused;
  std::vector<std::string> refused_angles;
  const double* v = values.data();
  for (const std::vector<LoopEnd>& node_ends : ends)
  {
    FlatRimNode& node = table.emplace_back();
    node.section_angle_rad = node_ends.front().interior_angle_rad;
    node.dihedral_angle_rad = node_ends.front().dihedral_angle_rad();
    bool failed = false;
    double slope = 0;
    for (std::size_t k = 0; k < node_ends.size(); ++k, v += packed_side)
    {
      failed = failed || v[packed_side - 1] < 0;
      slope = std::max(slope, v[packed_side - 1]);
      node.sides.push_back(unpack_side(v));
    }
    refused.push_back(failed || slope > largest_slope);
    if (refused.back())
      refused_angles.push_back(failed ? fmt::format("{:.2f} deg (its solve failed)", node.section_angle_rad / degree)
                                      : fmt::format("{:.2f} deg (slope {:.3f})", node.section_angle_rad / degree,
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
                                          why, table.front().section_angle_rad / degree);
  return {std::move(table), std::move(refused_nodes)};
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

namespace
{
/// `value` of every `stride`-th node, linear in the angle, held at the ends.
template <typename Value>
double interpolate_nodes(const std::vector<FlatRimNode>& table, int stride, double section_angle_rad, Value value)
{
  std::vector<std::pair<double, double>> nodes;
  for (std::size_t k = 0; k < table.size(); k += static_cast<std::size_t>(stride))
    nodes.emplace_back(table[k].section_angle_rad, value(table[k]));
  return interpolate_held(nodes, section_angle_rad);
}
} // namespace

double flat_rim_peak(const std::vector<FlatRimNode>& table, int stride, double section_angle_rad)
{
  return interpolate_nodes(table, stride, section_angle_rad, [](const FlatRimNode& n) { return n.peak_pa(); });
}

double flat_rim_ratio(const std::vector<FlatRimNode>& table, int stride, double section_angle_rad)
{
  return interpolate_nodes(table, stride, section_angle_rad, [](const FlatRimNode& n) { return n.ratio(); });
}

double FlatRimNode::peak_pa() const
{
  return std::ranges::max(sides, {}, &FlatRimSide::peak_pressure_pa).peak_pressure_pa;
}

const FlatRimSide& FlatRimNode::largest_ratio_side() const
{
  return *std::ranges::max_element(sides, {}, &FlatRimSide::ratio);
}

bool FlatRimNode::converged() const
{
  return std::ranges::all_of(sides, [](const FlatRimSide& side) { return side.converged; });
}
} // namespace rollcheck::study::rims
