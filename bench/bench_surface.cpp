// The whole surface analysis against the map's size (docs/surfaces.md, "Speed"): the real
// 650 x 650 X3P and synthetic maps from 256^2 to 4096^2 and a 3 x 2,000,000 strip, each with
// the default ensemble (99 surrogate surfaces), no contact curves (they add scene tables, timed
// apart). Wall time and the process's CPU time over all threads (the ensemble runs on every
// core; on a shared machine the CPU time is the reproducible one): `bench_surface --benchmark_filter=...`.
#include <benchmark/benchmark.h>

#include <string>

#include "asperity/topography/analysis.hpp"
#include "asperity/topography/height_map_io.hpp"
#include "asperity/topography/synthetic.hpp"

namespace t = asperity::topography;

namespace {

t::AnalysisOptions defaults() {
  t::AnalysisOptions options;  // the command's defaults: 99 surrogates, all cores
  return options;
}

void BM_RealX3P(benchmark::State& state) {
  const t::HeightMap map = t::read_height_map(std::string(ASPERITY_SURFACES) + "/digitalsurf-650x650.x3p");
  for (auto _ : state) benchmark::DoNotOptimize(t::analyse_height_map(map, defaults()));
  state.SetLabel("650 x 650, 2482 summits");
}

void BM_Synthetic(benchmark::State& state) {
  const std::size_t n = static_cast<std::size_t>(state.range(0));
  t::HeightMap map = t::spectral_random_field(n, n, 1e-7, 1e-7, t::CorrelationFunction::exponential, 8, 1);
  for (double& h : map.heights) h *= 1e-8;
  std::size_t summits = 0;
  for (auto _ : state) {
    const t::SurfaceAnalysis a = t::analyse_height_map(map, defaults());
    summits = a.summits.list.size();
  }
  state.SetLabel(std::to_string(n) + "^2, " + std::to_string(summits) + " summits");
}

void BM_Strip(benchmark::State& state) {
  t::HeightMap map = t::spectral_random_field(2000000, 3, 1e-8, 1e-8, t::CorrelationFunction::exponential, 8, 3);
  for (double& h : map.heights) h *= 1e-8;
  for (auto _ : state) benchmark::DoNotOptimize(t::analyse_height_map(map, defaults()));
  state.SetLabel("3 x 2,000,000");
}

}  // namespace

BENCHMARK(BM_RealX3P)->Unit(benchmark::kSecond)->UseRealTime()->MeasureProcessCPUTime()->Iterations(3);
BENCHMARK(BM_Synthetic)->Arg(256)->Arg(512)->Arg(1024)->Arg(2048)->Unit(benchmark::kSecond)->UseRealTime()->MeasureProcessCPUTime()->Iterations(2);
BENCHMARK(BM_Synthetic)->Arg(4096)->Unit(benchmark::kSecond)->UseRealTime()->MeasureProcessCPUTime()->Iterations(1);
BENCHMARK(BM_Strip)->Unit(benchmark::kSecond)->UseRealTime()->MeasureProcessCPUTime()->Iterations(1);
BENCHMARK_MAIN();
