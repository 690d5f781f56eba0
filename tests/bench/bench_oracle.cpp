// Oracle and search benchmarks on the reference meshes, each printed with the
// reference code's wall time on this machine kind (tests/data/reference/
// README.md) and the speed-up: counters reference_s and speedup (reference
// time / our mean time per iteration).
//   rollcheck_bench --benchmark_filter='oracle|search'
#include "geometry/read_mesh.h"
#include "oracle/approximate_oracle.h"
#include "oracle/contact_distribution.h"
#include "oracle/parametric_search.h"
#include "oracle/rigid_body_oracle.h"
#include "oracle/rolling_body.h"
#include "study/body_scores/score_body.h"
#include <benchmark/benchmark.h>
#include <chrono>

namespace
{
using namespace rollcheck;

const geometry::SurfaceMesh& reference_oloid()
{
  static const geometry::SurfaceMesh mesh
      = geometry::read_mesh(std::string(ROLLCHECK_REFERENCE_MESH_DIR) + "/oloid_reference.obj");
  return mesh;
}

/// Times each iteration of `body` and sets the comparison counters (none
/// when the reference has no such step, reference_s = 0).
template <typename Body>
void timed(benchmark::State& state, double reference_s, Body body)
{
  double total = 0;
  for (auto _ : state)
  {
    const auto start = std::chrono::steady_clock::now();
    body();
    total += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  if (reference_s <= 0)
    return;
  const double mean = total / static_cast<double>(state.iterations());
  state.counters["reference_s"] = reference_s;
  state.counters["speedup"] = reference_s / mean;
}

const oracle::PaperCompat paper = oracle::PaperCompat::reference();

/// Body preparation: mass properties, centroids, vertex graph (not in the
/// oracle timings below, as trimesh caches the same on the mesh).
void BM_oracle_rolling_body_oloid(benchmark::State& state)
{
  timed(state, 0.0, [] { benchmark::DoNotOptimize(oracle::make_rolling_body(reference_oloid(), paper)); });
}
BENCHMARK(BM_oracle_rolling_body_oloid)->Unit(benchmark::kMillisecond);

/// One oracle's trajectory of the reference oloid and its CDS.
template <typename Oracle>
void oracle_with_cds(benchmark::State& state, double reference_s, Oracle run_oracle)
{
  const oracle::RollingBody body = oracle::make_rolling_body(reference_oloid(), paper);
  timed(state, reference_s, [&] {
    const oracle::Trajectory t = run_oracle(body);
    benchmark::DoNotOptimize(oracle::contact_distribution(t, body.face_areas, 50));
  });
}

/// Approximate oracle, 600 steps, and its CDS; the reference: 8-14 ms per body
/// (oloid: 0.0297 s in reference_outputs.json, the README's upper figure 14 ms used).
void BM_oracle_approximate_oloid(benchmark::State& state)
{
  oracle_with_cds(state, 0.014,
                  [](const oracle::RollingBody& body) { return oracle::approximate_oracle(body, {}, paper); });
}
BENCHMARK(BM_oracle_approximate_oloid)->Unit(benchmark::kMillisecond);

/// Rigid-body oracle, 3 runs x 5000 steps, 600 samples, and its CDS; the
/// reference: 1.42 s.
void BM_oracle_rigid_body_oloid(benchmark::State& state)
{
  oracle_with_cds(state, 1.42,
                  [](const oracle::RollingBody& body) { return oracle::rigid_body_oracle(body, {}, paper); });
}
BENCHMARK(BM_oracle_rigid_body_oloid)->Unit(benchmark::kMillisecond);

/// study::body_scores::score_body: the rigid-body oracle with every score (CDS, SDS, TDS,
/// WDS, FDS) from one trajectory, the mesh read and its curvatures included;
/// the reference runs one simulation per oracle: rigid 2.03 + Hertz 2.37 +
/// fatigue 2.33 + thermal 3.22 + wear 3.12 = 13.07 s (wall_s of
/// reference_outputs.json, oloid).
void BM_oracle_rigid_body_all_scores_oloid(benchmark::State& state)
{
  study::body_scores::ScoreBodySettings settings;
  settings.body.mesh_file = std::string(ROLLCHECK_REFERENCE_MESH_DIR) + "/oloid_reference.obj";
  settings.compat = paper;
  timed(state, 13.07, [&] { benchmark::DoNotOptimize(study::body_scores::score_body(settings)); });
}
BENCHMARK(BM_oracle_rigid_body_all_scores_oloid)->Unit(benchmark::kMillisecond);

/// The search with the revalidated genomes scored as `rollcheck search` does.
oracle::SearchSettings search_options(oracle::SearchGrid grid)
{
  oracle::SearchSettings o;
  o.grid = grid;
  o.compat = paper;
  study::body_scores::ScoreBodySettings scoring;
  scoring.compat = paper;
  scoring.convergence_every = 0;
  o.revalidation_metrics = study::body_scores::revalidation_scores(scoring);
  return o;
}

/// Quick grid (45 genomes + anchor): meshing, approximate screening, rigid-body
/// revalidation with every score of the top 5 and the anchor, on all cores.
/// The reference: 1.0 s for the screening alone.
void BM_search_quick_validate_top5(benchmark::State& state)
{
  const oracle::SearchSettings o = search_options(oracle::SearchGrid::quick);
  timed(state, 1.0, [&] { benchmark::DoNotOptimize(oracle::parametric_search(o)); });
}
BENCHMARK(BM_search_quick_validate_top5)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(5);

/// Standard grid (616 genomes + anchor) with rigid-body revalidation of every
/// genome, on all cores. The reference: 10.7 s for the screening alone (and
/// 616 x 1.4 s ~ 860 s if it revalidated every genome).
void BM_search_standard_validate_all(benchmark::State& state)
{
  oracle::SearchSettings o = search_options(oracle::SearchGrid::standard);
  o.validate_all = true;
  timed(state, 10.7, [&] { benchmark::DoNotOptimize(oracle::parametric_search(o)); });
}
BENCHMARK(BM_search_standard_validate_all)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);
} // namespace
