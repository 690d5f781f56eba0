#include "oracle/parametric_search.h"
#include "core/seconds_since.h"
#include "core/error.h"
#include "oracle/contact_distribution.h"
#include "oracle/parallel_for.h"
#include <algorithm>
#include <chrono>
#include <cmath>
#include <fmt/format.h>
#include <mutex>
#include <numeric>

namespace rollcheck::oracle
{
namespace
{
class ProgressReporter
{
public:
  ProgressReporter(const SearchSettings& o, std::string phase, std::size_t total)
      : callback_(o.progress), state_{std::move(phase), 0, total}
  {
    report();
  }
  void advance()
  {
    std::lock_guard lock(mutex_);
    ++state_.done;
    report();
  }

private:
  void report()
  {
    if (callback_)
      callback_(state_);
  }
  const std::function<void(const SearchProgress&)>& callback_;
  SearchProgress state_;
  std::mutex mutex_;
};

geometry::SurfaceMesh roller_mesh(const geometry::RollerGenome& g, const SearchSettings& o, int points)
{
  return geometry::two_circle_roller(g, geometry::RollerFamily::paper, o.radius_m, points);
}

/// Layer 1 for one genome; an InputError from meshing marks it invalid. The
/// mesh is kept for layer 2 (a few tens of kB each).
void screen(GenomeResult& r, geometry::SurfaceMesh& mesh, const SearchSettings& o, const ApproximateSettings& approx,
            int points)
{
  try
  {
    mesh = roller_mesh(r.genome, o, points);
  }
  catch (const InputError& e)
  {
    r.valid = false;
    r.error = e.what();
    return;
  }
  const RollingBody body = make_rolling_body(mesh, o.compat);
  const ContactDistribution cds = contact_distribution(approximate_oracle(body, approx, o.compat), body.face_areas, 0);
  r.valid = true;
  r.n_faces = mesh.faces.rows();
  r.area_m2 = body.mass.area_m2;
  r.approximate_cds = cds.summary.score;
  r.approximate_contact_cv = cds.summary.cv;
  r.approximate_max_contact_ratio = cds.summary.max_mean_ratio;
}

/// Layer 2 for one valid genome.
void revalidate(GenomeResult& r, const geometry::SurfaceMesh& mesh, const SearchSettings& o)
{
  const RollingBody body = make_rolling_body(mesh, o.compat);
  const Trajectory trajectory = rigid_body_oracle(body, o.rigid, o.compat);
  const ContactDistribution cds = contact_distribution(trajectory, body.face_areas, 0);
  r.validated = true;
  r.rigid_cds = cds.summary.score;
  r.rigid_contact_cv = cds.summary.cv;
  r.rigid_max_contact_ratio = cds.summary.max_mean_ratio;
  if (o.revalidation_metrics)
    r.metrics = o.revalidation_metrics(mesh, body, trajectory);
}

/// 1-based ranks by `key` ascending among `members`, ties in grid order.
template <typename Key>
void rank(std::vector<GenomeResult>& genomes, const std::vector<std::size_t>& members, Key key, long GenomeResult::*out)
{
  std::vector<std::size_t> order = members;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return key(genomes[a]) < key(genomes[b]); });
  for (std::size_t k = 0; k < order.size(); ++k)
    genomes[order[k]].*out = static_cast<long>(k + 1);
}
} // namespace

SearchResult parametric_search(const SearchSettings& options)
{
  const auto start = std::chrono::steady_clock::now();
  SearchResult result;
  result.options = options;
  SearchSettings& o = result.options;
  if (o.approximate_steps == 0)
    o.approximate_steps = reference_search_steps(o.grid);
  if (o.points < 3 || o.anchor_points < 3)
    throw InputError(fmt::format("search: points per circle must be at least 3, got {} (anchor {})", o.points,
                                 o.anchor_points));
  if (!std::isfinite(o.radius_m) || o.radius_m <= 0)
    throw InputError(fmt::format("search: radius must be positive, got {} m", o.radius_m));
  ApproximateSettings approx = o.approximate;
  approx.steps = o.approximate_steps;
  validate(approx);
  validate(o.rigid);
  result.threads = thread_count(o.threads);
  result.anchor_points = o.matched_resolution ? o.points : o.anchor_points;

  const std::vector<geometry::RollerGenome> grid = search_grid(o.grid);
  result.genomes.resize(grid.size());
  for (std::size_t i = 0; i < grid.size(); ++i)
  {
    result.genomes[i].genome = grid[i];
    result.genomes[i].is_anchor_genome = is_oloid_anchor(grid[i]);
  }
  result.anchor.genome = {90.0, 1.0, 1.0, 2};
  result.anchor.is_anchor_genome = true;

  // Layer 1: every genome and the anchor (the last item).
  std::vector<geometry::SurfaceMesh> meshes(grid.size() + 1);
  {
    ProgressReporter progress(o, "approximate", grid.size() + 1);
    parallel_for(grid.size() + 1, result.threads, [&](std::size_t i) {
      if (i < grid.size())
        screen(result.genomes[i], meshes[i], o, approx, o.points);
      else
        screen(result.anchor, meshes[i], o, approx, result.anchor_points);
      progress.advance();
    });
  }
  if (!result.anchor.valid)
    throw InputError("search: the anchor oloid could not be meshed: " + result.anchor.error);
  result.approximate_wall_s = seconds_since(start);

  std::vector<std::size_t> valid;
  for (std::size_t i = 0; i < grid.size(); ++i)
    if (result.genomes[i].valid)
      valid.push_back(i);
  rank(result.genomes, valid, [](const GenomeResult& r) { return r.approximate_cds; }, &GenomeResult::approximate_rank);

  // Layer 2: the best K by approximate CDS (or all) and the anchor.
  std::vector<std::size_t> chosen;
  for (std::size_t i : valid)
    if (o.validate_all || static_cast<std::size_t>(result.genomes[i].approximate_rank) <= o.validate_top)
      chosen.push_back(i);
  const auto rigid_start = std::chrono::steady_clock::now();
  {
    ProgressReporter progress(o, "rigid-body", chosen.size() + 1);
    parallel_for(chosen.size() + 1, result.threads, [&](std::size_t k) {
      if (k < chosen.size())
        revalidate(result.genomes[chosen[k]], meshes[chosen[k]], o);
      else
        revalidate(result.anchor, meshes.back(), o);
      progress.advance();
    });
  }
  rank(result.genomes, chosen, [](const GenomeResult& r) { return r.rigid_cds; }, &GenomeResult::rigid_rank);
  result.rigid_wall_s = seconds_since(rigid_start);
  result.wall_s = seconds_since(start);
  return result;
}
} // namespace rollcheck::oracle
