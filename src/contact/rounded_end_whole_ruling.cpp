#include "contact/rounded_end_whole_ruling.h"
#include "core/error.h"
#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <iterator>
#include <limits>
#include <optional>
#include <ranges>

namespace rollcheck::contact
{
namespace
{
/// The whole ruling's columns from x' = 0: to 1.3 times the loaded length,
/// stopping r_e short of the far rim and short of where an oblique far rim
/// crosses the grid's end (the body's outline on the ground is convex: its
/// far corners inside). A contact that would run beyond stops the tilt's
/// search with a message.
std::size_t whole_ruling_columns(const RoundedEndSettings& s, const RoundedEndProblem& end, double cell,
                                 std::size_t half_across)
{
  const std::size_t margin = rounding_margin(s.edge_radius_m, cell);
  const double across = static_cast<double>(half_across + margin) * cell;
  const auto inside = [&](std::size_t columns) {
    const double along = static_cast<double>(columns - 1 + margin) * cell;
    return std::isfinite(end.hull_height(along, across)) && std::isfinite(end.hull_height(along, -across));
  };
  const double reach = std::min(1.3 * end.load.length_m, end.ruling_length_m - s.edge_radius_m);
  std::size_t columns = static_cast<std::size_t>(std::ceil(reach / cell)) + 1;
  while (!inside(columns))
    if (--columns == 1)
      throw ComputationError(fmt::format("flat rim, whole ruling: the body's outline on the ground does not cover "
                                         "{:.4g} m across the ruling (the hull was not found there)",
                                         across));
  return columns;
}

/// The whole ruling's contact at a tilt: F on the grid, and its centre's
/// distance beyond the foot.
class TiltedRuling
{
public:
  TiltedRuling(const HalfSpaceGrid& grid, const BallRoundedSurface& surface, double effective_modulus_pa,
               double force_n, double foot_m, RoundedEndLevel& level)
      : grid_(grid), surface_(surface), deflection_(grid, effective_modulus_pa), force_(force_n), foot_(foot_m),
        level_(level), gap_(grid.size())
  {
  }

  /// F's centre beyond the foot (m) at this tilt; none when the contact runs
  /// off the grid's far side (too little tilt). The last contact that did
  /// not is kept.
  std::optional<double> centre_beyond_foot(double tilt)
  {
    for (std::size_t i = 0; i < grid_.nx; ++i)
      for (std::size_t j = 0; j < grid_.ny; ++j)
        gap_[i * grid_.ny + j] = surface_(i, j) + tilt * grid_.x(i);
    ++level_.solves;
    try
    {
      HalfSpaceContact next = solve_half_space_contact(deflection_, gap_, force_, {}, solved_.pressure_pa);
      level_.iterations += next.iterations;
      solved_ = std::move(next);
    }
    catch (const ContactBeyondGrid& e)
    {
      if (e.across)
        throw;
      return std::nullopt;
    }
    const double everywhere = std::numeric_limits<double>::infinity();
    const Eigen::Vector2d total = load_over(solved_.pressure_pa, grid_, -everywhere, everywhere);
    return total[1] / total[0] - foot_;
  }

  const HalfSpaceContact& solved() const { return solved_; }
  double foot_m() const { return foot_; }

private:
  const HalfSpaceGrid& grid_;
  const BallRoundedSurface& surface_;
  HalfSpaceDeflection deflection_;
  double force_, foot_;
  RoundedEndLevel& level_;
  std::vector<double> gap_;
  HalfSpaceContact solved_;
};

/// Sets the tilt from `tilt` on until F's centre lies within 1e-4 of the
/// ruling's length of the foot: bracketed by doubling or halving, then
/// regula falsi with the Illinois halving.
void settle_tilt(TiltedRuling& ruling, double tilt, double ruling_length_m)
{
  double too_little = 0, too_much = 0;
  std::optional<double> beyond_little, beyond_much;
  int kept = 0; // the side the last solve replaced: +1 too little, -1 too much
  for (int k = 0;; ++k)
  {
    if (k == 60)
      throw ComputationError(fmt::format("flat rim, whole ruling: F's centre did not settle at the centre of mass's "
                                         "foot, {:.4g} m from the end (the contact may reach the ruling's far rim, "
                                         "which this grid leaves out)",
                                         ruling.foot_m()));
    const std::optional<double> beyond = ruling.centre_beyond_foot(tilt);
    if (beyond && std::abs(*beyond) < 1e-4 * ruling_length_m)
      return;
    if (!beyond || *beyond > 0)
    {
      too_little = tilt;
      beyond_little = beyond;
      if (kept == 1 && beyond_much)
        *beyond_much /= 2;
      kept = 1;
    }
    else
    {
      too_much = tilt;
      beyond_much = beyond;
      if (kept == -1 && beyond_little)
        *beyond_little /= 2;
      kept = -1;
    }
    if (too_much == 0)
      tilt *= 2;
    else if (too_little == 0)
      tilt /= 2;
    else if (beyond_little)
      tilt = too_little + (too_much - too_little) * *beyond_little / (*beyond_little - *beyond_much);
    else
      tilt = (too_little + too_much) / 2;
  }
}
} // namespace

SolvedLevel solve_whole_ruling_level(const RoundedEndSettings& s, const RoundedEndProblem& end, const LevelScale& scale,
                                     double cell)
{
  const auto start = std::chrono::steady_clock::now();
  const std::size_t half_across = half_across_cells(s, end, scale, 0, cell);
  const std::size_t first_cell = cells_over(s.before_over_half_width * scale.half_width_m, cell); // x' = 0 here
  const HalfSpaceGrid grid{first_cell + whole_ruling_columns(s, end, cell, half_across),
                           2 * half_across + 1,
                           cell,
                           cell,
                           -static_cast<double>(first_cell) * cell,
                           -static_cast<double>(half_across) * cell};
  const BallRoundedSurface surface = ball_rounded_surface(end.hull_height, grid, s.edge_radius_m);
  const double force = end.load.load_to(end.load.length_m);
  SolvedLevel solved;
  RoundedEndLevel& level = solved.level;
  level.cell_m = cell;
  level.cells = grid.size();
  TiltedRuling ruling(grid, surface, scale.effective_modulus_pa, force,
                      end.load.moment_to(end.load.length_m) / force, level);
  settle_tilt(ruling, 4 * end.load.at_end_n_per_m / (scale.effective_modulus_pa * end.load.length_m),
              end.ruling_length_m);

  const std::vector<double>& pressure = ruling.solved().pressure_pa;
  read_level(level, pressure, grid);
  solved.largest_slope = largest_loaded_slope(surface, grid, pressure);
  // Halfway along the contact the column reads line Hertz at its own load.
  const auto loaded = std::ranges::find_if(level.station_load_n_per_m | std::views::reverse,
                                           [](double q) { return q > 0; });
  const auto contact_end = static_cast<std::size_t>(std::distance(loaded, level.station_load_n_per_m.rend()) - 1);
  const std::size_t halfway = (first_cell + contact_end) / 2;
  level.far_peak_pa = level.station_peak_pa[halfway];
  level.far_line_hertz_pa = line_contact(level.station_load_n_per_m[halfway], end.sheet_radius(grid.x(halfway)),
                                         scale.effective_modulus_pa, s.poisson_ratio)
                                .peak_pressure_pa;
  solved.end_lift_m = surface(first_cell, half_across);
  level.wall_s = seconds_since(start);
  return solved;
}
} // namespace rollcheck::contact
