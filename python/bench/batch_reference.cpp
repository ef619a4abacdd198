// The C++ side of python/bench/bench_python.py: Curve::value_batch on the very separations the
// Python side uses (read from a file of float64), so that the two costs per element compare.
//   batch_reference SEPARATIONS.f64 [Google Benchmark flags]
#include <benchmark/benchmark.h>

#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "asperity/table.hpp"

namespace {

std::vector<double> read_doubles(const std::string& path) {
  std::ifstream file(path, std::ios::binary | std::ios::ate);
  if (!file) return {};
  std::vector<double> values(static_cast<std::size_t>(file.tellg()) / sizeof(double));
  file.seekg(0);
  file.read(reinterpret_cast<char*>(values.data()), static_cast<std::streamsize>(values.size() * sizeof(double)));
  return values;
}

void value_batch(benchmark::State& state, const asperity::Curve* curve, int twice_order,
                 const std::vector<double>* separations) {
  std::vector<double> out(separations->size());
  for (auto _ : state) {
    curve->value_batch(twice_order, separations->data(), out.data(), out.size());
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * out.size()));
}

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (argc != 3) {
    std::fprintf(stderr, "usage: batch_reference WEIBULL.f64 GAUSSIAN.f64 [benchmark flags]\n");
    return 2;
  }
  static const std::vector<double> weibull_separations = read_doubles(argv[1]);
  static const std::vector<double> gaussian_separations = read_doubles(argv[2]);
  if (weibull_separations.empty() || gaussian_separations.empty()) {
    std::fprintf(stderr, "batch_reference: cannot read the separations\n");
    return 2;
  }
  static const asperity::Table table = asperity::Table::open_default();
  static const asperity::Curve weibull = table.curve(asperity::Distribution::weibull, asperity::Side::tail, 2.0);
  static const asperity::Curve gaussian = table.curve(asperity::Distribution::gaussian, asperity::Side::tail, 2.0);
  benchmark::RegisterBenchmark("cxx_value_batch/weibull_a2_X3_2", value_batch, &weibull, 3, &weibull_separations)
      ->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("cxx_value_batch/gaussian_F5_2", value_batch, &gaussian, 5, &gaussian_separations)
      ->Unit(benchmark::kMillisecond);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
