#include "contact/rounded_end_half_space.h"
#include "core/error.h"
#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <numbers>
#include <optional>

namespace rollcheck::contact
{
namespace
{
/// Edges from `start` towards `stop` (excluding start), the first cell
/// `first` long, each next `growth` times longer up to `largest`, the last
/// one cut at stop.
std::vector<double> graded_edges(double start, double first, double stop, double growth, double largest)
{
  std::vector<double> edges;
  const double sign = stop > start ? 1.0 : -1.0;
  double edge = start, size = first;
  while (sign * (stop - edge) > 1e-12)
  {
    edge += sign * std::min(size, sign * (stop - edge));
    edges.push_back(edge);
    size = std::min(size * growth, largest);
  }
  return edges;
}

/// In units of b with E* = 1: R, so that p0 = b E* / (2 R) = 1 / (2 R).
constexpr double sheet_radius = 1e4;

void check(const RoundedEndHalfSpaceSettings& s)
{
  if (!(s.radius_ratio > 0) || !std::isfinite(s.radius_ratio))
    throw InputError(fmt::format("rounded end by half-space: R / r_e must be positive, got {}", s.radius_ratio));
  if (!(s.held_length_over_half_width >= 10) || !std::isfinite(s.held_length_over_half_width))
    throw InputError(fmt::format("rounded end by half-space: the line contact must be held over at least 10 b, got "
                                 "{} b",
                                 s.held_length_over_half_width));
  const double layer = boundary_layer_over_half_width(s.radius_ratio);
  if (!(s.held_length_over_half_width >= 4 * layer))
    throw InputError(fmt::format("rounded end by half-space: the line contact held over {} b lies within 4 boundary "
                                 "layers of the fillet (s = 2 r_e b / (pi R) = {:.3g} b)",
                                 s.held_length_over_half_width, layer));
  const RoundedEndGridSettings& g = s.grid;
  if (!(g.finest_over_layer > 0 && g.finest_over_layer <= 1) || !(g.across_over_half_width > 0
                                                                  && g.across_over_half_width <= 0.5)
      || !(g.core_over_layer > 2) || !(g.extent_over_half_width >= 1.75))
    throw InputError(fmt::format("rounded end by half-space: the grid needs finest cells in (0, 1] s, cells across in "
                                 "(0, 0.5] b and a core above 2 s, got {}, {} and {}",
                                 g.finest_over_layer, g.across_over_half_width, g.core_over_layer));
}
} // namespace

double boundary_layer_over_half_width(double radius_ratio) { return 2 / (std::numbers::pi * radius_ratio); }

GradedHalfSpaceGrid rounded_end_grid(const RoundedEndHalfSpaceSettings& settings)
{
  check(settings);
  const double length = settings.held_length_over_half_width;
  const double layer = boundary_layer_over_half_width(settings.radius_ratio);
  const double small = settings.grid.finest_over_layer * layer;
  std::vector<double> centre;
  for (double x = -2 * layer; x < settings.grid.core_over_layer * layer + small / 2;
       x = -2 * layer + static_cast<double>(centre.size()) * small)
    centre.push_back(x);
  GradedHalfSpaceGrid grid;
  std::vector<double> before = graded_edges(centre.front(), small, -length, 1.15, length / 20);
  grid.x_edges_m.assign(before.rbegin(), before.rend());
  grid.x_edges_m.insert(grid.x_edges_m.end(), centre.begin(), centre.end());
  for (const double x : graded_edges(centre.back(), small, centre.back() + 2, 1.15, 0.125))
    grid.x_edges_m.push_back(x);
  const double across = settings.grid.across_over_half_width;
  const double extent = settings.grid.extent_over_half_width;
  for (double y = 0; y < extent - 0.5 + across / 2; y = across * static_cast<double>(grid.y_edges_m.size()))
    grid.y_edges_m.push_back(y);
  for (const double y : graded_edges(grid.y_edges_m.back(), across, extent, 1.3, 0.25))
    grid.y_edges_m.push_back(y);
  grid.mirror_x_m = -length;
  grid.mirror_y = true;
  return grid;
}

namespace
{
/// The end on the settings' grid; none where the contact reaches its side.
std::optional<RoundedEndHalfSpace> solve_on_grid(const RoundedEndHalfSpaceSettings& settings)
{
  const GradedHalfSpaceGrid grid = rounded_end_grid(settings);
  const double length = settings.held_length_over_half_width;
  const double edge_radius = sheet_radius / settings.radius_ratio;
  const std::size_t nx = grid.nx(), ny = grid.ny(), n = grid.size();
  std::vector<double> gap(n);
  std::vector<char> loaded(n);
  for (std::size_t i = 0; i < nx; ++i)
    for (std::size_t j = 0; j < ny; ++j)
    {
      const double x = grid.x(i), y = grid.y(j), past = std::max(0.0, x);
      gap[i * ny + j] = y * y / (2 * sheet_radius) + past * past / (2 * edge_radius);
      loaded[i * ny + j] = x < 0 && y < 1;
    }
  const double p0 = 1 / (2 * sheet_radius);
  // q L over y >= 0, q = pi b p0 / 2.
  const double force = std::numbers::pi * p0 / 2 * length / 2;
  const std::vector<double> influence = graded_half_space_influence(grid, 1.0, settings.threads);
  const GradedContactSolution solution = graded_half_space_contact(grid, influence, gap, force, std::move(loaded));
  const std::vector<double>& p = solution.pressure_pa;
  for (std::size_t i = 0; i < nx; ++i)
    if (p[i * ny + ny - 1] > 0)
      return std::nullopt;
  for (std::size_t j = 0; j < ny; ++j)
    if (p[(nx - 1) * ny + j] > 0)
      throw ComputationError("rounded end by half-space: the contact reaches the grid's end past the fillet");
  std::size_t far = 0, peak = 0;
  for (std::size_t i = 0; i < nx; ++i)
  {
    if (std::abs(grid.x(i) + length / 2) < std::abs(grid.x(far) + length / 2))
      far = i;
    if (p[i * ny] > p[peak * ny])
      peak = i;
  }
  RoundedEndHalfSpace r;
  r.cells = n;
  r.active_set_passes = solution.active_set_passes;
  r.layer_over_half_width = boundary_layer_over_half_width(settings.radius_ratio);
  r.far_over_p0 = p[far * ny] / p0;
  r.peak_over_p0 = p[peak * ny] / p0;
  r.peak_over_far = p[peak * ny] / p[far * ny];
  r.peak_x_over_layer = grid.x(peak) / r.layer_over_half_width;
  r.extent_over_half_width = settings.grid.extent_over_half_width;
  return r;
}
} // namespace

RoundedEndHalfSpace rounded_end_half_space(const RoundedEndHalfSpaceSettings& settings)
{
  RoundedEndHalfSpaceSettings s = settings;
  for (int widened = 0;; ++widened)
  {
    if (const std::optional<RoundedEndHalfSpace> r = solve_on_grid(s))
      return *r;
    if (widened == 3)
      throw ComputationError(fmt::format("rounded end by half-space: the contact reaches the grid's side, {:.3g} b "
                                         "across, after widening it three times",
                                         s.grid.extent_over_half_width));
    s.grid.extent_over_half_width *= 1.5;
    const std::size_t cells = rounded_end_grid(s).size();
    if (graded_half_space_bytes(cells) > s.max_bytes)
      throw ComputationError(fmt::format("rounded end by half-space: the contact reaches the grid's side; {:.3g} b "
                                         "across, {} cells would take {:.1f} GiB, more than the {:.1f} allowed",
                                         s.grid.extent_over_half_width, cells,
                                         graded_half_space_bytes(cells) / (1ull << 30), s.max_bytes / (1ull << 30)));
  }
}
} // namespace rollcheck::contact
