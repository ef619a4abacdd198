// Lookup speed, in one binary and one run, as ratios: every goal of issue 14 has its rows here.
// Random separations (4096, uniform over each curve's whole table range [table_min_separation,
// table_max_separation], not a sweep), so branch prediction and caches see what a solver's
// inner loop sees. Run on a quiet machine, interleaved, medians:
//   build/bench/bench_lookup --benchmark_repetitions=5 --benchmark_enable_random_interleaving=true
//     --benchmark_report_aggregates_only=true      (one command line)
//   build/bench/bench_lookup --check      (no timing: every copy and baseline below against Curve)
//
// Curve kinds (KIND): weibull_tail_a0.5, weibull_tail_a2, weibull_tail_a20, weibull_bounded_a0.5,
// weibull_bounded_a2, weibull_bounded_a20 (X_3/2, the load), gaussian (F_5/2 over the table's
// range) and gaussian_fit_domain (F_5/2 over h in [0, 4), where the lubrication codes' fit holds).
//
// Rows (names are kept from run to run; items_per_second counts queries, so every row is per query):
//   BM_ScalarKind/KIND               Curve::value, one order, one query a call
//   BM_Scalar/twice_order:N          the same, Weibull a = 2 tail, each order
//   BM_GaussianF52CurveFit           the one-line fit 4.4086e-5 (4 - h)^6.804 on gaussian_fit_domain's
//                                    separations (goal: BM_ScalarKind/gaussian_fit_domain <= 0.8x,
//                                    every Weibull BM_ScalarKind <= 1.0x)
//   BM_ContactAllFour                contact_at (count, area, load, stiffness, their ratio), Weibull
//                                    a = 2 tail, from a SurfaceScales (its factors on every query, in the kernel)
//   BM_ContactAllFourScales          the same from the factors computed once (contact_at_scales)
//                                    (goal, both rows: <= 1.5x BM_ScalarKind/weibull_tail_a2)
//   BM_ContactOrders                 Curve::contact_orders, the four orders' logs and values alone
//   BM_Batch/ISA                     Curve::value_batch per instruction set (generic, avx2, avx512),
//                                    Weibull a = 2 tail, 4096 queries a call (goal avx512 <= 3 ns,
//                                    avx2 >= 3x scalar)
//   BM_BatchGaussian/ISA             the same, gaussian (goal avx512 <= 2 ns)
//   BM_BatchKind/KIND                Curve::value_batch, the best instruction set, every kind
//   BM_BatchTail/ISA/RESULTS         Curve::value_batch, gaussian, where every X is subnormal
//                                    (subnormal_results: ln X in [-745, -709]) or normal (normal_results:
//                                    ln X in [-700, -664]): what subnormal results cost the vector exps
//   BM_BatchCApi                     asperity_eval_batch, Weibull a = 2 tail
//   BM_ScalarCApi                    asperity_eval, one query a call, the same curve and queries
//   BM_BatchFloor/PART/ISA           the batch's floor (issue 41, item 7; batch_floor.hpp), each part
//                                    alone over BM_Batch's 4096 doubles: exp (the runtime's vector exp on
//                                    the batch's own ln X), exp_libmvec (glibc's _ZGVdN4v_exp /
//                                    _ZGVeN8v_exp), quintic (the polynomial, coefficients in registers),
//                                    quintic_exp (both in one pass: the arithmetic every query needs);
//                                    .../normal_range: the exps on x in [-700, 700] (BM_StdExp's);
//                                    BM_BatchFloor/stream: memcpy of the separations to the output
//   BM_BatchThreads/min_time:1.000/real_time/threads:T   one Curve's batch path from T threads at once (throughput:
//                                    items_per_second; goal threads:2 >= 1.8x threads:1)
//   BM_CoreProbe/min_time:1.000/real_time/threads:T   pure floating-point work, no memory: whether this machine's
//                                    CPUs scale at all (two hyperthreads of one core would not)
//   BM_DirectQuadrature/KIND         Boost exp_sinh (tanh_sinh on the bounded side's finite range) at
//                                    1e-14 on the defining integrals, written for any shape
//                                    (direct_quadrature.hpp) (goal: >= 1000x BM_ScalarKind/KIND)
//   BM_HighwayBatch/TARGET/KIND      the batch loop written with Highway (highway_kernel.hpp), per
//                                    Highway target, and TARGET = dispatched (HWY_DYNAMIC_DISPATCH)
//   BM_IntrinsicsBatch/avx512/KIND   the batch loop written by hand in AVX-512 intrinsics
//                                    (intrinsics_kernel.hpp), against BM_Batch/avx512 and
//                                    BM_BatchGaussian/avx512 (the compiler's loop)
//   BM_Record/PATH/RECORD/KIND       issue 13: bench-local copies of the lookup (record_kernels.hpp)
//                                    with 48-byte records as the runtime holds them (48B), 48-byte
//                                    records from a 64-byte aligned base (48B_aligned64) and 64-byte
//                                    records, padded, aligned (64B_aligned64); PATH = scalar (inline,
//                                    as Curve::value) or batch_ISA (through value_batch's blocks). The
//                                    scalar 48B rows are the runtime's code (compare with
//                                    BM_ScalarKind); the batch 48B rows are the runtime's former
//                                    fused loop, the baseline of BM_Batch's three passes.
//   BM_ScalarHostIsa/ISA/EXP/KIND    the scalar lookup built for ISA (out of line, through a pointer),
//                                    with the library's exp (libm) or the runtime's inline one
//                                    (inline_exp): what a scalar kernel chosen at load time would give
//   BM_StdExp, BM_FastExp, BM_StdLog, BM_FastLog   the elementary functions alone (x in
//                                    [-700, 700]); BM_FastExpLanes: exp's masked form (for vector
//                                    loops) one call at a time; .../subnormal_results: x in [-745, -709]
//   BM_OursSameSegment, BM_Boost*    the far-tail segment of Weibull a = 2 X_3/2: ours against
//                                    Boost.Math's interpolators on the table's knots and map
//   BM_PhysicalForward, BM_PhysicalInverseLoad     ContactModel forward (separation) and inverse (load)
//   BM_ContactCurves*/nodes:N        a contact-curves table (a measured surface's exact contact,
//                                    contact_curves.hpp) of N nodes (a smooth law's, made here):
//                                    Pressure, AtSeparation (pressure, stiffness, area), Inverse
//                                    (separation at a pressure); against BM_Scalar/twice_order:3
//                                    and BM_PhysicalForward
// Counters: curve_bytes (Curve::memory_bytes, all six orders), grid_intervals (per order),
// underflow_fraction (quadrature: share of queries whose X underflows to 0 in double).
#include <benchmark/benchmark.h>

#include <boost/math/interpolators/cubic_hermite.hpp>
#include <boost/math/interpolators/makima.hpp>
#include <boost/math/interpolators/quintic_hermite.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "batch_floor.hpp"
#include "direct_quadrature.hpp"
#include "grid_copy.hpp"
#include "highway_kernel.hpp"
#include "intrinsics_kernel.hpp"
#include "random_separations.hpp"
#include "record_kernels.hpp"
#include "asperity/asperity.h"
#if ASPERITY_BENCH_LAW_CURVES
#include "asperity/generator/law_curves.hpp"
#endif
#include "asperity/contact.hpp"
#include "asperity/contact_curves.hpp"
#include "asperity/contact_model.hpp"
#include "asperity/detail/fast_math.hpp"
#include "asperity/detail/segment_map.hpp"
#include "asperity/table.hpp"

namespace {
using namespace asperity;
using bench::uniform;

constexpr std::size_t query_count = 4096;  // a power of two: index with a mask
constexpr int batch_block = 256;           // as the runtime's Curve::value_batch

const Table& table() {
  static const Table instance = Table::open_default();
  return instance;
}

// ---- the curve kinds ----

struct Kind {
  const char* name;
  Distribution distribution;
  Side side;
  double shape;
  int twice_order;
  bool fit_domain;  // separations on [0, 4) instead of the table's range
};
const Kind kinds[] = {
    {"weibull_tail_a0.5", Distribution::weibull, Side::tail, 0.5, 3, false},
    {"weibull_tail_a2", Distribution::weibull, Side::tail, 2.0, 3, false},
    {"weibull_tail_a20", Distribution::weibull, Side::tail, 20.0, 3, false},
    {"weibull_bounded_a0.5", Distribution::weibull, Side::bounded, 0.5, 3, false},
    {"weibull_bounded_a2", Distribution::weibull, Side::bounded, 2.0, 3, false},
    {"weibull_bounded_a20", Distribution::weibull, Side::bounded, 20.0, 3, false},
    {"gaussian", Distribution::gaussian, Side::tail, 0.0, 5, false},
    {"gaussian_fit_domain", Distribution::gaussian, Side::tail, 0.0, 5, true},
};
constexpr std::size_t kind_count = sizeof kinds / sizeof kinds[0];

// A block of doubles at a chosen alignment (std::vector gives malloc's 16 bytes).
struct AlignedDoubles {
  explicit AlignedDoubles(std::size_t count)
      : data(static_cast<double*>(std::aligned_alloc(64, (count * sizeof(double) + 63) / 64 * 64 + 64)), &std::free) {}
  std::unique_ptr<double, decltype(&std::free)> data;
};

// Issue 13's record layouts: 6 doubles an interval where the runtime's allocation puts them,
// 6 doubles from a 64-byte aligned base (half the records still straddle two cache lines), and
// 8 doubles (2 of padding) from a 64-byte aligned base (one line each).
enum class Records { runtime48, aligned48, aligned64 };
const char* to_string(Records records) {
  return records == Records::runtime48 ? "48B" : records == Records::aligned48 ? "48B_aligned64" : "64B_aligned64";
}

struct KindData {
  const Kind* kind;
  Curve curve;
  std::vector<double> separations;
  bench::GridCopy grid;  // the same grid, for the bench-local kernels
  // the kind's order as 48-byte records from a 64-byte aligned base, and as 64-byte records
  AlignedDoubles records48{0}, records64{0};
  const double* records(Records layout) const {
    return layout == Records::aligned48   ? records48.data.get()
           : layout == Records::aligned64 ? records64.data.get()
                                          : grid.order(kind->twice_order);
  }
};

KindData make_kind(const Kind& kind) {
  KindData data;
  data.kind = &kind;
  data.curve = table().curve(kind.distribution, kind.side, kind.shape);
  const unsigned seed = static_cast<unsigned>(&kind - kinds) + 1;
  data.separations = kind.fit_domain ? uniform(0.0, std::nextafter(4.0, 0.0), query_count, seed)
                                     : uniform(data.curve.table_min_separation(), data.curve.table_max_separation(),
                                               query_count, seed);
  data.grid = bench::copy_grid(table(), kind.distribution, kind.side, kind.shape);
  const std::size_t intervals = static_cast<std::size_t>(data.grid.grid.intervals);
  const double* order = data.grid.order(kind.twice_order);
  data.records48 = AlignedDoubles(intervals * 6);
  data.records64 = AlignedDoubles(intervals * 8);
  for (std::size_t i = 0; i < intervals; ++i)
    for (int k = 0; k < 8; ++k) {
      if (k < 6) data.records48.data.get()[i * 6 + k] = order[i * 6 + k];
      data.records64.data.get()[i * 8 + k] = k < 6 ? order[i * 6 + k] : 0.0;
    }
  return data;
}

const std::vector<KindData>& all_kinds() {
  static const std::vector<KindData> data = [] {
    std::vector<KindData> out;
    for (const Kind& kind : kinds) out.push_back(make_kind(kind));
    return out;
  }();
  return data;
}
const KindData& kind_data(const char* name) {
  for (const KindData& data : all_kinds())
    if (std::strcmp(data.kind->name, name) == 0) return data;
  std::fprintf(stderr, "no curve kind %s\n", name);
  std::abort();
}

void describe(benchmark::State& state, const KindData& data) {
  state.counters["curve_bytes"] = static_cast<double>(data.curve.memory_bytes());
  state.counters["grid_intervals"] = static_cast<double>(data.curve.grid_intervals());
}

// ---- the scalar lookup, per kind, and the fit ----

void BM_ScalarKind(benchmark::State& state, const char* name) {
  const KindData& data = kind_data(name);
  const Curve& curve = data.curve;
  const int order = data.kind->twice_order;
  const double* separations = data.separations.data();
  std::size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(curve.value(order, separations[i++ & (query_count - 1)]));
  state.SetItemsProcessed(state.iterations());
  describe(state, data);
}

void BM_Scalar(benchmark::State& state) {
  const KindData& data = kind_data("weibull_tail_a2");
  const int order = static_cast<int>(state.range(0));
  std::size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(data.curve.value(order, data.separations[i++ & (query_count - 1)]));
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_Scalar)->DenseRange(0, 5)->ArgName("twice_order");

// The lubrication codes' F_5/2 fit; past h = 4 it answers 0 without computing anything.
void BM_GaussianF52CurveFit(benchmark::State& state) {
  const std::vector<double>& separations = kind_data("gaussian_fit_domain").separations;
  std::size_t i = 0;
  for (auto _ : state) {
    const double h = separations[i++ & (query_count - 1)];
    benchmark::DoNotOptimize(h < 4 ? 4.4086e-5 * std::pow(4 - h, 6.804) : 0.0);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_GaussianF52CurveFit);

// ---- four quantities ----

void BM_ContactAllFour(benchmark::State& state) {
  const KindData& data = kind_data("weibull_tail_a2");
  const SurfaceScales surface{1e4, 1e-4, 1e-6, 1e11};
  ContactState out;
  std::size_t i = 0;
  for (auto _ : state) {
    contact_at(data.curve, surface, data.separations[i++ & (query_count - 1)], out);
    benchmark::DoNotOptimize(out);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_ContactAllFour);

void BM_ContactAllFourScales(benchmark::State& state) {
  const KindData& data = kind_data("weibull_tail_a2");
  const ContactScales scales = contact_scales(SurfaceScales{1e4, 1e-4, 1e-6, 1e11});
  ContactState out;
  std::size_t i = 0;
  for (auto _ : state) {
    contact_at_scales(data.curve, scales, data.separations[i++ & (query_count - 1)], out);
    benchmark::DoNotOptimize(out);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_ContactAllFourScales);

void BM_ContactOrders(benchmark::State& state) {
  const KindData& data = kind_data("weibull_tail_a2");
  double logs[4], values[4];
  std::size_t i = 0;
  for (auto _ : state) {
    data.curve.contact_orders(data.separations[i++ & (query_count - 1)], logs, values);
    benchmark::DoNotOptimize(values);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_ContactOrders);

// The physical layer: forward (a separation) against inverse (a load): a tabulated inverse and
// one Newton step, against the same queries (the loads the separations give).
const ContactModel& physical_model() {
  static const ContactModel model(table(), [] {
    RoughSurface surface;
    surface.shape = 2.0;
    surface.height_scale = 1e-6;
    surface.summit_radius = 1e-4;
    surface.summit_density = 1e10;
    surface.nominal_area = 1e-4;
    surface.contact_modulus = 1e11;
    return surface;
  }());
  return model;
}
void BM_PhysicalForward(benchmark::State& state) {
  const ContactModel& model = physical_model();
  const std::vector<double>& separations = kind_data("weibull_tail_a2").separations;
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
    for (double s : kind_data("weibull_tail_a2").separations) {
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

#if ASPERITY_BENCH_LAW_CURVES
// A law scene's curves (docs/contact-laws.md section 8): Kogut-Etsion on Gaussian summits, s in
// [0, 4], 1e-6 (tables/scenes/kogut-etsion.toml's), served by ContactCurves: forward at random
// separations over the range, and the inverse at the pressures they give; compare with
// BM_PhysicalForward / BM_PhysicalInverseLoad and BM_ContactAllFour.
const ContactCurves& law_curves() {
  static const ContactCurves curves = [] {
    SceneLaw law;
    law.law = kogut_etsion_law(1e-4, 1.13e11, 1e9, 0.3);
    law.distribution = Distribution::gaussian;
    law.height_scale = 1e-6;
    law.summit_radius = 1e-4;
    law.summit_density = 4e8;
    law.nominal_area = 1e-4;
    law.range_min = 0;
    law.range_max = 4;
    law.max_rel_error = 1e-6;
    return ContactCurves(generator::generate_law_curves(law).data);
  }();
  return curves;
}
const std::vector<double>& law_separations() {
  static const std::vector<double> out = [] {
    std::vector<double> u;
    std::uint64_t state = 88172645463325252ull;
    for (std::size_t i = 0; i < query_count; ++i) {
      state ^= state << 13, state ^= state >> 7, state ^= state << 17;
      u.push_back(4e-6 * static_cast<double>(state >> 11) * 0x1p-53);
    }
    return u;
  }();
  return out;
}
void BM_LawCurvesForward(benchmark::State& state) {
  const ContactCurves& curves = law_curves();
  const std::vector<double>& u = law_separations();
  std::size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(curves.at_separation(u[i++ & (query_count - 1)]));
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_LawCurvesForward);
void BM_LawCurvesInversePressure(benchmark::State& state) {
  const ContactCurves& curves = law_curves();
  static const std::vector<double> pressures = [&] {
    std::vector<double> out;
    for (double u : law_separations()) out.push_back(curves.pressure(u));
    return out;
  }();
  std::size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(curves.at_pressure(pressures[i++ & (query_count - 1)]));
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_LawCurvesInversePressure);

// An adhesive law's curves (tables/scenes/jkr.toml's: JKR on Gaussian summits, sigma_s = 2 nm,
// s in [-1, 4], 1e-6): the net of two ln-cubic parts forward at random separations over the
// range, and the inverse on the stable branch (up to the pull-off) at the pressures of random
// separations there; compare with BM_LawCurvesForward / BM_LawCurvesInversePressure.
const ContactCurves& adhesive_curves() {
  static const ContactCurves curves = [] {
    SceneLaw law;
    law.law = jkr_law(1e-4, 1.13e11, 0.5);
    law.distribution = Distribution::gaussian;
    law.height_scale = 2e-9;
    law.summit_radius = 1e-4;
    law.summit_density = 4e8;
    law.nominal_area = 1e-4;
    law.range_min = -1;
    law.range_max = 4;
    law.max_rel_error = 1e-6;
    return ContactCurves(generator::generate_law_curves(law).data);
  }();
  return curves;
}
// law_separations() (uniform in [0, 4 um]) mapped onto [from, to]
std::vector<double> separations_over(double from, double to) {
  std::vector<double> out;
  for (double u : law_separations()) out.push_back(from + (to - from) * u / 4e-6);
  return out;
}
void BM_LawCurvesAdhesiveForward(benchmark::State& state) {
  const ContactCurves& curves = adhesive_curves();
  static const std::vector<double> u = separations_over(curves.min_separation(), curves.max_separation());
  std::size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(curves.at_separation(u[i++ & (query_count - 1)]));
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_LawCurvesAdhesiveForward);
void BM_LawCurvesAdhesiveInversePressure(benchmark::State& state) {
  const ContactCurves& curves = adhesive_curves();
  static const std::vector<double> pressures = [&] {
    std::vector<double> out;
    for (double u : separations_over(curves.min_separation(), curves.stable_branch_end())) out.push_back(curves.pressure(u));
    return out;
  }();
  std::size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(curves.at_pressure(pressures[i++ & (query_count - 1)]));
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_LawCurvesAdhesiveInversePressure);
#endif

// ---- contact curves against separation (a measured surface as a table) ----

// N nodes of ln p(u) = -u/lambda - (u/mu)^3 over 0.1 to 1.1 um, k = -dp/du, a ~ p: the shape of
// an exact solve's curves, made here so that the benchmark needs no file.
const ContactCurves& contact_curves(int nodes) {
  static std::vector<std::unique_ptr<ContactCurves>> made(2);
  auto& slot = made[nodes == 33 ? 0 : 1];
  if (!slot) {
    ContactCurvesData data;
    data.source = "benchmark";
    const double lambda = 0.2e-6, mu = 0.5e-6;
    for (int i = 0; i < nodes; ++i) {
      const double u = 0.1e-6 + 1e-6 * i / (nodes - 1);
      const double p = 1e8 * std::exp(-u / lambda - std::pow(u / mu, 3));
      data.separation.push_back(u);
      data.pressure.push_back(p);
      data.stiffness.push_back(p * (1 / lambda + 3 / mu * std::pow(u / mu, 2)));
      data.area_fraction.push_back(0.5 * p / 1e8);
    }
    data.contact_modulus = 1e11;
    data.nominal_area = 1e-6;
    slot = std::make_unique<ContactCurves>(data);
  }
  return *slot;
}
const std::vector<double>& contact_curve_separations() {
  static const std::vector<double> values = bench::uniform(0.1e-6, 1.1e-6, query_count, 31);
  return values;
}

void BM_ContactCurvesPressure(benchmark::State& state) {
  const ContactCurves& curves = contact_curves(static_cast<int>(state.range(0)));
  const std::vector<double>& separations = contact_curve_separations();
  std::size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(curves.pressure(separations[i++ & (query_count - 1)]));
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_ContactCurvesPressure)->Arg(33)->Arg(257)->ArgName("nodes");

void BM_ContactCurvesAtSeparation(benchmark::State& state) {
  const ContactCurves& curves = contact_curves(static_cast<int>(state.range(0)));
  const std::vector<double>& separations = contact_curve_separations();
  std::size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(curves.at_separation(separations[i++ & (query_count - 1)]));
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_ContactCurvesAtSeparation)->Arg(33)->Arg(257)->ArgName("nodes");

void BM_ContactCurvesInverse(benchmark::State& state) {
  const ContactCurves& curves = contact_curves(static_cast<int>(state.range(0)));
  std::vector<double> pressures;
  for (double u : contact_curve_separations()) pressures.push_back(curves.pressure(u));
  std::size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(curves.separation_at_pressure(pressures[i++ & (query_count - 1)]));
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_ContactCurvesInverse)->Arg(33)->Arg(257)->ArgName("nodes");

// ---- the batch path ----

void run_batch(benchmark::State& state, const KindData& data, InstructionSet isa) {
  if (!instruction_set_available(isa)) {
    state.SkipWithError("instruction set not available on this CPU");
    return;
  }
  std::vector<double> out(query_count);
  for (auto _ : state) {
    data.curve.value_batch(data.kind->twice_order, data.separations.data(), out.data(), query_count, isa);
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * query_count);
  describe(state, data);
}
void BM_Batch(benchmark::State& state, InstructionSet isa) { run_batch(state, kind_data("weibull_tail_a2"), isa); }
BENCHMARK_CAPTURE(BM_Batch, generic, InstructionSet::generic);
BENCHMARK_CAPTURE(BM_Batch, avx2, InstructionSet::avx2);
BENCHMARK_CAPTURE(BM_Batch, avx512, InstructionSet::avx512);
void BM_BatchGaussian(benchmark::State& state, InstructionSet isa) { run_batch(state, kind_data("gaussian"), isa); }
BENCHMARK_CAPTURE(BM_BatchGaussian, generic, InstructionSet::generic);
BENCHMARK_CAPTURE(BM_BatchGaussian, avx2, InstructionSet::avx2);
BENCHMARK_CAPTURE(BM_BatchGaussian, avx512, InstructionSet::avx512);
void BM_BatchKind(benchmark::State& state, const char* name) {
  run_batch(state, kind_data(name), InstructionSet::automatic);
}

// The batch path where every result is subnormal (ln X in [-745, -709]) against results of the
// same tail in [-700, -664]: whether the vector exps pay for subnormal results (exp8 makes them
// with vscalefpd; a CPU that takes a microcode assist there would show it here). Gaussian F_5/2.
std::vector<double> separations_with_logs(const Curve& curve, int twice_order, double lower_log, double upper_log) {
  // ln X decreases with s past 0: the separation where it crosses `log`, by bisection
  const auto separation_at = [&](double log) {
    double low = 0, high = curve.table_max_separation();
    for (int step = 0; step < 200; ++step) {
      const double middle = 0.5 * (low + high);
      (curve.log_value(twice_order, middle) > log ? low : high) = middle;
    }
    return 0.5 * (low + high);
  };
  return uniform(separation_at(upper_log), separation_at(lower_log), query_count, 11);
}
void BM_BatchTail(benchmark::State& state, InstructionSet isa, bool subnormal_results) {
  if (!instruction_set_available(isa)) {
    state.SkipWithError("instruction set not available on this CPU");
    return;
  }
  const KindData& data = kind_data("gaussian");
  const std::vector<double> separations = subnormal_results
                                              ? separations_with_logs(data.curve, data.kind->twice_order, -745, -709)
                                              : separations_with_logs(data.curve, data.kind->twice_order, -700, -664);
  std::vector<double> out(query_count);
  for (auto _ : state) {
    data.curve.value_batch(data.kind->twice_order, separations.data(), out.data(), query_count, isa);
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * query_count);
}
BENCHMARK_CAPTURE(BM_BatchTail, avx2/normal_results, InstructionSet::avx2, false);
BENCHMARK_CAPTURE(BM_BatchTail, avx2/subnormal_results, InstructionSet::avx2, true);
BENCHMARK_CAPTURE(BM_BatchTail, avx512/normal_results, InstructionSet::avx512, false);
BENCHMARK_CAPTURE(BM_BatchTail, avx512/subnormal_results, InstructionSet::avx512, true);

void BM_BatchCApi(benchmark::State& state) {
  static asperity_table* handle = asperity_table_open(nullptr, nullptr, 0);
  static asperity_curve* curve = asperity_curve_open(handle, "weibull", "tail", 2.0, nullptr, 0);
  const std::vector<double>& separations = kind_data("weibull_tail_a2").separations;
  std::vector<double> out(query_count);
  for (auto _ : state) {
    asperity_eval_batch(curve, 3, separations.data(), out.data(), query_count);
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * query_count);
}
BENCHMARK(BM_BatchCApi);
// the scalar lookup through the C API (asperity_eval), BM_BatchCApi's reference
void BM_ScalarCApi(benchmark::State& state) {
  static asperity_table* handle = asperity_table_open(nullptr, nullptr, 0);
  static asperity_curve* curve = asperity_curve_open(handle, "weibull", "tail", 2.0, nullptr, 0);
  const double* separations = kind_data("weibull_tail_a2").separations.data();
  std::size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(asperity_eval(curve, 3, separations[i++ & (query_count - 1)]));
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_ScalarCApi);

const std::vector<double>& exponents();

// ---- the batch path's floor (batch_floor.hpp): its parts alone, over BM_Batch's 4096 queries ----

// ln X of BM_Batch's queries (Weibull a = 2 tail, X_3/2): the exps' inputs as the batch has them
// (3% of them below ln DBL_MIN)
const std::vector<double>& batch_logs() {
  static const std::vector<double> logs = [] {
    const KindData& data = kind_data("weibull_tail_a2");
    std::vector<double> out(query_count);
    data.curve.log_value_batch(data.kind->twice_order, data.separations.data(), out.data(), query_count);
    return out;
  }();
  return logs;
}
const bench::BatchFloorKernels* floor_kernels(benchmark::State& state, InstructionSet isa) {
  const bench::BatchFloorKernels& kernels = isa == InstructionSet::avx512 ? bench::batch_floor_avx512
                                                                          : bench::batch_floor_avx2;
  if (!kernels.exp || !instruction_set_available(isa)) {
    state.SkipWithError("instruction set not available");
    return nullptr;
  }
  return &kernels;
}
template <class Run>
void run_floor(benchmark::State& state, Run run) {
  std::vector<double> out(query_count);
  for (auto _ : state) {
    run(out.data());
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * query_count);
}
// inputs: the batch's ln X, or x in [-700, 700] (exponents(): every result normal, where
// libmvec takes no per-lane fallback)
void BM_BatchFloorExp(benchmark::State& state, InstructionSet isa, bool library, bool normal_range) {
  const bench::BatchFloorKernels* kernels = floor_kernels(state, isa);
  if (!kernels) return;
  const double* logs = normal_range ? exponents().data() : batch_logs().data();
  const auto exp = library ? kernels->libmvec_exp : kernels->exp;
  run_floor(state, [&](double* out) { exp(logs, out, query_count); });
}
BENCHMARK_CAPTURE(BM_BatchFloorExp, avx2, InstructionSet::avx2, false, false)->Name("BM_BatchFloor/exp/avx2");
BENCHMARK_CAPTURE(BM_BatchFloorExp, avx512, InstructionSet::avx512, false, false)->Name("BM_BatchFloor/exp/avx512");
BENCHMARK_CAPTURE(BM_BatchFloorExp, avx2, InstructionSet::avx2, true, false)->Name("BM_BatchFloor/exp_libmvec/avx2");
BENCHMARK_CAPTURE(BM_BatchFloorExp, avx512, InstructionSet::avx512, true, false)
    ->Name("BM_BatchFloor/exp_libmvec/avx512");
BENCHMARK_CAPTURE(BM_BatchFloorExp, avx2, InstructionSet::avx2, false, true)
    ->Name("BM_BatchFloor/exp/avx2/normal_range");
BENCHMARK_CAPTURE(BM_BatchFloorExp, avx512, InstructionSet::avx512, false, true)
    ->Name("BM_BatchFloor/exp/avx512/normal_range");
BENCHMARK_CAPTURE(BM_BatchFloorExp, avx2, InstructionSet::avx2, true, true)
    ->Name("BM_BatchFloor/exp_libmvec/avx2/normal_range");
BENCHMARK_CAPTURE(BM_BatchFloorExp, avx512, InstructionSet::avx512, true, true)
    ->Name("BM_BatchFloor/exp_libmvec/avx512/normal_range");
// the quintic alone and with its exp: one interval's coefficients in registers, y in [-0.5, 0.5)
// as the grid's positions are
void BM_BatchFloorQuintic(benchmark::State& state, InstructionSet isa, bool with_exp) {
  const bench::BatchFloorKernels* kernels = floor_kernels(state, isa);
  if (!kernels) return;
  static const std::vector<double> positions = uniform(-0.5, 0.5, query_count, 12);
  const KindData& data = kind_data("weibull_tail_a2");
  const double* record = data.grid.order(data.kind->twice_order) + 100 * detail::fast_stride;
  const auto quintic = with_exp ? kernels->quintic_exp : kernels->quintic;
  run_floor(state, [&](double* out) { quintic(record, positions.data(), out, query_count); });
}
BENCHMARK_CAPTURE(BM_BatchFloorQuintic, avx2, InstructionSet::avx2, false)->Name("BM_BatchFloor/quintic/avx2");
BENCHMARK_CAPTURE(BM_BatchFloorQuintic, avx512, InstructionSet::avx512, false)->Name("BM_BatchFloor/quintic/avx512");
BENCHMARK_CAPTURE(BM_BatchFloorQuintic, avx2, InstructionSet::avx2, true)->Name("BM_BatchFloor/quintic_exp/avx2");
BENCHMARK_CAPTURE(BM_BatchFloorQuintic, avx512, InstructionSet::avx512, true)
    ->Name("BM_BatchFloor/quintic_exp/avx512");
// the memory traffic alone: the separations read, the values written (memcpy)
void BM_BatchFloorStream(benchmark::State& state) {
  const double* separations = kind_data("weibull_tail_a2").separations.data();
  run_floor(state, [&](double* out) { std::memcpy(out, separations, query_count * sizeof(double)); });
}
BENCHMARK(BM_BatchFloorStream)->Name("BM_BatchFloor/stream");

// Threads share the curve (and the queries); each writes its own output.
void BM_BatchThreads(benchmark::State& state) {
  const KindData& data = kind_data("weibull_tail_a2");
  std::vector<double> out(query_count);
  for (auto _ : state) {
    data.curve.value_batch(data.kind->twice_order, data.separations.data(), out.data(), query_count);
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * query_count);
}
// a second per repetition (the command line's default is shorter): two threads on a shared
// machine meet the other tenants' bursts, which a longer window averages
BENCHMARK(BM_BatchThreads)->Threads(1)->Threads(2)->UseRealTime()->MinTime(1.0);

// 24 independent multiply-add chains in registers: limited by the floating-point ports, so two
// threads on two real cores do twice the work of one, and two hyperthreads of one core do not.
void BM_CoreProbe(benchmark::State& state) {
  double accumulator[24];
  for (int k = 0; k < 24; ++k) accumulator[k] = 1.0 + k;
  for (auto _ : state) {
    for (int round = 0; round < 64; ++round)
      for (double& value : accumulator) value = value * 0.9999999 + 1e-7;
    benchmark::DoNotOptimize(accumulator);
  }
  state.SetItemsProcessed(state.iterations() * 64 * 24);
}
BENCHMARK(BM_CoreProbe)->Threads(1)->Threads(2)->UseRealTime()->MinTime(1.0);

// ---- direct quadrature, per kind ----

void BM_DirectQuadrature(benchmark::State& state, const char* name) {
  const KindData& data = kind_data(name);
  const bench::DirectQuadrature quadrature(data.kind->distribution, data.kind->side, data.kind->shape,
                                           data.kind->twice_order);
  std::size_t i = 0, underflow = 0, count = 0;
  for (auto _ : state) {
    const double value = quadrature(data.separations[i++ & (query_count - 1)]);
    benchmark::DoNotOptimize(value);
    underflow += value == 0;
    ++count;
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["underflow_fraction"] = count ? static_cast<double>(underflow) / count : 0.0;
}

// ---- bench-local kernels: Highway and the record layouts, through Curve::value_batch's blocks ----

// What Curve::value_batch does around its kernel: blocks of 256 copied in, queries off the
// grid answered one by one (here by the Curve itself).
void batch_through(bench::BlockLookup block, const KindData& data, const double* coefficients, const double* separations,
                   double* out, std::size_t count) {
  double block_separations[batch_block];
  for (std::size_t start = 0; start < count; start += batch_block) {
    const int size = static_cast<int>(std::min<std::size_t>(batch_block, count - start));
    for (int j = 0; j < size; ++j) block_separations[j] = separations[start + j];
    if (block(data.grid.grid, coefficients, block_separations, out + start, size) == 0) continue;
    detail::FastPosition unused;
    for (int j = 0; j < size; ++j)
      if (!detail::fast_position(data.grid.grid, block_separations[j], unused))
        out[start + j] = data.curve.value(data.kind->twice_order, block_separations[j]);
  }
}

void run_block_lookup(benchmark::State& state, const KindData& data, bench::BlockLookup block,
                      const double* coefficients) {
  std::vector<double> out(query_count);
  for (auto _ : state) {
    batch_through(block, data, coefficients, data.separations.data(), out.data(), query_count);
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * query_count);
}

void BM_HighwayBatch(benchmark::State& state, const char* target, const char* name) {
  const KindData& data = kind_data(name);
  bench::BlockLookup block = bench::highway_block_dispatched;
  if (std::strcmp(target, "dispatched") != 0)
    for (const bench::HighwayTarget& candidate : bench::highway_targets())
      if (std::strcmp(candidate.name, target) == 0) {
        if (!candidate.available) {
          state.SkipWithError("Highway target not available on this CPU");
          return;
        }
        block = candidate.block;
      }
  run_block_lookup(state, data, block, data.grid.order(data.kind->twice_order));
}

void BM_IntrinsicsBatch(benchmark::State& state, const char* name) {
  if (!bench::intrinsics_block_avx512 || !instruction_set_available(InstructionSet::avx512)) {
    state.SkipWithError("no AVX-512 here");
    return;
  }
  const KindData& data = kind_data(name);
  run_block_lookup(state, data, bench::intrinsics_block_avx512, data.grid.order(data.kind->twice_order));
}

struct IsaKernels {
  const char* name;
  InstructionSet isa;
  const bench::RecordKernels* kernels;
};
const IsaKernels isa_kernels[] = {{"generic", InstructionSet::generic, &bench::record_kernels_generic},
                                  {"avx2", InstructionSet::avx2, &bench::record_kernels_avx2},
                                  {"avx512", InstructionSet::avx512, &bench::record_kernels_avx512}};

// isa: the batch loop built for it, or null: the scalar lookup
void BM_Record(benchmark::State& state, const IsaKernels* isa, Records layout, const char* name) {
  const KindData& data = kind_data(name);
  const double* coefficients = data.records(layout);
  const bool wide = layout == Records::aligned64;
  if (isa && !instruction_set_available(isa->isa)) {
    state.SkipWithError("instruction set not available on this CPU");
    return;
  }
  if (isa) {
    run_block_lookup(state, data, wide ? isa->kernels->block8 : isa->kernels->block6, coefficients);
  } else {
    const detail::FastGrid& grid = data.grid.grid;
    std::size_t i = 0;
    if (wide)
      for (auto _ : state)
        benchmark::DoNotOptimize(bench::record_lookup<8>(grid, coefficients, data.separations[i++ & (query_count - 1)]));
    else
      for (auto _ : state)
        benchmark::DoNotOptimize(bench::record_lookup<6>(grid, coefficients, data.separations[i++ & (query_count - 1)]));
    state.SetItemsProcessed(state.iterations());
  }
  state.counters["base_mod_64"] = static_cast<double>(reinterpret_cast<std::uintptr_t>(coefficients) % 64);
}

void BM_ScalarHostIsa(benchmark::State& state, const IsaKernels* isa, bool inline_exp, const char* name) {
  if (!instruction_set_available(isa->isa)) {
    state.SkipWithError("instruction set not available on this CPU");
    return;
  }
  const KindData& data = kind_data(name);
  const bench::ScalarLookup lookup = inline_exp ? isa->kernels->scalar6_inline_exp : isa->kernels->scalar6;
  const double* coefficients = data.grid.order(data.kind->twice_order);
  std::size_t i = 0;
  for (auto _ : state)
    benchmark::DoNotOptimize(lookup(data.grid.grid, coefficients, data.separations[i++ & (query_count - 1)]));
  state.SetItemsProcessed(state.iterations());
}

// ---- elementary functions: ours (detail/fast_math.hpp) against the library's ----

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
double our_exp_lanes(double x) { return detail::fast_exp_lanes(x); }
double our_log(double x) { return detail::fast_log(x); }
BENCHMARK(run_elementary<std_exp, false>)->Name("BM_StdExp");
BENCHMARK(run_elementary<our_exp, false>)->Name("BM_FastExp");
BENCHMARK(run_elementary<our_exp_lanes, false>)->Name("BM_FastExpLanes");

// exp where its result is subnormal (x in [-745, -709]): the tails' X < 1e-308
template <double (*function)(double)>
void run_exp_below_normal(benchmark::State& state) {
  static const std::vector<double> arguments = uniform(-745.0, -709.0, query_count, 5);
  std::size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(function(arguments[i++ & (query_count - 1)]));
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(run_exp_below_normal<std_exp>)->Name("BM_StdExp/subnormal_results");
BENCHMARK(run_exp_below_normal<our_exp>)->Name("BM_FastExp/subnormal_results");
BENCHMARK(run_elementary<std_log, true>)->Name("BM_StdLog");
BENCHMARK(run_elementary<our_log, true>)->Name("BM_FastLog");

// ---- one segment: ours against Boost.Math's interpolators ----

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
    const auto maps = detail::SegmentMap::resolve(set.layout, set.distribution, set.side, 2.0);
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
    // the table's map to the segment variable: u = a ln s, t = e^u
    const double s = queries[i++ & (query_count - 1)], u = 2.0 * std::log(s), t = std::exp(u);
    benchmark::DoNotOptimize(std::exp(interpolator(u) - t));
  }
  state.SetItemsProcessed(state.iterations());
}

void BM_OursSameSegment(benchmark::State& state) {
  const std::vector<double>& queries = far_tail_segment().queries;
  const Curve& curve = kind_data("weibull_tail_a2").curve;
  std::size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(curve.value(3, queries[i++ & (query_count - 1)]));
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

// ---- registration of the per-kind rows ----

const char* const record_kinds[] = {"weibull_tail_a0.5", "weibull_tail_a2", "gaussian"};
const char* const highway_kinds[] = {"weibull_tail_a2", "gaussian"};
const char* const host_isa_kinds[] = {"weibull_tail_a2", "gaussian_fit_domain"};

void register_kind_rows() {
  for (const Kind& kind : kinds) {
    benchmark::RegisterBenchmark((std::string("BM_ScalarKind/") + kind.name).c_str(), BM_ScalarKind, kind.name);
    benchmark::RegisterBenchmark((std::string("BM_BatchKind/") + kind.name).c_str(), BM_BatchKind, kind.name);
    benchmark::RegisterBenchmark((std::string("BM_DirectQuadrature/") + kind.name).c_str(), BM_DirectQuadrature,
                                 kind.name);
  }
  for (const char* kind : highway_kinds) {
    for (const bench::HighwayTarget& target : bench::highway_targets())
      benchmark::RegisterBenchmark((std::string("BM_HighwayBatch/") + target.name + "/" + kind).c_str(),
                                   BM_HighwayBatch, target.name, kind);
    benchmark::RegisterBenchmark((std::string("BM_HighwayBatch/dispatched/") + kind).c_str(), BM_HighwayBatch,
                                 "dispatched", kind);
    benchmark::RegisterBenchmark((std::string("BM_IntrinsicsBatch/avx512/") + kind).c_str(), BM_IntrinsicsBatch,
                                 kind);
  }
  for (const char* kind : record_kinds)
    for (Records layout : {Records::runtime48, Records::aligned48, Records::aligned64}) {
      const std::string suffix = std::string("/") + to_string(layout) + "/" + kind;
      benchmark::RegisterBenchmark(("BM_Record/scalar" + suffix).c_str(), BM_Record,
                                   static_cast<const IsaKernels*>(nullptr), layout, kind);
      for (const IsaKernels& isa : isa_kernels)
        benchmark::RegisterBenchmark((std::string("BM_Record/batch_") + isa.name + suffix).c_str(), BM_Record, &isa,
                                     layout, kind);
    }
  for (const char* kind : host_isa_kinds)
    for (const IsaKernels& isa : isa_kernels)
      for (bool inline_exp : {false, true})
        benchmark::RegisterBenchmark((std::string("BM_ScalarHostIsa/") + isa.name + (inline_exp ? "/inline_exp/" : "/libm/") +
                                      kind).c_str(),
                                     BM_ScalarHostIsa, &isa, inline_exp, kind);
}

// ---- --check: every copy and baseline above against Curve (no timing) ----

// |a - b| relative to |b|, with values below the normal range compared absolutely
double difference(double a, double b) {
  if (a == b) return 0;
  const double scale = std::max(std::fabs(b), std::numeric_limits<double>::min());
  const double d = std::fabs(a - b) / scale;
  return std::isnan(d) ? std::numeric_limits<double>::infinity() : d;
}
// The same in units of the rounding of ln X: X = e^(ln X) carries the rounding of ln X (one
// ulp of |ln X|, which differs with and without fused multiply-adds) as a relative error.
double rounding_units(double a, double b) {
  const double log_magnitude = b > 0 ? std::fabs(std::log(b)) : 745.0;
  return difference(a, b) / (std::numeric_limits<double>::epsilon() * std::max(1.0, log_magnitude));
}

struct Worst {
  const char* what;
  double bound;
  double worst = 0;
  bool report(std::FILE* out) const {
    const bool ok = worst <= bound;
    std::fprintf(out, "  %-66s %.3g (bound %g) %s\n", what, worst, bound, ok ? "ok" : "FAILED");
    return ok;
  }
};

int run_checks() {
  bool ok = true;
  constexpr double rounding = 8;  // units of rounding_units: FMA or not, another exp
  for (const KindData& data : all_kinds()) {
    const int order = data.kind->twice_order;
    const std::vector<double>& s = data.separations;
    std::printf("%s (X_%g, s in [%g, %g], %zu grid intervals, %zu curve bytes)\n", data.kind->name, 0.5 * order,
                *std::min_element(s.begin(), s.end()), *std::max_element(s.begin(), s.end()),
                data.curve.grid_intervals(), data.curve.memory_bytes());
    std::vector<double> reference(query_count), logs(query_count), out(query_count);
    for (std::size_t i = 0; i < query_count; ++i) reference[i] = data.curve.value(order, s[i]);
    // the grid copy is the Curve's grid: the same ln X, bit for bit
    Worst copy{"grid copy: ln X vs Curve::log_value (1 where not bitwise equal)", 0};
    for (std::size_t i = 0; i < query_count; ++i) {
      detail::FastPosition at;
      const double mine = detail::fast_position(data.grid.grid, s[i], at)
                              ? detail::fast_quintic(data.grid.order(order), at.interval * detail::fast_stride, at.y)
                              : data.curve.log_value(order, s[i]);
      copy.worst = std::max(copy.worst, mine == data.curve.log_value(order, s[i]) ? 0.0 : 1.0);
    }
    ok &= copy.report(stdout);
    for (Records layout : {Records::runtime48, Records::aligned48, Records::aligned64}) {
      const double* coefficients = data.records(layout);
      const bool wide = layout == Records::aligned64;
      for (const IsaKernels& isa : isa_kernels) {
        if (!instruction_set_available(isa.isa)) continue;
        const bench::RecordKernels& k = *isa.kernels;
        const std::string label = std::string("record copy ") + to_string(layout) + ", " + isa.name;
        Worst scalar{nullptr, rounding}, batch{nullptr, rounding};
        const std::string scalar_label = label + ": scalar vs Curve::value (rounding units)";
        const std::string batch_label = label + ": batch vs Curve::value (rounding units)";
        scalar.what = scalar_label.c_str();
        batch.what = batch_label.c_str();
        batch_through(wide ? k.block8 : k.block6, data, coefficients, s.data(), out.data(), query_count);
        for (std::size_t i = 0; i < query_count; ++i) {
          const double one = wide ? bench::record_lookup<8>(data.grid.grid, coefficients, s[i])
                                  : bench::record_lookup<6>(data.grid.grid, coefficients, s[i]);
          if (!std::isnan(one)) scalar.worst = std::max(scalar.worst, rounding_units(one, reference[i]));
          if (!wide) {  // the out-of-line builds, with either exp
            for (const double other : {k.scalar6(data.grid.grid, coefficients, s[i]),
                                       k.scalar6_inline_exp(data.grid.grid, coefficients, s[i])})
              if (!std::isnan(other)) scalar.worst = std::max(scalar.worst, rounding_units(other, reference[i]));
          }
          batch.worst = std::max(batch.worst, rounding_units(out[i], reference[i]));
        }
        ok &= scalar.report(stdout) & batch.report(stdout);
      }
    }
    for (const IsaKernels& isa : isa_kernels) {
      if (!instruction_set_available(isa.isa)) continue;
      const std::string label = std::string("Curve::value_batch, ") + isa.name + ", vs Curve::value (rounding units)";
      Worst batch{label.c_str(), rounding};
      data.curve.value_batch(order, s.data(), out.data(), query_count, isa.isa);
      for (std::size_t i = 0; i < query_count; ++i) batch.worst = std::max(batch.worst, rounding_units(out[i], reference[i]));
      ok &= batch.report(stdout);
    }
    for (const bench::HighwayTarget& target : bench::highway_targets()) {
      if (!target.available) continue;
      const std::string label = std::string("Highway ") + target.name + " vs Curve::value (rounding units)";
      Worst highway{label.c_str(), rounding};
      batch_through(target.block, data, data.grid.order(order), s.data(), out.data(), query_count);
      for (std::size_t i = 0; i < query_count; ++i)
        highway.worst = std::max(highway.worst, rounding_units(out[i], reference[i]));
      ok &= highway.report(stdout);
    }
    if (bench::intrinsics_block_avx512 && instruction_set_available(InstructionSet::avx512)) {
      Worst intrinsics{"AVX-512 intrinsics vs Curve::value (rounding units)", rounding};
      batch_through(bench::intrinsics_block_avx512, data, data.grid.order(order), s.data(), out.data(), query_count);
      for (std::size_t i = 0; i < query_count; ++i)
        intrinsics.worst = std::max(intrinsics.worst, rounding_units(out[i], reference[i]));
      ok &= intrinsics.report(stdout);
    }
    // the quadrature baseline computes the right thing (where X is a normal double): the
    // table's error (~1e-11) plus the quadrature's
    const bench::DirectQuadrature quadrature(data.kind->distribution, data.kind->side, data.kind->shape, order);
    // (every query: the timing loop must not meet one that throws)
    Worst direct{"direct quadrature vs Curve::value (relative, where X > 1e-300)", 1e-9};
    for (std::size_t i = 0; i < query_count; ++i) {
      const double value = quadrature(s[i]);
      if (reference[i] > 1e-300) direct.worst = std::max(direct.worst, difference(value, reference[i]));
    }
    ok &= direct.report(stdout);
  }
  std::printf(ok ? "all checks passed\n" : "SOME CHECKS FAILED\n");
  return ok ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  for (int i = 1; i < argc; ++i)
    if (std::strcmp(argv[i], "--check") == 0) return run_checks();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::AddCustomContext("instruction_set", to_string(best_instruction_set()));
  std::string highway;
  for (const bench::HighwayTarget& target : bench::highway_targets())
    highway += std::string(highway.empty() ? "" : " ") + target.name + (target.available ? "" : "(unavailable)");
  benchmark::AddCustomContext("highway_targets", highway);
  register_kind_rows();
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
