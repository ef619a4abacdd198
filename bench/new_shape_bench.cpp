// A new shape (issue 41, item 6): what a curve at a shape the table has no node for costs to
// make and to ask, against a query at a shape already made, in one binary. Every row's
// iteration is one shape, a different one each time (1,000 distinct shapes cycled over the
// tail's served range; Weibull tail side), and one query of all six orders at s = 1.3:
//   BM_GridCurveNewShape     Table::curve (the lookup grid built from the 12-node blend) + query
//   BM_DirectCurveNewShape   Table::direct_curve (the nodes answered directly) + query
//   BM_GridCurveQuery        the query alone on a curve already made (the repeated-shape cost)
//   BM_DirectCurveQuery      the query alone on a direct curve already made
//   build/bench/new_shape_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

#include "asperity/table.hpp"

namespace {
using namespace asperity;

const Table& table() {
  static const Table instance = Table::open_default();
  return instance;
}

// 1,000 shapes spread over the tail set's range, none a node (an irrational step)
const std::vector<double>& shapes() {
  static const std::vector<double> list = [] {
    const CurveSet* set = table().find(Distribution::weibull, Side::tail);
    std::vector<double> out;
    for (int i = 0; i < 1000; ++i) {
      const double u = std::fmod(0.5 + i * 0.6180339887498949, 1.0);
      out.push_back(set->shape_min * std::pow(set->shape_max / set->shape_min, u));
    }
    return out;
  }();
  return list;
}

constexpr double separation = 1.3;

template <bool direct>
void new_shape(benchmark::State& state) {
  std::size_t i = 0;
  double out[order_count];
  for (auto _ : state) {
    const double shape = shapes()[i++ % shapes().size()];
    const Curve curve = direct ? table().direct_curve(Distribution::weibull, Side::tail, shape)
                               : table().curve(Distribution::weibull, Side::tail, shape);
    curve.log_values(separation, out);
    benchmark::DoNotOptimize(out);
  }
}
void BM_GridCurveNewShape(benchmark::State& state) { new_shape<false>(state); }
void BM_DirectCurveNewShape(benchmark::State& state) { new_shape<true>(state); }
BENCHMARK(BM_GridCurveNewShape)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_DirectCurveNewShape)->Unit(benchmark::kMicrosecond);

template <bool direct>
void query(benchmark::State& state) {
  const double shape = shapes()[0];
  const Curve curve = direct ? table().direct_curve(Distribution::weibull, Side::tail, shape)
                             : table().curve(Distribution::weibull, Side::tail, shape);
  double out[order_count];
  double s = separation;
  for (auto _ : state) {
    curve.log_values(s, out);
    benchmark::DoNotOptimize(out);
    s = s == separation ? separation * (1 + 1e-9) : separation;  // not a constant the compiler sees
  }
}
void BM_GridCurveQuery(benchmark::State& state) { query<false>(state); }
void BM_DirectCurveQuery(benchmark::State& state) { query<true>(state); }
BENCHMARK(BM_GridCurveQuery)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_DirectCurveQuery)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
