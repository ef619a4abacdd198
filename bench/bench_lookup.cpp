// Lookup latency, in one binary and one run, against the alternatives a user has:
// Boost.Math's interpolators on the same knots, direct adaptive quadrature, and the one-line
// curve fit lubrication codes use for the Gaussian F_5/2. Random separations over the whole
// range (not a sweep), so branch prediction and caches see what a solver's inner loop sees.
//   build/bench/bench_lookup --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <boost/math/interpolators/cubic_hermite.hpp>
#include <boost/math/interpolators/makima.hpp>
#include <boost/math/interpolators/quintic_hermite.hpp>
#include <cmath>
#include <random>
#include <vector>

#include "random_separations.hpp"
#include "asperity/asperity.h"
#include "asperity/contact.hpp"
#include "asperity/contact_model.hpp"
#include "asperity/detail/fast_math.hpp"
#include "asperity/table.hpp"
#include "quadrature.hpp"

namespace {
using namespace asperity;

constexpr std::size_t query_count = 4096;  // a power of two: index with a mask

const Table& table() {
  static const Table instance = Table::open_default();
  return instance;
}

using bench::uniform;

// Weibull a = 2, tail side: separations across the whole tabulated range.
const Curve& weibull_curve() {
  static const Curve curve = table().curve(Distribution::weibull, Side::tail, 2.0);
  return curve;
}
const std::vector<double>& weibull_separations() {
  static const std::vector<double> values =
      uniform(weibull_curve().table_min_separation(), weibull_curve().table_max_separation(), query_count, 1);
  return values;
}

void BM_Scalar(benchmark::State& state) {
  const Curve& curve = weibull_curve();
  const int order = static_cast<int>(state.range(0));
  const std::vector<double>& separations = weibull_separations();
  std::size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(curve.value(order, separations[i++ & (query_count - 1)]));
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_Scalar)->DenseRange(0, 5)->ArgName("twice_order");

void BM_ContactAllFour(benchmark::State& state) {
  const Curve& curve = weibull_curve();
  const std::vector<double>& separations = weibull_separations();
  const Surface surface{1e4, 1e-4, 1e-6, 1e11};
  ContactState out;
  std::size_t i = 0;
  for (auto _ : state) {
    contact_at(curve, surface, separations[i++ & (query_count - 1)], out);
    benchmark::DoNotOptimize(out);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_ContactAllFour);

// The physical layer: forward (a separation) against inverse (a load): a tabulated inverse and
// one Newton step, against the same queries (the loads the separations give).
const ContactModel& physical_model() {
  static const ContactModel model(table(), [] {
    PhysicalSurface surface;
    surface.shape = 2.0;
    return surface;
  }());
  return model;
}
void BM_PhysicalForward(benchmark::State& state) {
  const ContactModel& model = physical_model();
  const std::vector<double>& separations = weibull_separations();
  const double sigma = model.surface().height_scale;
  std::size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(model.at_separation(sigma * separations[i++ & (query_count - 1)]));
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_PhysicalForward);

void BM_PhysicalInverseLoad(benchmark::State& state) {
  const ContactModel& model = physical_model();
  static const std::vector<double> loads = [&] {
    std::vector<double> out;
    const double sigma = model.surface().height_scale;
    for (double s : weibull_separations()) {
      const double load = model.at_separation(sigma * s).load;
      out.push_back(load > 1e-290 ? load : 1e-290);
    }
    return out;
  }();
  std::size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(model.at_load(loads[i++ & (query_count - 1)]));
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_PhysicalInverseLoad);

// The batch path, per instruction set (the same separations, order 3/2).
void BM_Batch(benchmark::State& state, InstructionSet isa) {
  if (!instruction_set_available(isa)) {
    state.SkipWithError("instruction set not available on this CPU");
    return;
  }
  const Curve& curve = weibull_curve();
  const std::vector<double>& separations = weibull_separations();
  std::vector<double> out(query_count);
  for (auto _ : state) {
    curve.value_batch(3, separations.data(), out.data(), query_count, isa);
    benchmark::DoNotOptimize(out.data());
  }
  state.SetItemsProcessed(state.iterations() * query_count);
}
BENCHMARK_CAPTURE(BM_Batch, generic, InstructionSet::generic);
BENCHMARK_CAPTURE(BM_Batch, avx2, InstructionSet::avx2);
BENCHMARK_CAPTURE(BM_Batch, avx512, InstructionSet::avx512);

void BM_BatchCApi(benchmark::State& state) {
  static asperity_table* handle = asperity_table_open(nullptr, nullptr, 0);
  static asperity_curve* curve = asperity_curve_open(handle, "weibull", "tail", 2.0, nullptr, 0);
  const std::vector<double>& separations = weibull_separations();
  std::vector<double> out(query_count);
  for (auto _ : state) {
    asperity_eval_batch(curve, 3, separations.data(), out.data(), query_count);
    benchmark::DoNotOptimize(out.data());
  }
  state.SetItemsProcessed(state.iterations() * query_count);
}
BENCHMARK(BM_BatchCApi);

// Our exp and log (detail/fast_math.hpp) against the library's, which stay the baseline.
const std::vector<double>& exponents() {
  static const std::vector<double> values = uniform(-700.0, 700.0, query_count, 4);
  return values;
}
template <double (*function)(double), bool positive_argument>
void run_elementary(benchmark::State& state) {
  const std::vector<double>& arguments = exponents();
  std::size_t i = 0;
  for (auto _ : state) {
    const double argument = arguments[i++ & (query_count - 1)];
    benchmark::DoNotOptimize(function(positive_argument ? argument + 701.0 : argument));
  }
  state.SetItemsProcessed(state.iterations());
}
double std_exp(double x) { return std::exp(x); }
double std_log(double x) { return std::log(x); }
double our_exp(double x) { return detail::fast_exp(x); }
double our_log(double x) { return detail::fast_log(x); }
BENCHMARK(run_elementary<std_exp, false>)->Name("BM_StdExp");
BENCHMARK(run_elementary<our_exp, false>)->Name("BM_FastExp");
BENCHMARK(run_elementary<std_log, true>)->Name("BM_StdLog");
BENCHMARK(run_elementary<our_log, true>)->Name("BM_FastLog");

// The far-tail segment of X_3/2 (a = 2) as knot arrays, for the Boost interpolators. Every
// method answers the same queries: u = ln(s^a), value = exp(H(u) - t).
struct Segment {
  std::vector<double> u, h, slope, curvature;
  double u0 = 0, step = 0;
  std::vector<double> queries;  // separations inside the segment
};
const Segment& far_tail_segment() {
  static const Segment segment = [] {
    const CurveSet& set = *table().find(Distribution::weibull, Side::tail);
    std::size_t shape = 0;
    while (set.shapes[shape] != 2.0) ++shape;
    const auto maps = SegmentMap::resolve(set.layout, set.distribution, set.side, 2.0);
    const std::size_t last = maps.size() - 1;
    int first = 0;
    for (std::size_t i = 0; i < last; ++i) first += set.layout[i].knots;
    const int knots = set.layout[last].knots;
    Segment out;
    out.u0 = maps[last].u_lo;
    out.step = (maps[last].u_hi - maps[last].u_lo) / (knots - 1);
    const double* data = &set.knots[shape * set.curve_stride() + (3 * set.total_knots() + first) * 3];
    for (int j = 0; j < knots; ++j) {
      out.u.push_back(out.u0 + out.step * j);
      out.h.push_back(data[3 * j]);
      out.slope.push_back(data[3 * j + 1]);
      out.curvature.push_back(data[3 * j + 2]);
    }
    out.queries = uniform(maps[last].s_lo, maps[last].s_hi, query_count, 2);
    return out;
  }();
  return segment;
}

template <class Interpolator>
void run_interpolator(benchmark::State& state, const Interpolator& interpolator) {
  const std::vector<double>& queries = far_tail_segment().queries;
  std::size_t i = 0;
  for (auto _ : state) {
    // the same map to the segment variable as the runtime's: u = a ln s, t = e^u
    const double s = queries[i++ & (query_count - 1)], u = 2.0 * std::log(s), t = std::exp(u);
    benchmark::DoNotOptimize(std::exp(interpolator(u) - t));
  }
  state.SetItemsProcessed(state.iterations());
}

void BM_OursSameSegment(benchmark::State& state) {
  const std::vector<double>& queries = far_tail_segment().queries;
  std::size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(weibull_curve().value(3, queries[i++ & (query_count - 1)]));
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_OursSameSegment);

void BM_BoostCardinalQuinticHermite(benchmark::State& state) {
  const Segment& segment = far_tail_segment();
  const boost::math::interpolators::cardinal_quintic_hermite<std::vector<double>> interpolator(
      std::vector<double>(segment.h), std::vector<double>(segment.slope), std::vector<double>(segment.curvature),
      segment.u0, segment.step);
  run_interpolator(state, interpolator);
}
BENCHMARK(BM_BoostCardinalQuinticHermite);

void BM_BoostQuinticHermite(benchmark::State& state) {
  const Segment& segment = far_tail_segment();
  const boost::math::interpolators::quintic_hermite<std::vector<double>> interpolator(
      std::vector<double>(segment.u), std::vector<double>(segment.h), std::vector<double>(segment.slope),
      std::vector<double>(segment.curvature));
  run_interpolator(state, interpolator);
}
BENCHMARK(BM_BoostQuinticHermite);

void BM_BoostCubicHermite(benchmark::State& state) {
  const Segment& segment = far_tail_segment();
  const boost::math::interpolators::cubic_hermite<std::vector<double>> interpolator(
      std::vector<double>(segment.u), std::vector<double>(segment.h), std::vector<double>(segment.slope));
  run_interpolator(state, interpolator);
}
BENCHMARK(BM_BoostCubicHermite);

void BM_BoostMakima(benchmark::State& state) {
  const Segment& segment = far_tail_segment();
  const boost::math::interpolators::makima<std::vector<double>> interpolator(std::vector<double>(segment.u),
                                                                             std::vector<double>(segment.h));
  run_interpolator(state, interpolator);
}
BENCHMARK(BM_BoostMakima);

// Direct evaluation: adaptive double-exponential quadrature (Boost exp_sinh, tolerance 1e-14).
void BM_DirectQuadrature(benchmark::State& state) {
  const tablegen::CurveId id{Distribution::weibull, Side::tail, 2.0};
  const std::vector<double>& separations = weibull_separations();
  std::size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(tablegen::log_integral(id, 1.5, separations[i++ & (query_count - 1)]));
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_DirectQuadrature);

// The same, in a batch (one call for 4096 queries): what a solver's inner loop would use.
void BM_BatchWeibullOrder3(benchmark::State& state) { BM_Batch(state, InstructionSet::automatic); }
BENCHMARK(BM_BatchWeibullOrder3);

// The Gaussian F_5/2: our lookup against the lubrication codes' fit 4.4086e-5 (4 - h)^6.804,
// over the fit's own domain h in [0, 4) (past 4 it answers 0 without computing anything).
const std::vector<double>& gaussian_separations() {
  static const std::vector<double> values = uniform(0.0, 4.0, query_count, 3);
  return values;
}

void BM_GaussianF52Ours(benchmark::State& state) {
  static const Curve curve = table().curve(Distribution::gaussian, Side::tail, 0);
  const std::vector<double>& separations = gaussian_separations();
  std::size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(curve.value(5, separations[i++ & (query_count - 1)]));
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_GaussianF52Ours);

void BM_GaussianF52OursBatch(benchmark::State& state) {
  static const Curve curve = table().curve(Distribution::gaussian, Side::tail, 0);
  const std::vector<double>& separations = gaussian_separations();
  std::vector<double> out(query_count);
  for (auto _ : state) {
    curve.value_batch(5, separations.data(), out.data(), query_count);
    benchmark::DoNotOptimize(out.data());
  }
  state.SetItemsProcessed(state.iterations() * query_count);
}
BENCHMARK(BM_GaussianF52OursBatch);

void BM_GaussianF52CurveFit(benchmark::State& state) {
  const std::vector<double>& separations = gaussian_separations();
  std::size_t i = 0;
  for (auto _ : state) {
    const double h = separations[i++ & (query_count - 1)];
    benchmark::DoNotOptimize(h < 4 ? 4.4086e-5 * std::pow(4 - h, 6.804) : 0.0);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_GaussianF52CurveFit);

}  // namespace

BENCHMARK_MAIN();
