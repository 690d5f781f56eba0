// Geometry benchmarks: building the 400-point oloid surfaces (Qhull hull plus
// checks), the mesh every oracle run starts from.
#include "geometry/body.h"
#include <benchmark/benchmark.h>

namespace
{
void BM_body_mesh_400(benchmark::State& state, const char* body)
{
  const rollcheck::geometry::BodySpec spec{.body = body, .points = 400};
  for (auto _ : state)
    benchmark::DoNotOptimize(rollcheck::geometry::make_body(spec));
}
BENCHMARK_CAPTURE(BM_body_mesh_400, oloid, "oloid")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_body_mesh_400, paper_oloid, "paper-oloid")->Unit(benchmark::kMillisecond);
} // namespace

BENCHMARK_MAIN();
