// Scene tables against tolerance: generation time (tablegen --scene's work), table size,
// achieved error and lookup latency, for tables/scenes/tolerance-sweep.toml (a worn surface
// near first contact, a Gaussian lubrication film, a ground surface given by its load range).
// scripts/scenes-report.sh turns the JSON into docs/scenes.md's measured section.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "asperity/instruction_set.hpp"
#include "asperity/scene.hpp"
#include "asperity/scene_curves.hpp"
#include "asperity/generator/scene_table.hpp"

namespace {
using namespace asperity;

// tables/scenes/tolerance-sweep.toml at a given tolerance for every curve.
Scene sweep_scene(double tolerance) {
  Scene scene = read_scene_file(std::string(ASPERITY_SCENES_DIR) + "/tolerance-sweep.toml");
  for (SceneCurve& curve : scene.curves) curve.max_rel_error = tolerance;
  return scene;
}

struct Built {
  generator::SceneResult result;
  std::vector<SceneCurveView> views;
};

const Built& built(double tolerance) {
  static std::map<double, Built> cache;
  auto found = cache.find(tolerance);
  if (found == cache.end()) {
    Built entry;
    const Scene scene = sweep_scene(tolerance);
    entry.result = generator::generate_scene_table(scene, 2);
    Table table(entry.result.table);
    entry.views = serve_scene(table, scene);
    found = cache.emplace(tolerance, std::move(entry)).first;
  }
  return found->second;
}

void BM_SceneGenerate(benchmark::State& state) {
  const double tolerance = std::pow(10.0, -static_cast<double>(state.range(0)));
  const Scene scene = sweep_scene(tolerance);
  double kib = 0, worst = 0;
  int knots = 0;
  for (auto _ : state) {
    const generator::SceneResult result = generator::generate_scene_table(scene, 2);
    kib = worst = 0;
    knots = 0;
    for (const auto& report : result.curves) {
      kib += report.memory_bytes / 1024.0;
      worst = std::max(worst, report.achieved_error / report.curve.max_rel_error);
      knots += report.knots;
    }
  }
  state.counters["tolerance"] = tolerance;
  state.counters["memory_kib"] = kib;
  state.counters["knots"] = knots;
  state.counters["achieved_over_asked"] = worst;
}
BENCHMARK(BM_SceneGenerate)->DenseRange(4, 12, 2)->Unit(benchmark::kMillisecond)->Iterations(3);

// Lookup latency inside each curve's range (random separations, the first asked order).
void BM_SceneLookup(benchmark::State& state) {
  const double tolerance = std::pow(10.0, -static_cast<double>(state.range(0)));
  const SceneCurveView& view = built(tolerance).views[static_cast<std::size_t>(state.range(1))];
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> pick(view.separation_min, view.separation_max);
  std::vector<double> separations(4096);
  for (double& s : separations) s = pick(rng);
  const int order = view.spec.twice_orders.back();
  std::size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(view.curve.value(order, separations[i++ & 4095]));
  state.counters["tolerance"] = tolerance;
  state.counters["curve"] = static_cast<double>(state.range(1));
  state.counters["memory_kib"] = view.curve.memory_bytes() / 1024.0;
  state.SetLabel(view.spec.name);
}
BENCHMARK(BM_SceneLookup)->ArgsProduct({{4, 6, 8, 10, 12}, {0, 1, 2}});

}  // namespace

BENCHMARK_MAIN();
