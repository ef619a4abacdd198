// The batch ContactModel (ContactModel::at_separations, issue 32) against its baselines in one
// binary, per query (items_per_second counts queries): 4096 random separations a call, uniform
// over the curve's table range [table_min_separation, table_max_separation] (as bench_lookup's),
// physical ones sigma_s s for the model.
//   build/bench/bench_contact_model --benchmark_repetitions=5 --benchmark_enable_random_interleaving=true
//     --benchmark_report_aggregates_only=true      (one command line)
//
// Rows (KIND: weibull_tail_a2, weibull_bounded_a1.3, gaussian over the table's range, where 3 %
// of the tail's loads underflow (X_3/2 < 1e-308: the scalar path answers those, beyond the table
// with its series); weibull_tail_a2_contact over s in [-3, 6], every load a normal number; the
// load, X_3/2):
//   BM_DimensionlessBatch/KIND   Curve::value_batch(load) on the dimensionless separations: the batch lookup
//   BM_ModelBatch/KIND           ContactModel::at_separations(load) on the physical ones: the lookup, the
//                                datum's shift and the factor
//   BM_ModelScalarLoop/KIND      a loop of ContactModel::at_separation(d).load (every field computed)
// The goal (issue 32): BM_ModelBatch at the batch lookup's cost plus the factors.
#include <benchmark/benchmark.h>

#include <cmath>
#include <string>
#include <vector>

#include "asperity/contact_model.hpp"
#include "asperity/table.hpp"
#include "random_separations.hpp"

namespace {
using namespace asperity;

constexpr std::size_t query_count = 4096;

const Table& table() {
  static const Table instance = Table::open_default();
  return instance;
}

struct Kind {
  ContactModel model;
  std::vector<double> s, d;  // dimensionless and physical separations
};

// lo, hi: the separations' range (NaN: the curve's table range)
Kind make_kind(Distribution distribution, Side side, double shape, double lo = NAN, double hi = NAN) {
  RoughSurface surface;
  surface.distribution = distribution;
  surface.side = side;
  surface.shape = shape;
  surface.height_scale = 1e-6;
  surface.summit_radius = 1e-4;
  surface.summit_density = 1e10;
  surface.nominal_area = 1e-4;
  surface.contact_modulus = 1e11;
  Kind kind{ContactModel(table(), surface), {}, {}};
  const Curve& curve = kind.model.curve();
  kind.s = bench::uniform(std::isnan(lo) ? curve.table_min_separation() : lo,
                          std::isnan(hi) ? curve.table_max_separation() : hi, query_count, 7);
  for (double s : kind.s) kind.d.push_back(s * surface.height_scale);
  return kind;
}

const Kind& kind(const std::string& name) {
  static const Kind weibull = make_kind(Distribution::weibull, Side::tail, 2.0);
  static const Kind bounded = make_kind(Distribution::weibull, Side::bounded, 1.3);
  static const Kind gaussian = make_kind(Distribution::gaussian, Side::tail, 2.0);
  static const Kind in_contact = make_kind(Distribution::weibull, Side::tail, 2.0, -3.0, 6.0);
  if (name == "weibull_tail_a2_contact") return in_contact;
  return name == "weibull_tail_a2" ? weibull : name == "gaussian" ? gaussian : bounded;
}

void BM_DimensionlessBatch(benchmark::State& state, const std::string& name) {
  const Kind& k = kind(name);
  std::vector<double> out(query_count);
  for (auto _ : state) {
    k.model.curve().value_batch(orders::load, k.s.data(), out.data(), query_count);
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * query_count);
}

void BM_ModelBatch(benchmark::State& state, const std::string& name) {
  const Kind& k = kind(name);
  std::vector<double> out(query_count);
  for (auto _ : state) {
    k.model.at_separations(ContactQuantity::load, k.d.data(), out.data(), query_count);
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * query_count);
}

void BM_ModelScalarLoop(benchmark::State& state, const std::string& name) {
  const Kind& k = kind(name);
  std::vector<double> out(query_count);
  for (auto _ : state) {
    for (std::size_t i = 0; i < query_count; ++i) out[i] = k.model.at_separation(k.d[i]).load;
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * query_count);
}

#define ASPERITY_KINDS(bm)                                           \
  BENCHMARK_CAPTURE(bm, weibull_tail_a2, std::string("weibull_tail_a2")); \
  BENCHMARK_CAPTURE(bm, weibull_bounded_a1.3, std::string("weibull_bounded_a1.3")); \
  BENCHMARK_CAPTURE(bm, gaussian, std::string("gaussian")); \
  BENCHMARK_CAPTURE(bm, weibull_tail_a2_contact, std::string("weibull_tail_a2_contact"))
ASPERITY_KINDS(BM_DimensionlessBatch);
ASPERITY_KINDS(BM_ModelBatch);
ASPERITY_KINDS(BM_ModelScalarLoop);

}  // namespace

BENCHMARK_MAIN();
