#include "contact/rounded_end_window.h"
#include "contact/line_hertz_beyond.h"
#include <Eigen/Dense>
#include <cmath>
#include <fmt/format.h>
#include <limits>
#include <optional>

namespace rollcheck::contact
{
namespace
{
/// The window [-before, after] and, on the same cells, the ruling from the
/// window's start to 1.3 times its loaded length (the window's columns first).
struct WindowGrids
{
  double after = 0;            ///< the window's far edge, on the cells' boundary: the ruling beyond is loaded from there
  std::size_t first_cell = 0;  ///< x' = 0 at this column
  std::size_t half_across = 0; ///< y = 0 at this row
  HalfSpaceGrid window;
  HalfSpaceGrid outer;
};

WindowGrids window_grids(const RoundedEndSettings& s, const RoundedEndProblem& end, const LevelScale& scale,
                         double cell)
{
  const double before = s.before_over_half_width * scale.half_width_m;
  const std::size_t after_cells = cells_over(s.after_over_half_width * scale.half_width_m, cell);
  WindowGrids g;
  g.after = (static_cast<double>(after_cells) + 0.5) * cell;
  // Across: the widest contact of the ruling beyond the window.
  g.half_across = half_across_cells(s, end, scale, g.after, cell);
  const std::size_t ny = 2 * g.half_across + 1;
  g.first_cell = cells_over(before, cell);
  const std::size_t window_nx = g.first_cell + after_cells + 1;
  const std::size_t outer_nx = g.first_cell + cells_over(1.3 * end.load.length_m, cell) + 1;
  g.outer = {outer_nx, ny, cell, cell, -static_cast<double>(g.first_cell) * cell,
             -static_cast<double>(g.half_across) * cell};
  g.window = {window_nx, ny, cell, cell, g.outer.first_x_m, g.outer.first_y_m};
  return g;
}

/// The window's contact matched to the ruling beyond it: its force (over the
/// ruling's on the window) and its tilt, in b^2 / (r_e after), set so that
/// the matching zone carries the ruling's load and moment arm. The guess
/// and Broyden's Jacobian are kept from one balance iteration to the next.
class WindowMatch
{
public:
  WindowMatch(const RoundedEndSettings& s, const WindowGrids& grids, const BallRoundedSurface& surface,
              const LevelScale& scale, RoundedEndLevel& level)
      : grids_(grids), surface_(surface), level_(level), deflection_(grids.window, scale.effective_modulus_pa),
        gap_(grids.window.size()), half_width_(scale.half_width_m), edge_radius_(s.edge_radius_m)
  {
    solver_.contact_continues_past_last_x = true;
  }

  /// Matches the window to `load`, whose part beyond the window deflects it by `beyond`.
  void operator()(const RulingLineLoad& load, const std::vector<double>& beyond)
  {
    const double zone_load = load.load_to(zone_end()) - load.load_to(zone_start());
    const double zone_arm = (load.moment_to(zone_end()) - load.moment_to(zone_start())) / zone_load;
    const auto mismatch = [&](const Eigen::Vector2d& guess) {
      solve(guess, load.load_to(grids_.after), beyond);
      const Eigen::Vector2d zone = load_over(solved_.pressure_pa, grids_.window, zone_start(), zone_end());
      return Eigen::Vector2d(zone[0] / zone_load - 1, (zone[1] / zone[0] - zone_arm) / (zone_end() - zone_start()));
    };
    Eigen::Vector2d residual = mismatch(unknowns_);
    if (!residual.allFinite())
    {
      // The force and tilt kept from the last balance iteration lift this
      // load's matching zone off: start again from the window's own load, untilted.
      unknowns_ = Eigen::Vector2d(1.0, 0.0);
      has_jacobian_ = false;
      residual = mismatch(unknowns_);
      if (!residual.allFinite())
        throw ComputationError("flat rim: the window's matching zone is off the plane under its own load, untilted");
    }
    // A step that lifts the matching zone off the plane has no moment arm
    // (a NaN mismatch) and is quartered: on a sheet much flatter than the
    // fillet (R >> r_e) the tilt's unit b^2 / (r_e after) is hundreds of
    // times the tilt the window takes.
    const auto quartered_until_finite = [&](Eigen::Vector2d step, Eigen::Vector2d& moved) {
      for (int quartering = 0; !(moved = mismatch(unknowns_ + step)).allFinite(); ++quartering)
      {
        if (quartering == 12)
          throw ComputationError("flat rim: every step of the window's force and tilt lifts its matching zone off");
        step /= 4;
      }
      return step;
    };
    Eigen::Vector2d moved;
    if (!has_jacobian_)
      for (int k = 0; k < 2; ++k)
      {
        Eigen::Vector2d step = Eigen::Vector2d::Zero();
        step[k] = k == 0 ? 0.02 : 0.1;
        step = quartered_until_finite(step, moved);
        jacobian_.col(k) = (moved - residual) / step[k];
      }
    has_jacobian_ = true;
    for (int k = 0; residual.cwiseAbs().maxCoeff() > 1e-4; ++k)
    {
      if (k > 30)
        throw ComputationError(fmt::format("flat rim: the window did not match the ruling beyond it (load off "
                                           "by {:.3g}, moment arm by {:.3g} of the zone)",
                                           residual[0], residual[1]));
      const Eigen::Vector2d step = quartered_until_finite(-jacobian_.colPivHouseholderQr().solve(residual), moved);
      unknowns_ += step;
      const Eigen::Vector2d next = moved;
      jacobian_ += (next - residual - jacobian_ * step) * step.transpose() / step.squaredNorm();
      residual = next;
    }
  }

  const HalfSpaceContact& solved() const { return solved_; }

private:
  double zone_start() const { return 0.5 * grids_.after; }
  double zone_end() const { return 0.9 * grids_.after; }

  /// The window's contact at `guess` (its force over `window_load`, the tilt).
  void solve(const Eigen::Vector2d& guess, double window_load, const std::vector<double>& beyond)
  {
    const HalfSpaceGrid& window = grids_.window;
    const double tilt = guess[1] * half_width_ * half_width_ / (edge_radius_ * grids_.after);
    for (std::size_t i = 0; i < window.nx; ++i)
      for (std::size_t j = 0; j < window.ny; ++j)
        gap_[i * window.ny + j] = surface_(i, j) + beyond[i * window.ny + j] + tilt * window.x(i);
    solved_ = solve_half_space_contact(deflection_, gap_, guess[0] * window_load, solver_, solved_.pressure_pa);
    level_.iterations += solved_.iterations;
    ++level_.solves;
  }

  const WindowGrids& grids_;
  const BallRoundedSurface& surface_;
  RoundedEndLevel& level_;
  HalfSpaceDeflection deflection_;
  HalfSpaceContactSettings solver_;
  std::vector<double> gap_;
  double half_width_, edge_radius_; ///< b and r_e: the tilt's unit is b^2 / (r_e after)
  HalfSpaceContact solved_;
  Eigen::Vector2d unknowns_{1.0, 0.0};
  Eigen::Matrix2d jacobian_;
  bool has_jacobian_ = false;
};

/// The ruling's load once the window is matched to it and, for a body's
/// end, the body balances: the window's load and the ruling's beyond it
/// carry F with its centre at the centre of mass's foot, the ruling beyond
/// taking the no-tension linear rule with the rest of F and its moment. The
/// balance is a fixed point of the rule beyond (q at the end and its slope,
/// scaled by the locus's): Broyden's method, starting from half steps (a
/// full step overshoots once the window is long: its own load then answers
/// strongly to the rule beyond it).
RulingLineLoad balance_body(const RoundedEndProblem& end, const WindowGrids& grids, const LineHertzBeyond& beyond,
                            WindowMatch& match, RoundedEndLevel& level)
{
  const double after = grids.after;
  RulingLineLoad load = end.load;
  const double force = load.load_to(load.length_m), force_moment = load.moment_to(load.length_m);
  const double q_scale = end.load.at_end_n_per_m, slope_scale = q_scale / end.ruling_length_m;
  Eigen::Vector2d rule(1.0, end.load.slope_n_per_m2 / slope_scale), last_residual = Eigen::Vector2d::Zero(),
                                                                       last_step = Eigen::Vector2d::Zero();
  Eigen::Matrix2d balance_jacobian = -2 * Eigen::Matrix2d::Identity();
  const auto rule_load = [&] {
    return RulingLineLoad::no_tension(rule[0] * q_scale, rule[1] * slope_scale, end.ruling_length_m);
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
    match(load, beyond.deflection(load));
    const double everywhere = std::numeric_limits<double>::infinity();
    const Eigen::Vector2d on_window = load_over(match.solved().pressure_pa, grids.window, -everywhere, everywhere);
    const double window_force = on_window[0], window_moment = on_window[1];
    level.window_load_change = window_force / end.load.load_to(after) - 1;
    if (!end.balance_body)
      return load;
    const double beyond_force = force - window_force;
    const std::optional<RulingLineLoad> next_load = RulingLineLoad::carrying(
        beyond_force, (force_moment - window_moment) / beyond_force, after, end.ruling_length_m);
    if (!next_load || next_load->length_m > grids.outer.x(grids.outer.nx - 1))
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
      return load;
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
}
} // namespace

SolvedLevel solve_window_level(const RoundedEndSettings& s, const RoundedEndProblem& end, const LevelScale& scale,
                               double cell)
{
  const auto start = std::chrono::steady_clock::now();
  const WindowGrids grids = window_grids(s, end, scale, cell);
  const LineHertzBeyond beyond{grids.outer, grids.window.nx, HalfSpaceDeflection(grids.outer, scale.effective_modulus_pa),
                               end.sheet_radius, scale.effective_modulus_pa, s.poisson_ratio};
  const BallRoundedSurface surface = ball_rounded_surface(end.hull_height, grids.window, s.edge_radius_m);
  SolvedLevel solved;
  RoundedEndLevel& level = solved.level;
  level.cell_m = cell;
  level.cells = grids.window.size();
  WindowMatch match(s, grids, surface, scale, level);
  const RulingLineLoad load = balance_body(end, grids, beyond, match, level);
  level.balanced_end_line_load_n_per_m = load.at_end_n_per_m;
  level.balanced_slope_n_per_m2 = load.slope_n_per_m2;
  level.balanced_loaded_length_m = load.length_m;

  const std::vector<double>& pressure = match.solved().pressure_pa;
  read_level(level, pressure, grids.window);
  solved.largest_slope = largest_loaded_slope(surface, grids.window, pressure);
  const std::size_t far = grids.first_cell + cells_over(0.75 * grids.after, cell);
  const double far_x = grids.window.x(far);
  level.far_peak_pa = level.station_peak_pa[far];
  level.far_line_hertz_pa = line_contact(load.at(far_x), end.sheet_radius(far_x), scale.effective_modulus_pa,
                                         s.poisson_ratio)
                                .peak_pressure_pa;
  solved.end_lift_m = surface(grids.first_cell, grids.half_across);
  level.wall_s = seconds_since(start);
  return solved;
}
} // namespace rollcheck::contact
