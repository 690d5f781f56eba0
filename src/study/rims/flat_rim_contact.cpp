#include "study/rims/flat_rim_contact.h"
#include "contact/half_space_contact.h"
#include "contact/hertz.h"
#include "core/error.h"
#include "geometry/rolling_ball_opening.h"
#include "geometry/two_circle_hull_height.h"
#include "oracle/contact_density.h"
#include "oracle/rolling_dynamics.h"
#include "oracle/rolling_study.h"
#include "oracle/support_set.h"
#include <Eigen/Dense>
#include <algorithm>
#include <chrono>
#include <functional>
#include <limits>
#include <memory>
#include <cmath>
#include <fmt/format.h>
#include <nlohmann/json.hpp>
#include <numbers>
#include <optional>
#include <ranges>

namespace rollcheck::study::rims
{
namespace
{
/// The hull's lower surface near a loaded end of a two-circle body's ruling,
/// over the ground frame with the end as its origin and x' along the ruling.
struct RulingEndSurface
{
  geometry::SpaceCircle a; ///< the circle the end lies on, t = 0 at the end
  geometry::SpaceCircle b;
  geometry::GroundFrame ground;
  // The surface within a few r_e of the end lies on segments from A within
  // 0.3 rad of it (3 mm at r1 = 10 mm): 0.15 rad missed the hull beyond the
  // FEM-SDS optimum's 160 deg end (test TheHullIsFoundBeyondTheFemSdsOptimumsEnd);
  // the samples keep their spacing.
  geometry::SegmentSearch search{-0.3, 0.3, 96};

  explicit RulingEndSurface(const LoopEnd& e)
      : a(space_circle(e.circles[static_cast<std::size_t>(e.end)], e.point_m())),
        b(space_circle(e.circles[static_cast<std::size_t>(1 - e.end)], e.end == 0 ? e.ruling.end_m : e.ruling.start_m))
  {
    ground.origin = e.point_m();
    ground.down = e.ruling.direction; // the support direction: out of the body, into the ground
    ground.along = e.end == 0 ? e.ruling.axis : Eigen::Vector3d(-e.ruling.axis);
    ground.across = ground.down.cross(ground.along);
  }

  // Where no segment from A near the end lies over a point, every t is
  // searched: the point lies outside the body's outline on the ground only
  // if none does (whole_ruling_columns asks that near an oblique far rim).
  geometry::SegmentSearch whole_circle{-std::numbers::pi, std::numbers::pi, 720};

  double height(double along_m, double across_m) const
  {
    const double z = geometry::two_circle_hull_height(a, b, ground, search, along_m, across_m);
    return std::isfinite(z) ? z : geometry::two_circle_hull_height(a, b, ground, whole_circle, along_m, across_m);
  }

  /// The circle with t = 0 at `through`, a point of it.
  static geometry::SpaceCircle space_circle(const oracle::Circle& c, const Eigen::Vector3d& through)
  {
    const Eigen::Vector3d radial = (through - c.centre_m).normalized();
    return {c.centre_m, radial, c.normal.cross(radial), c.radius_m};
  }
};

/// A line load along the ruling from the end (x' = 0): q(x') = at_end +
/// slope x' on [0, length], 0 elsewhere.
struct LineLoad
{
  double at_end_n_per_m = 0;
  double slope_n_per_m2 = 0;
  double length_m = 0;

  double at(double x) const { return x < 0 || x > length_m ? 0.0 : at_end_n_per_m + slope_n_per_m2 * x; }
  /// The load over [0, x] and its first moment about the end.
  double load_to(double x) const
  {
    x = std::clamp(x, 0.0, length_m);
    return at_end_n_per_m * x + slope_n_per_m2 * x * x / 2;
  }
  double moment_to(double x) const
  {
    x = std::clamp(x, 0.0, length_m);
    return at_end_n_per_m * x * x / 2 + slope_n_per_m2 * x * x * x / 3;
  }
  /// q = at_end + slope x' where positive, on [0, ruling_length] (the no-tension linear rule).
  static LineLoad no_tension(double at_end, double slope, double ruling_length)
  {
    return {at_end, slope, slope < 0 ? std::min(ruling_length, -at_end / slope) : ruling_length};
  }
  /// The no-tension linear rule on [from, ruling_length] carrying `force` with
  /// its centre at `centre` (the contact locus's rule, oracle::line_load);
  /// none when the centre lies in the far third (the load would leave `from`).
  static std::optional<LineLoad> carrying(double force, double centre, double from, double ruling_length)
  {
    const double length = ruling_length - from, e = (centre - from) / length;
    double at_from = 0, slope = 0;
    if (e > 0 && e < 1.0 / 3)
    {
      at_from = 2 * force / (3 * e * length);
      slope = -at_from / (3 * e * length);
    }
    else if (e >= 1.0 / 3 && e <= 2.0 / 3)
    {
      at_from = force / length * (4 - 6 * e);
      slope = (force / length * (6 * e - 2) - at_from) / length;
    }
    else
      return std::nullopt;
    return no_tension(at_from - slope * from, slope, ruling_length);
  }
};

/// One flat rim end: the hull's surface near it, the sheet's radius across
/// the ruling beyond the window, and the ruling's line load.
struct EndProblem
{
  std::function<double(double, double)> hull_height;
  std::function<double(double)> sheet_radius;
  LineLoad load;
  double ruling_length_m = 0;
  /// Re-solve the ruling's load beyond the window so that the body balances
  /// (a body's end); else the load beyond is held (an end of a long contact).
  bool balance_body = false;
};

double seconds_since(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// The hull over the window and a margin of 0.6 r_e (where the rolling ball
/// touches it), opened by the ball: the finished surface on the window's cells.
struct RoundedSurface
{
  std::vector<double> values;
  std::size_t margin = 0, ny = 0; ///< of the opened grid: the window's and its margin
  double operator()(std::size_t i, std::size_t j) const { return values[(i + margin) * ny + j + margin]; }
};

/// The cells about a grid whose hull the rounding needs: 0.6 r_e.
std::size_t opening_margin(double edge_radius, double cell)
{
  return static_cast<std::size_t>(std::ceil(0.6 * edge_radius / cell));
}

RoundedSurface rounded_surface(const EndProblem& end, const contact::HalfSpaceGrid& window, double edge_radius)
{
  const double cell = window.cell_x_m;
  RoundedSurface r;
  r.margin = opening_margin(edge_radius, cell);
  const std::size_t nx = window.nx + 2 * r.margin;
  r.ny = window.ny + 2 * r.margin;
  std::vector<double> hull(nx * r.ny);
  const double shift = static_cast<double>(r.margin);
  for (std::size_t i = 0; i < nx; ++i)
    for (std::size_t j = 0; j < r.ny; ++j)
    {
      const double along = window.first_x_m + (static_cast<double>(i) - shift) * cell;
      const double across = window.first_y_m + (static_cast<double>(j) - shift) * cell;
      const double z = end.hull_height(along, across);
      if (!std::isfinite(z))
        throw ComputationError(fmt::format("flat rim: the hull's surface was not found over the window (search "
                                           "range) at x' = {:.4g} m along the ruling, y = {:.4g} m across",
                                           along, across));
      hull[i * r.ny + j] = z;
    }
  r.values = geometry::rolling_ball_opening(hull, nx, r.ny, cell, cell, edge_radius);
  return r;
}

/// The rest of the loaded ruling beyond the window: its line load as line
/// Hertz pressure at the sheet's R(x'), prescribed on the columns of `grid`
/// from `first_column` on, and its deflection over the grid.
struct RulingBeyond
{
  contact::HalfSpaceGrid grid;
  std::size_t first_column = 0;
  contact::HalfSpaceDeflection influence;
  std::function<double(double)> sheet_radius;
  double effective_modulus = 0, poisson_ratio = 0;

  std::vector<double> deflection(const LineLoad& load) const
  {
    std::vector<double> prescribed(grid.size(), 0.0);
    const std::size_t ny = grid.ny;
    for (std::size_t i = first_column; i < grid.nx; ++i)
    {
      const double x = grid.x(i), q = load.at(x);
      if (q <= 0)
        continue;
      const contact::LineHertz hertz = contact::line_contact(q, sheet_radius(x), effective_modulus, poisson_ratio);
      double column = 0;
      for (std::size_t j = 0; j < ny; ++j)
        column += prescribed[i * ny + j] = contact::pressure_profile(hertz.peak_pressure_pa, hertz.half_width_m, grid.y(j));
      // Each column carries q exactly, whatever its cells resolve of b.
      if (column > 0)
        for (std::size_t j = 0; j < ny; ++j)
          prescribed[i * ny + j] *= q / (column * grid.cell_y_m);
    }
    return influence(prescribed);
  }
};

/// The force (N) and its moment about x' = 0 (N m) of the window's columns in [from, to].
Eigen::Vector2d load_over(const std::vector<double>& pressure, const contact::HalfSpaceGrid& window, double from,
                          double to)
{
  Eigen::Vector2d sum = Eigen::Vector2d::Zero();
  const double area = window.cell_area_m2();
  for (std::size_t i = 0; i < window.nx; ++i)
    if (const double x = window.x(i); x >= from && x <= to)
      for (std::size_t j = 0; j < window.ny; ++j)
        sum += pressure[i * window.ny + j] * area * Eigen::Vector2d(1.0, x);
  return sum;
}

/// The level's readings from the window's pressure: the peak, the columns,
/// where the contact starts, the slopes under it.
void read_level(FlatRimLevel& level, const std::vector<double>& pressure, const contact::HalfSpaceGrid& window,
                const RoundedSurface& surface, double& largest_slope)
{
  const std::size_t nx = window.nx, ny = window.ny;
  const double cell = window.cell_x_m; // square cells
  const auto peak = std::ranges::max_element(pressure);
  const auto k_peak = static_cast<std::size_t>(peak - pressure.begin());
  level.peak_pressure_pa = *peak;
  level.peak_along_m = window.x(k_peak / ny);
  level.peak_across_m = window.y(k_peak % ny);
  level.contact_start_m = window.x(nx - 1);
  for (std::size_t i = 0; i < nx; ++i)
  {
    double column_peak = 0, column_load = 0;
    for (std::size_t j = 0; j < ny; ++j)
    {
      const double p = pressure[i * ny + j];
      column_peak = std::max(column_peak, p);
      column_load += p * window.cell_y_m;
      if (p > 0)
      {
        level.contact_start_m = std::min(level.contact_start_m, window.x(i));
        // Half-space theory's small slopes, over the loaded cells.
        if (i > 0 && i + 1 < nx && j > 0 && j + 1 < ny)
          largest_slope = std::max(largest_slope, std::hypot(surface(i + 1, j) - surface(i - 1, j),
                                                             surface(i, j + 1) - surface(i, j - 1))
                                                      / (2 * cell));
      }
    }
    level.station_m.push_back(window.x(i));
    level.station_peak_pa.push_back(column_peak);
    level.station_load_n_per_m.push_back(column_load);
  }
}

/// The ruling beyond the window cannot balance the body with it: the window
/// covers too much of the loaded ruling.
struct WindowCannotBalance : ComputationError
{
  using ComputationError::ComputationError;
};

/// The half-width across the ruling its grid needs: the widest contact of
/// the locus's load from `from` on, with room for a balance raising it and
/// the end's extra load near it; at least the settings' `across`.
double widest_contact(const FlatRimSettings& s, const EndProblem& end, double effective_modulus, double half_width,
                      double from, double cell)
{
  double widest = s.across_over_half_width * half_width;
  for (double x = from; x < end.load.length_m; x += cell)
    widest = std::max(widest, 1.6 * contact::line_contact(end.load.at(x), end.sheet_radius(x), effective_modulus,
                                                           s.poisson_ratio).half_width_m);
  return widest;
}

/// The whole ruling's columns from x' = 0: to 1.3 times the locus's loaded
/// length, stopping r_e short of the far rim (whose rounding it would need
/// beyond), and short of where an oblique far rim crosses the grid's end:
/// the grid and the rounding's margin about it lie within the body's
/// outline on the ground (convex: its far corners inside). A contact that
/// would run beyond stops solve_whole_ruling_level with a message.
std::size_t whole_ruling_columns(const FlatRimSettings& s, const EndProblem& end, double cell,
                                 std::size_t half_across)
{
  const std::size_t margin = opening_margin(s.edge_radius_m, cell);
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

/// The whole loaded ruling in one grid: F on it, its centre at the centre
/// of mass's foot by the tilt along the ruling alone.
FlatRimLevel solve_whole_ruling_level(const FlatRimSettings& s, const EndProblem& end, double effective_modulus,
                                      double half_width, double cell, double across_scale, double& largest_slope,
                                      double& end_lift)
{
  const auto start = std::chrono::steady_clock::now();
  const auto cells_over = [&](double length) { return static_cast<std::size_t>(std::ceil(length / cell)); };
  const std::size_t half_across
      = cells_over(across_scale * widest_contact(s, end, effective_modulus, half_width, 0, cell));
  const std::size_t first_cell = cells_over(s.before_over_half_width * half_width); // x' = 0 at this column
  const contact::HalfSpaceGrid grid{first_cell + whole_ruling_columns(s, end, cell, half_across),
                                    2 * half_across + 1,
                                    cell,
                                    cell,
                                    -static_cast<double>(first_cell) * cell,
                                    -static_cast<double>(half_across) * cell};
  const RoundedSurface surface = rounded_surface(end, grid, s.edge_radius_m);
  const contact::HalfSpaceDeflection deflection(grid, effective_modulus);
  const double force = end.load.load_to(end.load.length_m);
  const double foot = end.load.moment_to(end.load.length_m) / force;
  FlatRimLevel level;
  level.cell_m = cell;
  level.cells = grid.size();
  contact::HalfSpaceContact solved;
  std::vector<double> gap(grid.size());
  // F's centre beyond the foot (m) at this tilt; none when the contact runs
  // off the grid's far side (too little tilt).
  const auto centre_beyond_foot = [&](double tilt) -> std::optional<double> {
    for (std::size_t i = 0; i < grid.nx; ++i)
      for (std::size_t j = 0; j < grid.ny; ++j)
        gap[i * grid.ny + j] = surface(i, j) + tilt * grid.x(i);
    ++level.solves;
    try
    {
      contact::HalfSpaceContact next
          = contact::solve_half_space_contact(deflection, gap, force, {}, solved.pressure_pa);
      level.iterations += next.iterations;
      solved = std::move(next);
    }
    catch (const contact::ContactBeyondGrid& e)
    {
      if (e.across)
        throw;
      return std::nullopt;
    }
    const double everywhere = std::numeric_limits<double>::infinity();
    const Eigen::Vector2d total = load_over(solved.pressure_pa, grid, -everywhere, everywhere);
    return total[1] / total[0] - foot;
  };
  // More tilt moves F's centre towards the end. From an estimate (the
  // locus's load falling to none over its loaded length, on an approach of
  // a few q / E*), doubled or halved until the foot is bracketed, then
  // regula falsi with the Illinois halving.
  double tilt = 4 * end.load.at_end_n_per_m / (effective_modulus * end.load.length_m);
  double too_little = 0, too_much = 0;
  std::optional<double> beyond_little, beyond_much;
  int kept = 0; // the side the last solve replaced: +1 too little, -1 too much
  for (int k = 0;; ++k)
  {
    if (k == 60)
      throw ComputationError(fmt::format("flat rim, whole ruling: F's centre did not settle at the centre of mass's "
                                         "foot, {:.4g} m from the end (the contact may reach the ruling's far rim, "
                                         "which this grid leaves out)",
                                         foot));
    const std::optional<double> beyond = centre_beyond_foot(tilt);
    if (beyond && std::abs(*beyond) < 1e-4 * end.ruling_length_m)
      break;
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
  read_level(level, solved.pressure_pa, grid, surface, largest_slope);
  // Halfway along the contact the column reads line Hertz at its own load.
  const auto loaded = std::ranges::find_if(level.station_load_n_per_m | std::views::reverse,
                                           [](double q) { return q > 0; });
  const auto contact_end = static_cast<std::size_t>(std::distance(loaded, level.station_load_n_per_m.rend()) - 1);
  const std::size_t halfway = (first_cell + contact_end) / 2;
  level.far_peak_pa = level.station_peak_pa[halfway];
  level.far_line_hertz_pa = contact::line_contact(level.station_load_n_per_m[halfway], end.sheet_radius(grid.x(halfway)),
                                                  effective_modulus, s.poisson_ratio)
                                .peak_pressure_pa;
  end_lift = surface(first_cell, half_across);
  level.wall_s = seconds_since(start);
  return level;
}

FlatRimLevel solve_level(const FlatRimSettings& s, const EndProblem& end, double effective_modulus, double half_width,
                         double cell, double across_scale, double& largest_slope, double& end_lift)
{
  if (s.whole_ruling)
    return solve_whole_ruling_level(s, end, effective_modulus, half_width, cell, across_scale, largest_slope,
                                    end_lift);
  const auto start = std::chrono::steady_clock::now();
  const auto cells_over = [&](double length) { return static_cast<std::size_t>(std::ceil(length / cell)); };
  const double before = s.before_over_half_width * half_width;
  // The window's far edge, on the cells' boundary: the ruling beyond it is
  // loaded from there.
  const std::size_t after_cells = cells_over(s.after_over_half_width * half_width);
  const double after = (static_cast<double>(after_cells) + 0.5) * cell;

  const auto& radius_at = end.sheet_radius;
  // Across: the widest contact of the ruling beyond the window.
  const std::size_t half_across
      = cells_over(across_scale * widest_contact(s, end, effective_modulus, half_width, after, cell));
  const std::size_t ny = 2 * half_across + 1;
  const std::size_t window_nx = cells_over(before) + after_cells + 1;
  const std::size_t first_cell = cells_over(before); // x' = 0 at this column
  const std::size_t outer_nx = first_cell + cells_over(1.3 * end.load.length_m) + 1;
  const contact::HalfSpaceGrid outer_grid{outer_nx, ny, cell, cell, -static_cast<double>(first_cell) * cell,
                                          -static_cast<double>(half_across) * cell};
  const contact::HalfSpaceGrid window{window_nx, ny, cell, cell, outer_grid.first_x_m, outer_grid.first_y_m};

  const RulingBeyond beyond{outer_grid, window_nx, contact::HalfSpaceDeflection(outer_grid, effective_modulus),
                            end.sheet_radius, effective_modulus, s.poisson_ratio};
  const RoundedSurface surface = rounded_surface(end, window, s.edge_radius_m);

  std::vector<double> gap(window.size());
  const contact::HalfSpaceDeflection deflection(window, effective_modulus);
  contact::HalfSpaceContactSettings solver;
  solver.contact_continues_past_last_x = true;
  FlatRimLevel level;
  level.cell_m = cell;
  level.cells = window.size();
  contact::HalfSpaceContact solved;
  // The window shares the counter-face's approach and tilt with the ruling
  // beyond it: both are set (through the window's force and the tilt, gap +
  // tilt x') so that the window carries the ruling's load and moment over its
  // matching zone [0.5, 0.9] of `after`, where the end no longer shows.
  const double zone_start = 0.5 * after, zone_end = 0.9 * after;
  Eigen::Vector2d unknowns(1.0, 0.0);
  Eigen::Matrix2d jacobian;
  bool has_jacobian = false;
  const auto match_window = [&](const LineLoad& load, const std::vector<double>& beyond) {
    const double zone_load = load.load_to(zone_end) - load.load_to(zone_start);
    const double zone_arm = (load.moment_to(zone_end) - load.moment_to(zone_start)) / zone_load;
    const auto mismatch = [&](const Eigen::Vector2d& guess) {
      // guess: the window's force over the ruling's on it, the tilt in b^2 / (r_e after).
      const double tilt = guess[1] * half_width * half_width / (s.edge_radius_m * after);
      for (std::size_t i = 0; i < window_nx; ++i)
        for (std::size_t j = 0; j < ny; ++j)
          gap[i * ny + j] = surface(i, j) + beyond[i * ny + j] + tilt * window.x(i);
      solved = contact::solve_half_space_contact(deflection, gap, guess[0] * load.load_to(after), solver,
                                                 solved.pressure_pa);
      level.iterations += solved.iterations;
      ++level.solves;
      const Eigen::Vector2d zone = load_over(solved.pressure_pa, window, zone_start, zone_end);
      return Eigen::Vector2d(zone[0] / zone_load - 1, (zone[1] / zone[0] - zone_arm) / (zone_end - zone_start));
    };
    // Broyden's method from a finite-difference Jacobian, both kept from one
    // balance iteration to the next.
    Eigen::Vector2d residual = mismatch(unknowns);
    if (!has_jacobian)
      for (int k = 0; k < 2; ++k)
      {
        Eigen::Vector2d step = Eigen::Vector2d::Zero();
        step[k] = k == 0 ? 0.02 : 0.1;
        jacobian.col(k) = (mismatch(unknowns + step) - residual) / step[k];
      }
    has_jacobian = true;
    for (int k = 0; residual.cwiseAbs().maxCoeff() > 1e-4; ++k)
    {
      if (k > 30)
        throw ComputationError(fmt::format("flat rim: the window did not match the ruling beyond it (load off "
                                           "by {:.3g}, moment arm by {:.3g} of the zone)",
                                           residual[0], residual[1]));
      const Eigen::Vector2d step = -jacobian.colPivHouseholderQr().solve(residual);
      unknowns += step;
      const Eigen::Vector2d next = mismatch(unknowns);
      jacobian += (next - residual - jacobian * step) * step.transpose() / step.squaredNorm();
      residual = next;
    }
  };
  // The body's balance: the window's load and the ruling's beyond it carry F
  // with its centre at the centre of mass's foot. The ruling beyond takes
  // the no-tension linear rule with the rest of F and its moment.
  LineLoad load = end.load;
  const double force = load.load_to(load.length_m), force_moment = load.moment_to(load.length_m);
  // The balance as a fixed point of the rule beyond (q at the end and its
  // slope, scaled by the locus's): Broyden's method, starting from half
  // steps (a full step overshoots once the window is long: its own load
  // then answers strongly to the rule beyond it).
  const double q_scale = end.load.at_end_n_per_m, slope_scale = q_scale / end.ruling_length_m;
  Eigen::Vector2d rule(1.0, end.load.slope_n_per_m2 / slope_scale), last_residual = Eigen::Vector2d::Zero(),
                                                                       last_step = Eigen::Vector2d::Zero();
  Eigen::Matrix2d balance_jacobian = -2 * Eigen::Matrix2d::Identity();
  const auto rule_load = [&] {
    return LineLoad::no_tension(rule[0] * q_scale, rule[1] * slope_scale, end.ruling_length_m);
  };
  // Back to half the last step.
  const auto halve_step = [&] {
    last_step /= 2;
    rule -= last_step;
    load = rule_load();
  };
  const auto cannot_balance = [&](const char* why) {
    return WindowCannotBalance(fmt::format("flat rim: {} (window {:.3g} m of the ruling's {:.3g} m)", why, after,
                                           end.ruling_length_m));
  };
  for (int balance = 0;; ++balance)
  {
    match_window(load, beyond.deflection(load));
    const double everywhere = std::numeric_limits<double>::infinity();
    const Eigen::Vector2d on_window = load_over(solved.pressure_pa, window, -everywhere, everywhere);
    const double window_force = on_window[0], window_moment = on_window[1];
    level.window_load_change = window_force / end.load.load_to(after) - 1;
    if (!end.balance_body)
      break;
    const double beyond_force = force - window_force;
    const std::optional<LineLoad> next_load = LineLoad::carrying(
        beyond_force, (force_moment - window_moment) / beyond_force, after, end.ruling_length_m);
    if (!next_load || next_load->length_m > outer_grid.x(outer_nx - 1))
    {
      // The step went too far (a long window's load answers strongly to the
      // rule beyond it): back to half of it.
      if (balance == 0 || balance > 40)
        throw cannot_balance("the ruling beyond the window cannot balance the body");
      halve_step();
      continue;
    }
    const Eigen::Vector2d residual
        = Eigen::Vector2d(next_load->at_end_n_per_m / q_scale, next_load->slope_n_per_m2 / slope_scale) - rule;
    if (residual.cwiseAbs().maxCoeff() < 1e-4)
      break;
    if (balance > 40)
      throw cannot_balance("the body's balance did not settle");
    if (balance > 0)
      balance_jacobian += (residual - last_residual - balance_jacobian * last_step) * last_step.transpose()
                          / last_step.squaredNorm();
    last_step = -balance_jacobian.colPivHouseholderQr().solve(residual);
    last_residual = residual;
    rule += last_step;
    load = rule_load();
    // A rule that ends inside the window, or puts more than F on it, leaves
    // nothing beyond to balance with (a window over most of the loaded
    // ruling: its rule's q at the end extrapolates a short load beyond it):
    // back to half the step.
    for (int halving = 0; !(load.length_m > after && load.load_to(after) < force); ++halving)
    {
      if (halving == 10)
        throw cannot_balance("the rule beyond the window ends inside it or loads it beyond F");
      halve_step();
    }
  }
  level.balanced_end_line_load_n_per_m = load.at_end_n_per_m;
  level.balanced_slope_n_per_m2 = load.slope_n_per_m2;
  level.balanced_loaded_length_m = load.length_m;

  read_level(level, solved.pressure_pa, window, surface, largest_slope);
  const std::size_t far = first_cell + cells_over(0.75 * after);
  level.far_peak_pa = level.station_peak_pa[far];
  level.far_line_hertz_pa = contact::line_contact(load.at(window.x(far)), radius_at(window.x(far)),
                                                  effective_modulus, s.poisson_ratio)
                                .peak_pressure_pa;
  end_lift = surface(first_cell, half_across);
  level.wall_s = seconds_since(start);
  return level;
}
} // namespace

namespace
{
void check_settings(const FlatRimSettings& s)
{
  for (const auto& [value, name] : {std::pair{s.body.radius_m, "--radius"}, {s.normal_load_n, "--load"},
                                    {s.edge_radius_m, "--edge-radius"}, {s.youngs_modulus_pa, "--youngs-modulus"},
                                    {s.sheet_radius_m, "--sheet-radius"}, {s.load_n_per_m, "--load-per-length"},
                                    {s.cells_per_half_width, "--cells"}, {s.before_over_half_width, "--before"},
                                    {s.after_over_half_width, "--after"}, {s.across_over_half_width, "--across"}})
    if (!(value > 0) || !std::isfinite(value))
      throw InputError(fmt::format("flat-rim: {} must be positive and finite, got {}", name, value));
  if (!(s.poisson_ratio > -1 && s.poisson_ratio < 0.5))
    throw InputError(fmt::format("flat-rim: --poisson must lie in (-1, 0.5), got {}", s.poisson_ratio));
  if (s.levels < 1)
    throw InputError("flat-rim: --levels must be at least 1");
  if (s.extra_levels < 0)
    throw InputError("flat-rim: --extra-levels must not be negative");
  const auto check_angle = [](double angle, const char* name) {
    if (!(angle >= smallest_flat_rim_angle_rad && angle <= std::numbers::pi))
      throw InputError(fmt::format("flat-rim: {} {} deg is outside [{}, 180] deg, where the rim's other face is "
                                   "gentle enough for half-space theory (use `rollcheck rim`)",
                                   name, angle * 180 / std::numbers::pi,
                                   smallest_flat_rim_angle_rad * 180 / std::numbers::pi));
  };
  if (s.interior_angle_rad != 0)
    check_angle(s.interior_angle_rad, "--interior-angle");
  check_angle(s.end_angle_rad, "--end-angle");
}

/// The peak's change from the level before the last to the last (two levels at least).
double last_level_change(const std::vector<FlatRimLevel>& levels)
{
  return levels.back().peak_pressure_pa / levels[levels.size() - 2].peak_pressure_pa - 1;
}

/// The levels and the longer window of one end at the settings' window,
/// into `result`; the window widens across where the contact outgrows it.
void solve_window(const FlatRimSettings& s, const EndProblem& end, FlatRimContact& result)
{
  result.levels.clear();
  result.largest_slope = 0;
  const auto level_at = [&](const FlatRimSettings& settings, double cell, double& largest_slope, double& end_lift) {
    for (;;)
      try
      {
        return solve_level(settings, end, result.effective_modulus_pa, result.half_width_m, cell,
                           result.across_scale, largest_slope, end_lift);
      }
      catch (const contact::ContactBeyondGrid& e)
      {
        if (!e.across || result.across_scale > 2)
          throw;
        result.across_scale *= 1.5;
      }
  };
  // The window's length: the first level again with the window twice as
  // long (the half-space's reach along the ruling is long: the end's extra
  // line load decays over tens of b). First, as the solve most likely to
  // need a shorter or wider window.
  const double first_cell = result.half_width_m / s.cells_per_half_width;
  if (!s.whole_ruling)
  {
    FlatRimSettings longer = s;
    longer.after_over_half_width *= 2;
    double unused_slope = 0, unused_lift = 0;
    result.longer_window_peak_pa = level_at(longer, first_cell, unused_slope, unused_lift).peak_pressure_pa;
  }
  const auto resolved = [&] {
    return result.levels.size() >= 2 && std::abs(last_level_change(result.levels)) < s.tolerance;
  };
  for (int k = 0; k < s.levels + s.extra_levels && (k < s.levels || !resolved()); ++k)
    result.levels.push_back(level_at(s, first_cell / std::pow(2.0, k), result.largest_slope, result.end_lift_m));
}

/// The levels and the longer window of one end, into `result`: at the
/// settings' window, or shortened where the ruling beyond cannot balance
/// the body with it.
void solve_end(const FlatRimSettings& s, const EndProblem& end, FlatRimContact& result)
{
  const auto start = std::chrono::steady_clock::now();
  result.end_line_load_n_per_m = end.load.at_end_n_per_m;
  const contact::LineHertz at_end = contact::line_contact(end.load.at_end_n_per_m, result.reference_radius_m,
                                                          result.effective_modulus_pa, s.poisson_ratio);
  result.half_width_m = at_end.half_width_m;
  result.line_hertz_peak_pa = at_end.peak_pressure_pa;
  FlatRimSettings window = s;
  for (int shortened = 0;; ++shortened)
    try
    {
      solve_window(window, end, result);
      break;
    }
    catch (const WindowCannotBalance&)
    {
      if (shortened == 3)
        throw;
      window.after_over_half_width *= 0.75;
    }
  result.whole_ruling = s.whole_ruling;
  result.after_over_half_width
      = s.whole_ruling ? result.levels.back().station_m.back() / result.half_width_m : window.after_over_half_width;
  if (!s.whole_ruling)
    result.window_change = result.longer_window_peak_pa / result.levels.front().peak_pressure_pa - 1;
  if (result.levels.size() >= 2)
    result.last_change = last_level_change(result.levels);
  result.converged = result.levels.size() >= 2 && std::abs(result.last_change) < s.tolerance
                     && std::abs(result.window_change) < s.tolerance;
  result.wall_s = seconds_since(start);
}
} // namespace

bool needs_whole_ruling(const FlatRimSettings& s, const FlatRimContact& r)
{
  return !r.whole_ruling && r.after_over_half_width < s.after_over_half_width
         && !(std::abs(r.window_change) < s.tolerance);
}

double end_hull_height(const LoopEnd& end, double along_m, double across_m)
{
  return RulingEndSurface(end).height(along_m, across_m);
}

LoopEnd body_loop_end(const geometry::BodySpec& body, double interior_angle_rad, int loop_side)
{
  if (loop_side != 0 && loop_side != 1)
    throw InputError(fmt::format("flat-rim: the loop's side must be 0 (forwards) or 1 (backwards), got {}", loop_side));
  const std::vector<oracle::Circle> circles = oracle::line_contact_circles(body);
  if (body.body == "cylinder")
    throw InputError("flat-rim: body 'cylinder': its ruling ends are square (90 deg), no rim end of 150-180 deg; a "
                     "square end is `rollcheck rim --interior-angle 90`");
  const Eigen::Vector3d centre_of_mass
      = body.body == "oloid"
            ? Eigen::Vector3d(0.5 * (circles[0].centre_m + circles[1].centre_m))
            : oracle::mass_model_of_mesh(oracle::mass_mesh(body, oracle::RollingStudyParameters{}.mass_points), 1.0)
                  .centre_of_mass_m;
  if (interior_angle_rad >= std::numbers::pi)
    return flattest_loop_ends(circles, centre_of_mass, {}).flattest;
  const double angles[1] = {interior_angle_rad};
  return flattest_loop_ends(circles, centre_of_mass, angles).at_angle[0][loop_side];
}

FlatRimContact flat_rim_contact(const FlatRimSettings& s)
{
  check_settings(s);
  if (s.interior_angle_rad == 0)
    return flat_rim_contact(s, body_loop_end(s.body, s.end_angle_rad, s.loop_side));
  if (s.whole_ruling)
    throw InputError("flat-rim: --whole-ruling solves a body's loop end; a straight rim's load is held along a long "
                     "contact, with no ruling to end it (drop --interior-angle or --whole-ruling)");
  FlatRimContact result;
  result.effective_modulus_pa = contact::effective_modulus(s.youngs_modulus_pa, s.poisson_ratio, s.steel_counter_face);
  result.interior_angle_rad = s.interior_angle_rad;
  result.end_radius_m = s.sheet_radius_m;
  // rim's end model with its flat sheet: a block whose top (x' > 0) meets
  // the rim's other face, leaning by 180 deg - a, along a straight edge
  // across the ruling, the sheet's profile y^2 / (2 R) in the gap.
  EndProblem end;
  const double lean = std::tan(std::numbers::pi - s.interior_angle_rad), radius = s.sheet_radius_m;
  end.hull_height = [lean, radius](double x, double y) { return y * y / (2 * radius) + std::max(0.0, -x * lean); };
  end.sheet_radius = [radius](double) { return radius; };
  result.reference_radius_m = std::max(radius, s.edge_radius_m);
  const double half_width = contact::line_contact(s.load_n_per_m, result.reference_radius_m,
                                                  result.effective_modulus_pa, s.poisson_ratio)
                                .half_width_m;
  // A long contact: the line load held to 400 b beyond the end (its far
  // end's deflection over the window is smooth; the window's tilt takes it).
  end.load = {s.load_n_per_m, 0.0, std::max(400.0, 3 * s.after_over_half_width) * half_width};
  end.ruling_length_m = end.load.length_m;
  solve_end(s, end, result);
  return result;
}

FlatRimContact flat_rim_contact(const FlatRimSettings& s, const LoopEnd& loop_end)
{
  check_settings(s);
  FlatRimContact result;
  result.effective_modulus_pa = contact::effective_modulus(s.youngs_modulus_pa, s.poisson_ratio, s.steel_counter_face);
  const oracle::Ruling& ruling = loop_end.ruling;
  result.ruling_length_m = ruling.length_m;
  result.centre_of_pressure = loop_end.centre_of_pressure_from_end();
  result.interior_angle_rad = loop_end.interior_angle_rad;
  result.end_radius_m = loop_end.radius_m();
  if (!(result.interior_angle_rad >= smallest_flat_rim_angle_rad))
    throw InputError(fmt::format("flat-rim: the end's interior angle, {:.4g} deg, is below {} deg (use `rollcheck rim`)",
                                 result.interior_angle_rad * 180 / std::numbers::pi,
                                 smallest_flat_rim_angle_rad * 180 / std::numbers::pi));
  const auto surface = std::make_shared<const RulingEndSurface>(loop_end);
  EndProblem end;
  end.hull_height = [surface](double x, double y) { return surface->height(x, y); };
  // Linear along the ruling: exact for a developable sheet.
  end.sheet_radius = [r0 = loop_end.radius_m(), r1 = loop_end.other_radius_m(), length = ruling.length_m](double x) {
    return r0 + (r1 - r0) * std::clamp(x / length, 0.0, 1.0);
  };
  // The contact locus's no-tension linear rule from this end (oracle::line_load).
  const double c = result.centre_of_pressure;
  const auto q = [&](double f) { return oracle::line_load(s.normal_load_n, c, ruling.length_m, f); };
  if (!(q(0) > 0))
    throw ComputationError(fmt::format("flat rim: the end carries no load (c = {:.4f} from it)", c));
  end.load = LineLoad::no_tension(q(0), c < 1.0 / 3 ? -q(0) / (3 * c * ruling.length_m) : (q(1) - q(0)) / ruling.length_m,
                                  ruling.length_m);
  end.ruling_length_m = ruling.length_m;
  end.balance_body = true;
  // The finished part has no radius below r_e (the hull's is 0 at a sheet's apex).
  result.reference_radius_m = std::max(result.end_radius_m, s.edge_radius_m);
  solve_end(s, end, result);
  return result;
}

nlohmann::json to_json(const FlatRimContact& r)
{
  nlohmann::json levels = nlohmann::json::array();
  for (const FlatRimLevel& l : r.levels)
    levels.push_back({{"cell_m", l.cell_m},
                      {"cells", l.cells},
                      {"iterations", l.iterations},
                      {"solves", l.solves},
                      {"peak_pressure_pa", l.peak_pressure_pa},
                      {"peak_along_m", l.peak_along_m},
                      {"peak_across_m", l.peak_across_m},
                      {"contact_start_m", l.contact_start_m},
                      {"window_load_change", l.window_load_change},
                      {"balanced_end_line_load_n_per_m", l.balanced_end_line_load_n_per_m},
                      {"balanced_slope_n_per_m2", l.balanced_slope_n_per_m2},
                      {"balanced_loaded_length_m", l.balanced_loaded_length_m},
                      {"far_peak_pa", l.far_peak_pa},
                      {"far_line_hertz_pa", l.far_line_hertz_pa},
                      {"wall_s", l.wall_s},
                      {"station_m", l.station_m},
                      {"station_peak_pa", l.station_peak_pa},
                      {"station_load_n_per_m", l.station_load_n_per_m}});
  return {{"ruling_length_m", r.ruling_length_m},
          {"end_interior_angle_deg", r.interior_angle_rad * 180 / std::numbers::pi},
          {"end_sheet_radius_m", r.end_radius_m},
          {"centre_of_pressure", r.centre_of_pressure},
          {"end_line_load_n_per_m", r.end_line_load_n_per_m},
          {"effective_modulus_pa", r.effective_modulus_pa},
          {"reference_radius_m", r.reference_radius_m},
          {"half_width_m", r.half_width_m},
          {"line_hertz_peak_pa", r.line_hertz_peak_pa},
          {"largest_slope", r.largest_slope},
          {"end_lift_m", r.end_lift_m},
          {"peak_pressure_pa", r.levels.back().peak_pressure_pa},
          {"far_line_hertz_error", r.levels.back().far_peak_pa / r.levels.back().far_line_hertz_pa - 1},
          {"last_change", r.last_change},
          // The whole ruling has no longer window.
          {"longer_window_peak_pa", r.whole_ruling ? nlohmann::json(nullptr) : nlohmann::json(r.longer_window_peak_pa)},
          {"window_change", r.whole_ruling ? nlohmann::json(nullptr) : nlohmann::json(r.window_change)},
          {"after_over_half_width", r.after_over_half_width},
          {"across_scale", r.across_scale},
          {"whole_ruling", r.whole_ruling},
          {"converged", r.converged},
          {"wall_s", r.wall_s},
          {"levels", levels}};
}
} // namespace rollcheck::study::rims
