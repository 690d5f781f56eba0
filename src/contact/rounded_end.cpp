#include "contact/rounded_end.h"
#include "contact/rounded_end_whole_ruling.h"
#include "contact/rounded_end_window.h"
#include "core/refinement_series.h"
#include <algorithm>
#include <cmath>
#include <fmt/format.h>

namespace rollcheck::contact
{
namespace
{
/// The peak at each level: the flat rim's verdicts are on its relative change.
RefinementSeries peak_series(const std::vector<RoundedEndLevel>& levels)
{
  RefinementSeries peaks;
  for (const RoundedEndLevel& level : levels)
    peaks.add(level.cell_m, level.peak_pressure_pa);
  return peaks;
}

/// A level on cells of `cell`, the window widened across (by half, at most
/// twice) where the contact reaches its border there.
SolvedLevel solve_level(const RoundedEndSettings& s, const RoundedEndProblem& end, double cell,
                        RoundedEndContact& result)
{
  for (;;)
    try
    {
      const LevelScale scale{result.effective_modulus_pa, result.half_width_m, result.across_scale};
      return s.whole_ruling ? solve_whole_ruling_level(s, end, scale, cell) : solve_window_level(s, end, scale, cell);
    }
    catch (const ContactBeyondGrid& e)
    {
      if (!e.across || result.across_scale > 2)
        throw;
      result.across_scale *= 1.5;
    }
}

/// The levels and the longer window of one end at the settings' window,
/// into `result`.
void solve_levels(const RoundedEndSettings& s, const RoundedEndProblem& end, RoundedEndContact& result,
                  const RoundedEndProgress& progress)
{
  auto tell = [&](const std::string& what) {
    if (progress)
      progress(what);
  };
  result.levels.clear();
  result.largest_slope = 0;
  // The window's length: the first level again with the window twice as
  // long (the half-space's reach along the ruling is long: the end's extra
  // line load decays over tens of b). First, as the solve most likely to
  // need a shorter or wider window.
  const double first_cell = result.half_width_m / s.cells_per_half_width;
  if (!s.whole_ruling)
  {
    RoundedEndSettings longer = s;
    longer.after_over_half_width *= 2;
    tell(fmt::format("the window twice as long ({:.0f} b), cells of b / {:.0f}", longer.after_over_half_width,
                     s.cells_per_half_width));
    result.longer_window_peak_pa = solve_level(longer, end, first_cell, result).level.peak_pressure_pa;
  }
  for (int k = 0; k < s.levels + s.extra_levels
                  && (k < s.levels || !converged(peak_series(result.levels), s.tolerance, relative_change));
       ++k)
  {
    tell(fmt::format("level {} ({} set, up to {} more while the peak changes), cells of b / {:.0f}", k + 1, s.levels,
                     s.extra_levels, s.cells_per_half_width * std::pow(2.0, k)));
    SolvedLevel solved = solve_level(s, end, first_cell / std::pow(2.0, k), result);
    result.largest_slope = std::max(result.largest_slope, solved.largest_slope);
    result.end_lift_m = solved.end_lift_m;
    result.levels.push_back(std::move(solved.level));
  }
}
} // namespace

RoundedEndContact solve_rounded_end(const RoundedEndSettings& s, const RoundedEndProblem& end,
                                    const RoundedEndProgress& progress)
{
  const auto start = std::chrono::steady_clock::now();
  RoundedEndContact result;
  result.effective_modulus_pa = effective_modulus(s);
  result.reference_radius_m = reference_radius(s, end);
  result.end_line_load_n_per_m = end.load.at_end_n_per_m;
  const LineHertz at_end = end_line_hertz(s, end);
  result.half_width_m = at_end.half_width_m;
  result.line_hertz_peak_pa = at_end.peak_pressure_pa;
  // Shortened by a quarter where the ruling beyond cannot balance the body with it.
  RoundedEndSettings window = s;
  for (int shortened = 0;; ++shortened)
    try
    {
      solve_levels(window, end, result, progress);
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
  const RefinementSeries peaks = peak_series(result.levels);
  if (peaks.size() >= 2)
    result.last_change = last_change(peaks, relative_change);
  result.converged = converged(peaks, s.tolerance, relative_change) && std::abs(result.window_change) < s.tolerance;
  result.wall_s = seconds_since(start);
  return result;
}

bool needs_whole_ruling(const RoundedEndSettings& s, const RoundedEndContact& r)
{
  return !r.whole_ruling && r.after_over_half_width < s.after_over_half_width
         && !(std::abs(r.window_change) < s.tolerance);
}
} // namespace rollcheck::contact
