// Speed against error against memory: for each method a user could use to get X_n(s), the
// time per query (Google Benchmark, random separations), the maximum relative error over the
// range, measured against 50-digit references (Boost.Multiprecision quadrature of the defining
// integrals, tests/reference.hpp) at the same fixed set of points for every method, and the
// bytes the method holds for the curve.
//   Methods: ours (scalar and batch) at several knot densities of the table (tablegen
//   --density) and several grid tolerances (CurveOptions::grid_tolerance), each curve holding
//   the one order studied (order_mask) as Boost's interpolators do; Boost.Math's interpolators
//   on the default knots with our map to the segment variable; direct quadrature (Boost
//   exp_sinh/tanh_sinh in double); for the Gaussian F_5/2 the lubrication codes' curve fit.
// Run by scripts/speed-vs-error.sh, which turns the JSON into docs/speed-vs-error.md and a plot.
#include <benchmark/benchmark.h>

#include <boost/math/interpolators/cubic_hermite.hpp>
#include <boost/math/interpolators/makima.hpp>
#include <boost/math/interpolators/quintic_hermite.hpp>
#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>
#include <random>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "random_separations.hpp"
#include "asperity/curve.hpp"
#include "asperity/detail/segment_map.hpp"
#include "asperity/generator/chain_ode.hpp"
#include "asperity/generator/quadrature.hpp"
#include "reference.hpp"

namespace {
using namespace asperity;
using detail::SegmentMap;

constexpr std::size_t query_count = 4096;
constexpr int reference_points = 400;

struct Study {
  std::string name;  // what the plot's panel says
  Distribution distribution;
  Side side;
  double shape;
  int twice_order;
  double lo, hi;  // the separations queried and checked
};

using bench::uniform;

// A curve's knots for a layout, straight from the generator's integrator.
std::vector<double> knots_for(const Study& study, const std::vector<SegmentSpec>& layout) {
  return generator::integrate_curve({study.distribution, study.side, study.shape}, layout, generator::ChainOptions{});
}

// Boost.Math interpolators on the same knots, one per segment, behind our map s -> u and offset.
template <class Interpolator>
class BoostCurve {
 public:
  template <class Make>
  BoostCurve(const Study& study, const std::vector<SegmentSpec>& layout, const std::vector<double>& knots,
             const Curve& ours, Make make)
      : ours_(ours), order_(order_of(study.twice_order)), twice_order_(study.twice_order) {
    maps_ = SegmentMap::resolve(layout, study.distribution, study.side, study.shape);
    int total = 0;
    for (const SegmentSpec& spec : layout) total += spec.knots;
    int first = 0;
    for (std::size_t index = 0; index < layout.size(); ++index) {
      const int count = layout[index].knots;
      const double step = (maps_[index].u_hi - maps_[index].u_lo) / (count - 1);
      std::vector<double> u, h, slope, curvature;
      const double* data = &knots[(static_cast<std::size_t>(study.twice_order) * total + first) * 3];
      for (int j = 0; j < count; ++j) {
        // the reciprocal segment's first knot (u = 0, s = -inf) carries no finite offset: skip it
        if (maps_[index].kind == SegmentKind::reciprocal && j == 0) continue;
        u.push_back(maps_[index].u_lo + step * j);
        h.push_back(data[3 * j]);
        slope.push_back(data[3 * j + 1]);
        curvature.push_back(data[3 * j + 2]);
      }
      segments_.push_back(std::make_unique<Interpolator>(make(u, h, slope, curvature, step)));
      first += count;
    }
  }
  double log_value(double separation) const {
    if (!(separation <= ours_.table_max_separation())) return ours_.log_value(twice_order_, separation);
    std::size_t index = 0;
    while (separation > maps_[index].s_hi) ++index;
    const double u = maps_[index].u_of_s(separation);
    return maps_[index].offset_value(order_, u) + (*segments_[index])(u);
  }

 private:
  const Curve& ours_;
  double order_;
  int twice_order_;
  std::vector<SegmentMap> maps_;
  std::vector<std::unique_ptr<Interpolator>> segments_;
};

struct Method {
  Method(std::string study_name, std::string method_name, std::string method_family, double knot_density,
         double bytes)
      : study(std::move(study_name)), name(std::move(method_name)), family(std::move(method_family)),
        density(knot_density), table_bytes(bytes) {}
  std::string study, name, family;
  double density = 0;         // knots relative to the default layout (0: no table)
  double table_bytes = 0;     // the knot data of the one order: 3 doubles a knot (ours), Boost's own
  double grid_tolerance = 0;  // ours: CurveOptions::grid_tolerance
  double memory_bytes = 0;    // what the method holds to answer the one order (ours: Curve::memory_bytes)
  double memory_all_orders = 0;  // ours: the same curve holding all six orders
  std::function<double(double)> log_value;          // ln X at one separation
  std::function<void(const double*, double*, std::size_t)> batch;  // X for many (optional)
  std::function<double(double)> value;              // X (for the timing of scalar methods)
  double max_error = 0;
};

double max_relative_error(const Method& method, const std::vector<double>& points, const std::vector<double>& reference) {
  double worst = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double log_value = method.log_value(points[i]);
    double error;
    if (std::isinf(reference[i]) && reference[i] < 0) error = log_value == reference[i] ? 0 : 1;
    else if (std::isinf(log_value) && log_value < 0) error = 1;  // says 0 where X > 0: 100% wrong
    else error = std::fabs(std::expm1(log_value - reference[i]));
    if (!(error <= worst)) worst = std::isnan(error) ? 1e300 : error;
  }
  return worst;
}

std::vector<Method>& methods() {
  static std::vector<Method> all;
  return all;
}
std::vector<std::unique_ptr<Curve>>& curves() {
  static std::vector<std::unique_ptr<Curve>> all;
  return all;
}

void add_methods(const Study& study) {
  const std::vector<SegmentSpec> base = default_layout(study.distribution, study.side);
  const std::vector<double> points = uniform(study.lo, study.hi, reference_points, 7);
  std::vector<double> reference(points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
    reference[i] = static_cast<double>(test::reference_log(study.distribution, study.side, study.shape,
                                                           order_of(study.twice_order), points[i]));
  const int order = study.twice_order;
  std::vector<Method> added;
  const Curve* default_curve = nullptr;
  std::vector<double> default_knots;
  for (double density : {0.125, 0.25, 0.5, 1.0, 2.0}) {
    const std::vector<SegmentSpec> layout = scale_knot_density(base, density);
    const std::vector<double> knots = knots_for(study, layout);
    int total = 0;
    for (const SegmentSpec& spec : layout) total += spec.knots;
    if (density == 1.0) default_knots = knots;
    for (double tolerance : {1e-13, 1e-11, 1e-9, 1e-7}) {
      CurveOptions options;
      options.grid_tolerance = tolerance;
      curves().push_back(std::make_unique<Curve>(study.distribution, study.side, study.shape, layout, knots.data(),
                                                 order_bit(order), options));
      const Curve* curve = curves().back().get();
      const Curve all_orders(study.distribution, study.side, study.shape, layout, knots.data(), Curve::all_orders,
                             options);
      if (density == 1.0 && tolerance == CurveOptions{}.grid_tolerance) default_curve = curve;
      for (bool is_batch : {false, true}) {
        const char* name = is_batch ? "asperity batch" : "asperity scalar";
        Method method{study.name, name, name, density, 24.0 * total};
        method.grid_tolerance = tolerance;
        method.memory_bytes = static_cast<double>(curve->memory_bytes());
        method.memory_all_orders = static_cast<double>(all_orders.memory_bytes());
        if (is_batch) {
          method.log_value = [curve, order](double s) {
            double out;
            curve->log_value_batch(order, &s, &out, 1);
            return out;
          };
          method.batch = [curve, order](const double* s, double* out, std::size_t n) {
            curve->value_batch(order, s, out, n);
          };
        } else {
          method.log_value = [curve, order](double s) { return curve->log_value(order, s); };
          method.value = [curve, order](double s) { return curve->value(order, s); };
        }
        added.push_back(method);
      }
    }
  }
  const std::vector<SegmentSpec>& layout = base;
  const Curve& ours = *default_curve;
  auto boost_method = [&](const std::string& name, auto curve_pointer, double bytes_per_knot) {
    Method method{study.name, name, "Boost.Math", 1.0, 0};
    int total = 0;
    for (const SegmentSpec& spec : layout) total += spec.knots;
    method.table_bytes = bytes_per_knot * total;
    method.memory_bytes = method.table_bytes;  // the knot vectors it holds (and little else)
    std::shared_ptr<std::remove_pointer_t<decltype(curve_pointer)>> shared(curve_pointer);
    method.log_value = [shared](double s) { return shared->log_value(s); };
    method.value = [shared](double s) { return std::exp(shared->log_value(s)); };
    added.push_back(method);
  };
  namespace bi = boost::math::interpolators;
  using V = std::vector<double>;
  boost_method("Boost cardinal_quintic_hermite",
               new BoostCurve<bi::cardinal_quintic_hermite<V>>(study, layout, default_knots, ours,
                   [](V u, V h, V d1, V d2, double step) {
                     return bi::cardinal_quintic_hermite<V>(std::move(h), std::move(d1), std::move(d2), u[0], step);
                   }), 24);
  boost_method("Boost quintic_hermite",
               new BoostCurve<bi::quintic_hermite<V>>(study, layout, default_knots, ours,
                   [](V u, V h, V d1, V d2, double) {
                     return bi::quintic_hermite<V>(std::move(u), std::move(h), std::move(d1), std::move(d2));
                   }), 32);
  boost_method("Boost cubic_hermite",
               new BoostCurve<bi::cubic_hermite<V>>(study, layout, default_knots, ours,
                   [](V u, V h, V d1, V, double) { return bi::cubic_hermite<V>(std::move(u), std::move(h), std::move(d1)); }),
               24);
  boost_method("Boost makima",
               new BoostCurve<bi::makima<V>>(study, layout, default_knots, ours,
                   [](V u, V h, V, V, double) { return bi::makima<V>(std::move(u), std::move(h)); }), 32);

  Method quadrature{study.name, "Boost exp_sinh/tanh_sinh quadrature", "quadrature", 0, 0};
  const generator::CurveId id{study.distribution, study.side, study.shape};
  quadrature.log_value = [id, order](double s) { return generator::log_integral(id, order_of(order), s); };
  quadrature.value = [id, order](double s) { return std::exp(generator::log_integral(id, order_of(order), s)); };
  added.push_back(quadrature);

  if (study.distribution == Distribution::gaussian && order == 5) {
    Method fit{study.name, "curve fit 4.4086e-5 (4 - h)^6.804", "curve fit", 0, 0};
    fit.value = [](double h) { return h < 4 ? 4.4086e-5 * std::pow(4 - h, 6.804) : 0.0; };
    fit.log_value = [](double h) { return h < 4 ? std::log(4.4086e-5) + 6.804 * std::log(4 - h) : -INFINITY; };
    added.push_back(fit);
  }
  for (Method& method : added) {
    method.max_error = max_relative_error(method, points, reference);
    methods().push_back(method);
  }
}

void run(benchmark::State& state, const Method* method, const std::vector<double>* queries) {
  std::vector<double> out(query_count);
  std::size_t i = 0;
  if (method->batch) {
    for (auto _ : state) {
      method->batch(queries->data(), out.data(), query_count);
      benchmark::DoNotOptimize(out.data());
    }
    state.SetItemsProcessed(state.iterations() * query_count);
  } else {
    for (auto _ : state) benchmark::DoNotOptimize(method->value((*queries)[i++ & (query_count - 1)]));
    state.SetItemsProcessed(state.iterations());
  }
  state.counters["max_rel_error"] = method->max_error;
  state.counters["density"] = method->density;
  state.counters["table_bytes"] = method->table_bytes;
  state.counters["memory_bytes"] = method->memory_bytes;
  state.counters["memory_all_orders"] = method->memory_all_orders;
  state.counters["grid_tolerance"] = method->grid_tolerance;
  state.counters["batch"] = method->batch ? 1 : 0;
  state.SetLabel(method->study + "|" + method->name + "|" + method->family);
}

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  benchmark::AddCustomContext("instruction_set", to_string(best_instruction_set()));
  // Weibull a = 2 load over the whole table (all-touching to the far tail); the Gaussian
  // F_5/2 over the lubrication range h in [0, 4), where the curve fit is meant to hold.
  const Study studies[] = {
      {"Weibull a=2 tail, X_3/2 (load), s in [-6, 27.5]", Distribution::weibull, Side::tail, 2.0, 3, -6.0, 27.5},
      {"Gaussian F_5/2, h in [0, 4)", Distribution::gaussian, Side::tail, 2.0, 5, 0.0, 4.0}};
  static std::vector<std::vector<double>> queries;
  for (const Study& study : studies) {
    std::fprintf(stderr, "references and tables for %s ...\n", study.name.c_str());
    add_methods(study);
    queries.push_back(uniform(study.lo, study.hi, query_count, 5));
  }
  const std::size_t per_first = [&] {
    std::size_t count = 0;
    for (const Method& method : methods()) count += method.study == studies[0].name;
    return count;
  }();
  for (std::size_t i = 0; i < methods().size(); ++i) {
    const Method* method = &methods()[i];
    const std::vector<double>* study_queries = &queries[i < per_first ? 0 : 1];
    char name[160];
    std::snprintf(name, sizeof name, "%s/%s/density:%g/grid_tolerance:%g",
                  i < per_first ? "weibull2_load" : "gaussian_F52", method->name.c_str(), method->density,
                  method->grid_tolerance);
    benchmark::RegisterBenchmark(name, run, method, study_queries);
  }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
