#include "asperity/generator/generate.hpp"

#include <atomic>
#include <cmath>
#include <exception>
#include <mutex>
#include <random>
#include <algorithm>
#include <sstream>
#include <thread>

#include "asperity/detail/parallel_for.hpp"
#include "asperity/detail/segment_map.hpp"
#include "asperity/error.hpp"
#include "asperity/interrupt.hpp"
#include "asperity/detail/table_schema.hpp"
#include "asperity/generator/quadrature.hpp"

namespace asperity::generator {

std::string GenerateOptions::describe() const {
  std::ostringstream text;
  text.precision(12);
  text << "shapes=" << shape_min << ":" << shape_max << ":" << shape_log_step << " (step in ln a - 1/a)"
       << " (bounded side: " << shape_log_step * bounded_step_factor << "; from a = " << large_shape_from << ": "
       << large_shape_step_factor << " of each)"
       << " sides=" << (tail ? "tail" : "") << (tail && bounded ? "," : "") << (bounded ? "bounded" : "")
       << " gaussian=" << (gaussian ? "yes" : "no") << " tolerance=" << tolerance
       << " check_stride=" << check_stride;
  if (knot_density != 1) text << " knot_density=" << knot_density;
  return text.str();
}

namespace {
// a with q(a) = ln a - 1/a (q is increasing in a): Newton's method.
double shape_of_grid_variable(double q) {
  double a = std::max(0.05, std::exp(q));
  for (int iteration = 0; iteration < 100; ++iteration) {
    const double change = (shape_grid_variable(a) - q) / (1 / a + 1 / (a * a));
    a = std::max(0.5 * a, a - change);
    if (std::fabs(change) < 1e-15 * a) break;
  }
  return a;
}
}  // namespace

std::vector<double> shape_grid(const GenerateOptions& options, Side side) {
  if (!(options.shape_min > 0) || !(options.shape_max >= options.shape_min) || !(options.shape_log_step > 0))
    throw Error("the shape grid needs 0 < LO <= HI and STEP > 0");
  if (options.shape_min == options.shape_max) return {options.shape_min};
  const double log_step =
      side == Side::bounded ? options.shape_log_step * GenerateOptions::bounded_step_factor : options.shape_log_step;
  // Refuse a grid a table may not hold before making it (a step of 1e-9 would be 1e10 nodes).
  const double nodes = (shape_grid_variable(options.shape_max) - shape_grid_variable(options.shape_min)) /
                           (log_step * GenerateOptions::large_shape_step_factor) + shape_stencil + 6;  // at most
  if (!(nodes <= schema::max_shapes))
    throw Error("the shape grid would have " + std::to_string(static_cast<long long>(std::min(nodes, 1e18))) +
                " nodes, more than a table holds (" + std::to_string(schema::max_shapes) + "): use a larger STEP");
  // Nodes: LO, HI and the paper's shapes 1, 2, 3, 5 between them exactly; between those
  // anchors uniform in q = ln a - 1/a with spacing at most STEP; shape_stencil/2 nodes more past
  // each end (with the end spacing) so the interpolation stencil stays centred over [LO, HI].
  std::vector<double> anchors = {options.shape_min};
  for (double shape : {1.0, 2.0, 3.0, 5.0})
    if (shape > options.shape_min && shape < options.shape_max) anchors.push_back(shape);
  anchors.push_back(options.shape_max);
  std::vector<double> shapes;
  const int extra = shape_stencil / 2;
  double first_step = 0, last_step = 0;
  for (std::size_t piece = 0; piece + 1 < anchors.size(); ++piece) {
    const double q_lo = shape_grid_variable(anchors[piece]), q_hi = shape_grid_variable(anchors[piece + 1]);
    const double piece_step = anchors[piece] >= GenerateOptions::large_shape_from
                                  ? log_step * GenerateOptions::large_shape_step_factor
                                  : log_step;
    const int intervals = std::max(1, static_cast<int>(std::ceil((q_hi - q_lo) / piece_step - 1e-9)));
    const double step = (q_hi - q_lo) / intervals;
    if (piece == 0) first_step = step;
    last_step = step;
    shapes.push_back(anchors[piece]);
    for (int i = 1; i < intervals; ++i) shapes.push_back(shape_of_grid_variable(q_lo + step * i));
  }
  shapes.push_back(anchors.back());
  std::vector<double> below, above;
  for (int i = extra; i >= 1; --i)
    below.push_back(shape_of_grid_variable(shape_grid_variable(options.shape_min) - first_step * i));
  for (int i = 1; i <= extra; ++i)
    above.push_back(shape_of_grid_variable(shape_grid_variable(options.shape_max) + last_step * i));
  shapes.insert(shapes.begin(), below.begin(), below.end());
  shapes.insert(shapes.end(), above.begin(), above.end());
  return shapes;
}

std::vector<double> check_separations(const Curve& curve, const std::vector<SegmentSpec>& layout, int check_stride) {
  std::vector<double> points;
  const std::vector<detail::SegmentMap> maps = detail::SegmentMap::resolve(layout, curve.distribution(), curve.side(), curve.shape());
  const int stride = std::max(1, check_stride);
  // Each segment: uniform in its own variable u (the knots' spacing), and log-spaced toward
  // both of its ends, where an interpolant is weakest.
  for (const detail::SegmentMap& map : maps) {
    if (map.kind == SegmentKind::reciprocal) {  // s in (-inf, s1]: u = sqrt(s1/s) in (0, 1]
      for (double u : {1e-6, 1e-3, 0.01, 0.05, 0.1, 0.3, 0.5, 0.7, 0.9, 0.99, 0.999999}) points.push_back(map.separation_of_u(u));
      continue;
    }
    const int uniform = std::max(8, 160 / stride);
    for (int i = 0; i < uniform; ++i) points.push_back(map.separation_of_u(map.u_lo + (map.u_hi - map.u_lo) * (i + 0.5) / uniform));
    const double width = map.s_hi - map.s_lo;
    for (int k = 1; k <= 16; k += (k < 4 ? 1 : stride)) {
      points.push_back(map.s_lo + width * std::pow(10.0, -k));
      points.push_back(map.s_hi - width * std::pow(10.0, -k));
    }
  }
  // Toward s = 0 from both sides, down to the smallest doubles (the tail's power terms
  // |s|^(n + a) live there), and s = 0 itself.
  std::vector<double> magnitudes = {0.0, 4.9406564584124654e-324, 2.2250738585072014e-308, 1e-300, 1e-250, 1e-200,
                                    1e-150, 1e-100, 1e-75, 1e-50, 1e-40, 1e-30, 8.470329472543003e-22};
  for (int k = 20; k >= 1; k -= (k > 4 ? stride : 1)) magnitudes.push_back(std::pow(10.0, -k));
  for (double magnitude : magnitudes) {
    points.push_back(magnitude);
    points.push_back(-magnitude);
  }
  // And random points: uniform over the table, and log-uniform in |s| over it.
  std::mt19937_64 rng(12345);
  std::uniform_real_distribution<double> unit(0, 1);
  const double lo = curve.table_min_separation(), hi = curve.table_max_separation();
  for (int i = 0; i < 64 / stride + 4; ++i) {
    points.push_back(lo + (hi - lo) * unit(rng));
    const double magnitude = std::exp(std::log(1e-12) + unit(rng) * (std::log(std::max(-lo, std::fabs(hi))) - std::log(1e-12)));
    points.push_back(unit(rng) < 0.5 ? -magnitude : magnitude);
  }
  std::sort(points.begin(), points.end());
  points.erase(std::unique(points.begin(), points.end()), points.end());
  return points;
}

std::vector<double> measure_curve_error(const Curve& curve, const std::vector<SegmentSpec>& layout, int check_stride) {
  const CurveId id{curve.distribution(), curve.side(), curve.shape()};
  std::vector<double> worst(order_count, 0.0);
  for (double separation : check_separations(curve, layout, check_stride)) {
    poll_interrupt();  // a quadrature per order
    if (curve.side() == Side::bounded && separation >= 0) continue;  // 0 exactly: nothing to measure
    for (int k = 0; k < order_count; ++k) {
      if (!curve.has_order(k)) continue;
      const double reference = log_integral(id, order_of(k), separation);
      const double value = curve.log_value(k, separation);
      double error = std::fabs(std::expm1(value - reference));
      if (std::isinf(reference) && reference < 0) error = value == reference ? 0.0 : INFINITY;  // both exactly 0
      if (!(error <= worst[k])) worst[k] = std::isnan(error) ? INFINITY : error;
    }
  }
  return worst;
}

TableData generate_table(const GenerateOptions& options, const std::function<void(int, int)>& progress) {
  struct Job { std::size_t set; std::size_t shape; };
  TableData table;
  table.generator = std::string("asperity tablegen ") + ASPERITY_VERSION_STRING +
                    " (Boost.odeint runge_kutta_fehlberg78, Boost.Math exp_sinh/tanh_sinh)";
  table.generator_options = options.describe();
  auto add_set = [&](Distribution distribution, Side side, std::vector<double> set_shapes) {
    CurveSet set;
    set.distribution = distribution;
    set.side = side;
    set.shapes = std::move(set_shapes);
    set.shape_min = distribution == Distribution::gaussian ? 2.0 : options.shape_min;
    set.shape_max = distribution == Distribution::gaussian ? 2.0 : options.shape_max;
    set.layout = scale_knot_density(default_layout(distribution, side), options.knot_density);
    set.knots.assign(set.shapes.size() * set.curve_stride(), 0.0);
    set.max_rel_error.assign(set.shapes.size() * order_count, 0.0);
    table.sets.push_back(std::move(set));
  };
  if (options.tail) add_set(Distribution::weibull, Side::tail, shape_grid(options, Side::tail));
  if (options.bounded) add_set(Distribution::weibull, Side::bounded, shape_grid(options, Side::bounded));
  if (options.gaussian) add_set(Distribution::gaussian, Side::tail, {2.0});
  if (table.sets.empty()) throw Error("nothing to generate: choose at least one side or --gaussian");

  std::vector<Job> jobs;
  for (std::size_t set = 0; set < table.sets.size(); ++set)
    for (std::size_t shape = 0; shape < table.sets[set].shapes.size(); ++shape) jobs.push_back({set, shape});
  // The expensive curves first (the far tail of small shapes), so threads finish together.
  std::atomic<int> done{0};
  std::mutex progress_mutex;
  detail::parallel_for(jobs.size(), options.threads, [&](std::size_t index) {
    CurveSet& set = table.sets[jobs[index].set];
    const double shape = set.shapes[jobs[index].shape];
    const CurveId id{set.distribution, set.side, shape};
    const std::vector<double> knots = integrate_curve(id, set.layout, ChainOptions{options.tolerance});
    std::copy(knots.begin(), knots.end(), set.knots.begin() + jobs[index].shape * set.curve_stride());
    const Curve curve(set.distribution, set.side, shape, set.layout, knots.data());
    const std::vector<double> errors = measure_curve_error(curve, set.layout, options.check_stride);
    std::copy(errors.begin(), errors.end(), set.max_rel_error.begin() + jobs[index].shape * order_count);
    const int finished = ++done;
    if (progress) {
      std::lock_guard<std::mutex> lock(progress_mutex);
      progress(finished, static_cast<int>(jobs.size()));
    }
  });
  return table;
}

}  // namespace asperity::generator
