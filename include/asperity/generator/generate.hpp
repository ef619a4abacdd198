// Building a whole table: every (distribution, side, shape) curve integrated in parallel,
// read back through the runtime and checked against direct quadrature.
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "asperity/table.hpp"
#include "asperity/generator/chain_ode.hpp"

namespace asperity::generator {

struct GenerateOptions {
  double shape_min = 0.5;
  double shape_max = 20;
  double shape_log_step = 0.075;  // spacing of the shape grid in q = ln(a) - 1/a (tail side)
  // The bounded side's grid is this much finer: between shapes its curves are the hardest to
  // interpolate (where tau = d^a ~ 10 turns the first-contact power law into the all-touching
  // polynomial); at the tail's spacing they reached 5.5e-10 there, at 2/3 of it 8.7e-12.
  static constexpr double bounded_step_factor = 2.0 / 3.0;
  // Above a = 5 (the grid's last anchor) this much finer again, on both sides: the curves depend
  // on the shape most steeply there (tail s ~ 1.1-1.4 at a ~ 19: 5.9e-12 between nodes at the
  // full step, the bounded side's tau ~ 10 at a ~ 19.5: 8.5e-12), and the 12-point blend's error
  // falls like the step to the 12th power (docs/accuracy.md, "Between grid shapes").
  static constexpr double large_shape_step_factor = 0.8;
  static constexpr double large_shape_from = 5;
  bool tail = true;
  bool bounded = true;
  bool gaussian = true;
  double tolerance = 1e-14;
  double knot_density = 1;  // knots per segment relative to the default layout (docs/speed-vs-error.md)
  int threads = 0;          // 0: hardware concurrency
  int check_stride = 1;     // > 1: fewer check points (tests)
  std::string describe() const;
};

// The shape grid of one side (the Gaussian has the one shape 2).
std::vector<double> shape_grid(const GenerateOptions& options, Side side = Side::tail);

// progress(done, total) is called from worker threads, serialized.
TableData generate_table(const GenerateOptions& options,
                         const std::function<void(int, int)>& progress = {});

// Where the generator checks a served curve against direct quadrature: every segment of its
// layout uniformly in its variable and log-spaced toward both of its ends, s = 0 and log-spaced
// toward it from both sides down to the smallest double, and random points over the table.
std::vector<double> check_separations(const Curve& curve, const std::vector<SegmentSpec>& layout, int check_stride);
// The largest relative error per order at those points (what a table stores as max_rel_error).
std::vector<double> measure_curve_error(const Curve& curve, const std::vector<SegmentSpec>& layout, int check_stride);

}  // namespace asperity::generator
