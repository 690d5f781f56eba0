// Geometry benchmarks: building the 400-point oloid surface (Qhull hull plus
// checks), the mesh every oracle run starts from.
#include "geometry/body.h"
#include "geometry/mass_properties.h"
#include <benchmark/benchmark.h>

namespace
{
void BM_oloid_mesh_400(benchmark::State& state)
{
  rollcheck::geometry::BodySpec spec;
  spec.body = "oloid";
  spec.points = 400;
  for (auto _ : state)
    benchmark::DoNotOptimize(rollcheck::geometry::make_body(spec));
}
BENCHMARK(BM_oloid_mesh_400)->Unit(benchmark::kMillisecond);

void BM_paper_oloid_mesh_400(benchmark::State& state)
{
  rollcheck::geometry::BodySpec spec;
  spec.body = "paper-oloid";
  spec.points = 400;
  for (auto _ : state)
    benchmark::DoNotOptimize(rollcheck::geometry::make_body(spec));
}
BENCHMARK(BM_paper_oloid_mesh_400)->Unit(benchmark::kMillisecond);
} // namespace

BENCHMARK_MAIN();
