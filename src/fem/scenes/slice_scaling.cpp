#include "fem/scenes/slice_scaling.h"
#include "contact/hertz.h"
#include "core/error.h"
#include "core/progress_beat.h"
#include "fem/all_gather.h"
#include "fem/petsc_session.h"
#include "fem/scenes/slice_table_store.h"
#include <chrono>
#include <cmath>
#include <fmt/format.h>

namespace rollcheck::fem
{
namespace
{
/// Nodes are solved at this radius; by the scaling any radius gives the same g.
constexpr double unit_radius_m = 1.0;
} // namespace

SliceScaling::SliceScaling(const SliceSettings& settings, int nodes_per_decade)
    : settings_(settings), nodes_per_decade_(nodes_per_decade),
      effective_modulus_pa_(
          contact::effective_modulus(settings.youngs_modulus_pa, settings.poisson_ratio, settings.elastic_plane))
{
  if (nodes_per_decade < 1)
    throw InputError(fmt::format("slice scaling: nodes per decade must be at least 1, got {}", nodes_per_decade));
}

void SliceScaling::cover(MPI_Comm comm, double lambda_min, double lambda_max)
{
  if (!(lambda_min > 0) || !(lambda_max >= lambda_min) || !std::isfinite(lambda_max))
    throw ComputationError(fmt::format("slice scaling: load ratio range [{}, {}] is not a positive interval",
                                       lambda_min, lambda_max));
  // Even bounds: the half table (stride 2) brackets the range too.
  int lo = static_cast<int>(std::floor(nodes_per_decade_ * std::log10(lambda_min)));
  int hi = static_cast<int>(std::ceil(nodes_per_decade_ * std::log10(lambda_max)));
  lo -= ((lo % 2) + 2) % 2;
  hi += ((hi % 2) + 2) % 2;
  std::vector<int> missing;
  std::vector<SliceLoad> loads;
  for (int k = lo; k <= hi; ++k)
    if (!nodes_.contains(k))
    {
      const double lambda = std::pow(10.0, static_cast<double>(k) / nodes_per_decade_);
      missing.push_back(k);
      loads.push_back({0.0, unit_radius_m, lambda * effective_modulus_pa_ * unit_radius_m});
    }
  if (missing.empty())
    return;
  // Nodes another process of the job has solved (slice_table_store.h): one
  // process alone reads them, so that the ranks of a run never disagree.
  ensure_petsc(); // MPI too
  int ranks = 1;
  MPI_Comm_size(comm, &ranks);
  std::optional<std::filesystem::path> folder = ranks == 1 ? slice_table_folder() : std::nullopt;
  std::vector<int> to_solve_k;
  std::vector<SliceLoad> to_solve;
  for (std::size_t i = 0; i < missing.size(); ++i)
    if (std::optional<SliceFem> stored = folder ? read_stored_slice(*folder, settings_, loads[i]) : std::nullopt)
    {
      add_node(missing[i], *stored);
      ++nodes_read_;
    }
    else
      to_solve_k.push_back(missing[i]), to_solve.push_back(loads[i]);
  if (!to_solve.empty())
  {
    int rank = 0;
    MPI_Comm_rank(comm, &rank);
    // A table of many nodes takes seconds to minutes: said, and repeated while it runs.
    ProgressBeat beat("FEM slice table", rank == 0, std::chrono::seconds(5));
    beat.step(fmt::format("solving {} node{} (load ratios {:.3g} to {:.3g})", to_solve.size(),
                          to_solve.size() == 1 ? "" : "s", to_solve.front().load_n_per_m / effective_modulus_pa_,
                          to_solve.back().load_n_per_m / effective_modulus_pa_));
    const auto start = std::chrono::steady_clock::now();
    const std::vector<SliceFem> solved = solve_slices(comm, to_solve, settings_);
    wall_s_ += wall_seconds_since(comm, start);
    for (std::size_t i = 0; i < to_solve.size(); ++i)
    {
      add_node(to_solve_k[i], solved[i]);
      if (folder && !store_slice(*folder, settings_, solved[i]))
        folder.reset(); // warned once
    }
  }
  index_nodes();
}

void SliceScaling::add_node(int k, const SliceFem& fem)
{
  nodes_[k] = {k, contact::load_ratio(fem.load.load_n_per_m, unit_radius_m, effective_modulus_pa_), fem,
               fem.peak_pressure_pa / fem.hertz_peak_pressure_pa,
               fem.refined_peak_pressure_pa / fem.hertz_peak_pressure_pa};
}

void SliceScaling::double_nodes()
{
  std::map<int, Node> doubled;
  for (auto& [k, node] : nodes_)
  {
    node.k = 2 * k;
    doubled.emplace(2 * k, std::move(node));
  }
  nodes_ = std::move(doubled);
  nodes_per_decade_ *= 2;
  index_nodes();
}

void SliceScaling::index_nodes()
{
  by_k_.clear();
  if (nodes_.empty())
    return;
  first_k_ = nodes_.begin()->first;
  by_k_.assign(static_cast<std::size_t>(nodes_.rbegin()->first - first_k_ + 1), nullptr);
  for (const auto& [k, node] : nodes_)
    by_k_[static_cast<std::size_t>(k - first_k_)] = &node;
}

double SliceScaling::ratio(double lambda, int stride, bool refined) const
{
  return interpolate(lambda, nodes_per_decade_ * std::log10(lambda), stride, refined);
}

std::array<double, 2> SliceScaling::ratios(double lambda) const
{
  const double position = nodes_per_decade_ * std::log10(lambda);
  return {interpolate(lambda, position, 1, false), interpolate(lambda, position, 2, false)};
}

double SliceScaling::interpolate(double lambda, double position, int stride, bool refined) const
{
  // The bracketing nodes of the stride's grid (multiples of the stride).
  const int lower = stride * static_cast<int>(std::floor(position / stride));
  const int upper = position == lower ? lower : lower + stride;
  const auto node = [&](int k) -> const Node* {
    const long i = static_cast<long>(k) - first_k_;
    return i >= 0 && i < static_cast<long>(by_k_.size()) ? by_k_[static_cast<std::size_t>(i)] : nullptr;
  };
  const Node *low = node(lower), *high = node(upper);
  if (!(lambda > 0) || !low || !high)
    throw ComputationError(fmt::format("slice scaling: load ratio {} lies outside the solved table", lambda));
  const double value_low = refined ? low->refined_ratio : low->ratio;
  const double value_high = refined ? high->refined_ratio : high->ratio;
  if (upper == lower)
    return value_low;
  const double t = (position - lower) / stride;
  return (1 - t) * value_low + t * value_high;
}
} // namespace rollcheck::fem
