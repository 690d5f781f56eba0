#include "fem/scenes/slab_contact.h"
#include "contact/hertz.h"
#include "fem/all_gather.h"
#include "fem/scenes/hertz_setup.h"
#include "fem/load_control.h"
#include "fem/nodal_fields.h"
#include "fem/petsc_session.h"
#include "fem/mesh/slab_mesh.h"
#include "core/error.h"
#include <algorithm>
#include <chrono>
#include <cmath>
#include <fmt/format.h>
#include <numeric>
#include <spdlog/spdlog.h>

namespace rollcheck::fem
{
namespace
{
constexpr double layer_growth = 1.5;
constexpr double section_growth = 0.5;
/// Largest ratio of b / R along the ruling that one section mesh serves: its
/// fine zone covers the largest with elements sized for the smallest.
constexpr double max_half_width_ratio = 2.0;
constexpr int layers_across_length = 24; ///< the largest layer is L / this

/// Layer boundaries in (0, 1]: thickness h_0 at x = 0 and h_L at x = L,
/// growing by layer_growth with the distance from the nearer end.
std::vector<double> layer_fractions(double length, double h_0, double h_L)
{
  const double largest = length / layers_across_length;
  std::vector<double> x;
  for (double t = 0; t < length;)
  {
    t += std::min({largest, h_0 + (layer_growth - 1) * t, h_L + (layer_growth - 1) * (length - t)});
    x.push_back(t);
  }
  std::vector<double> fractions;
  for (double t : x)
    fractions.push_back(t / x.back());
  return fractions;
}

/// Piecewise-linear interpolation through (xs, ys), continued linearly
/// beyond the first and last points; constant for a single point.
double interpolate(std::span<const double> xs, std::span<const double> ys, double x)
{
  if (xs.size() == 1)
    return ys[0];
  std::size_t i = std::upper_bound(xs.begin(), xs.end(), x) - xs.begin();
  i = std::clamp<std::size_t>(i, 1, xs.size() - 1);
  const double t = (x - xs[i - 1]) / (xs[i] - xs[i - 1]);
  return ys[i - 1] + t * (ys[i] - ys[i - 1]);
}

/// Smallest and largest b / R over the loaded slices (0, 0 if none).
std::array<double, 2> half_width_range(std::span<const SliceFem> slices)
{
  std::array<double, 2> range{INFINITY, 0.0};
  for (const SliceFem& s : slices)
    if (s.load.load_n_per_m > 0)
    {
      range[0] = std::min(range[0], s.hertz_half_width_m / s.load.radius_m);
      range[1] = std::max(range[1], s.hertz_half_width_m / s.load.radius_m);
    }
  return range[1] > 0 ? range : std::array<double, 2>{0.0, 0.0};
}
} // namespace

bool slab_feasible(std::span<const SliceFem> slices)
{
  const auto [smallest, largest] = half_width_range(slices);
  return largest > 0 && largest <= max_half_width_ratio * smallest;
}

namespace
{
/// The slices that carry load: their positions along the ruling and
/// approaches (the top's profile, and the force), their mean approach and
/// the range of b / R over them.
struct LoadedSlices
{
  std::vector<double> positions, approaches;
  double mean_approach = 0;
  std::array<double, 2> b_over_r{}; ///< smallest, largest
};

/// solve_slab's checks of the body and the slices (InputError), and the
/// loaded slices.
LoadedSlices loaded_slices(const SlabBody& body, std::span<const SliceFem> slices)
{
  for (double v : {body.length_m, body.start_radius_m, body.end_radius_m, body.force_n})
    if (!std::isfinite(v) || v <= 0)
      throw InputError(fmt::format("slab: length, radii and force must be positive and finite, got L = {} m, "
                                   "R = {} m, {} m, F = {} N",
                                   body.length_m, body.start_radius_m, body.end_radius_m, body.force_n));
  LoadedSlices loaded;
  for (const SliceFem& s : slices)
    if (s.load.load_n_per_m > 0)
    {
      loaded.positions.push_back(s.load.position_m);
      loaded.approaches.push_back(s.approach_m);
    }
  loaded.b_over_r = half_width_range(slices);
  if (loaded.positions.empty())
    throw InputError("slab: no slice carries load");
  if (!slab_feasible(slices))
    throw InputError(fmt::format("slab: the contact half-width over the radius varies {:.3g}-fold along the ruling "
                                 "(at most {}): one extruded section cannot resolve it",
                                 loaded.b_over_r[1] / loaded.b_over_r[0], max_half_width_ratio));
  if (!std::is_sorted(loaded.positions.begin(), loaded.positions.end()))
    throw InputError("slab: slices must be ordered along the ruling");
  loaded.mean_approach
      = std::accumulate(loaded.approaches.begin(), loaded.approaches.end(), 0.0) / loaded.approaches.size();
  return loaded;
}

/// The slab's geometry, its layers along the ruling as thick as the contact
/// elements `contact_element` (at unit radius) at each end (SlabFem's layers
/// and end_layer_m set).
SlabGeometry slab_geometry(const SlabBody& body, const LoadedSlices& loaded, double contact_element, SlabFem& result)
{
  SlabGeometry geometry;
  geometry.length_m = body.length_m;
  geometry.start_radius_m = body.start_radius_m;
  geometry.end_radius_m = body.end_radius_m;
  geometry.end_overhang_rad = body.end_overhang_rad;
  // End layers as thick as the contact elements at each end, but not thinner
  // than half those of the nearest loaded slice: a ruling may end near a
  // cone's apex (R -> 0), where its contact is unloaded.
  auto radius_at = [&](double x) {
    return body.start_radius_m + (body.end_radius_m - body.start_radius_m) * x / body.length_m;
  };
  const double h_0 = contact_element * std::max(body.start_radius_m, 0.5 * radius_at(loaded.positions.front())),
               h_L = contact_element * std::max(body.end_radius_m, 0.5 * radius_at(loaded.positions.back()));
  geometry.layer_fractions = layer_fractions(body.length_m, h_0, h_L);
  result.layers = static_cast<int>(geometry.layer_fractions.size());
  result.end_layer_m = std::min(h_0, h_L);
  return geometry;
}

/// The nodal pressure on the contact surface by node plane x = const, its
/// centre and the peaks at the ends and at the slices (into `result`).
void read_plane_pressures(MPI_Comm comm, const PenaltyContact& problem, const SlabGeometry& geometry,
                          std::span<const SliceFem> slices, SlabFem& result)
{
  std::vector<std::array<double, 2>> nodes; // (x, p)
  double moment = 0, total = 0;
  for (const SurfacePressureNode& node : gather_surface_pressure(comm, recover_contact_pressure(problem)))
  {
    const double along = slab_along(geometry, node.x.data());
    nodes.push_back({along, node.pressure_pa});
    moment += along * node.pressure_pa * node.weight;
    total += node.pressure_pa * node.weight;
  }
  if (!(total > 0))
    throw ComputationError("slab: no contact pressure on the surface after load control");
  result.centre_of_pressure = moment / total / geometry.length_m;
  std::sort(nodes.begin(), nodes.end());
  const double same_plane = 1e-9 * geometry.length_m;
  for (const auto& [x, pressure] : nodes)
  {
    if (result.plane_position_m.empty() || x - result.plane_position_m.back() > same_plane)
    {
      result.plane_position_m.push_back(x);
      result.plane_peak_pressure_pa.push_back(0);
    }
    result.plane_peak_pressure_pa.back() = std::max(result.plane_peak_pressure_pa.back(), pressure);
  }
  result.end_peak_pressure_pa = {result.plane_peak_pressure_pa.front(), result.plane_peak_pressure_pa.back()};
  for (const SliceFem& s : slices)
    result.slice_peak_pressure_pa.push_back(
        s.load.load_n_per_m > 0
            ? interpolate(result.plane_position_m, result.plane_peak_pressure_pa, s.load.position_m)
            : 0.0);
}
} // namespace

SlabFem solve_slab(MPI_Comm comm, const SlabBody& body, std::span<const SliceFem> slices,
                   const SlabSettings& settings)
{
  const auto start = std::chrono::steady_clock::now();
  const LoadedSlices loaded = loaded_slices(body, slices);
  const auto [smallest_b_over_r, largest_b_over_r] = loaded.b_over_r;
  ensure_petsc();

  SlabFem result;
  result.refine = settings.refine >= 0 ? settings.refine : default_refine(Model::solid, 1);
  // The section at unit radius, graded as the plane-strain scene.
  MeshGrading section
      = contact_grading(largest_b_over_r, contact_element_size(smallest_b_over_r, result.refine), 1.0);
  section.growth = section_growth;
  const SlabGeometry geometry = slab_geometry(body, loaded, section.contact_size_m, result);
  const SceneMesh scene = build_slab_mesh(comm, geometry, section);

  const double E_star
      = contact::effective_modulus(settings.youngs_modulus_pa, settings.poisson_ratio, settings.elastic_plane);
  const double body_modulus = E_star * (1 - settings.poisson_ratio * settings.poisson_ratio);
  const double kappa = settings.penalty_c * body_modulus / result.end_layer_m;
  PenaltyContact problem(scene, Model::solid, 1, body_modulus, settings.poisson_ratio, kappa, settings.petsc_options);
  result.dofs = problem.num_dofs();
  const double mean_approach = loaded.mean_approach;
  problem.set_approach_profile([&](const double* x) {
    return interpolate(loaded.positions, loaded.approaches, slab_along(geometry, x)) / mean_approach;
  });
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  if (rank == 0)
    spdlog::info("slab L = {:.4g} m, R = {:.4g}..{:.4g} m: {} layers, {} dofs, end layer {:.3g} m", body.length_m,
                 body.start_radius_m, body.end_radius_m, result.layers, result.dofs, result.end_layer_m);

  // Start as the slices do (fem/scenes/hertz_solve.cpp): their approach, the body
  // shifted by the height of its surface at the contact edge, exponent of a
  // line contact.
  const double b_over_r = 0.5 * (smallest_b_over_r + largest_b_over_r);
  const double mean_radius = 0.5 * (body.start_radius_m + body.end_radius_m);
  // The exponent depends on R / b alone.
  const double exponent = line_contact_approach(1.0, 1.0, b_over_r, 1.0).exponent;
  const LoadControlReport load
      = reach_force(problem, body.force_n, mean_approach, 0.5 * b_over_r * b_over_r * mean_radius, exponent, 1e-6,
                    world_rank() == 0 ? spdlog::level::info : spdlog::level::debug); // minutes: progress
  result.approach_factor = load.approach_m / mean_approach;
  result.newton_iterations = load.newton.newton_iterations;
  result.krylov_iterations = load.newton.krylov_iterations;
  result.force_n = problem.contact_force_n();
  read_plane_pressures(comm, problem, geometry, slices, result);
  result.wall_s = wall_seconds_since(comm, start);
  return result;
}
} // namespace rollcheck::fem
