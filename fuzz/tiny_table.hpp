// A tiny table of the right structure (its numbers are not integrals, only bounded):
// what the fuzz targets start from, built in memory in microseconds.
#pragma once
#include <cmath>
#include <vector>

#include "asperity/table.hpp"

namespace asperity::fuzz {

inline TableData tiny_table() {
  TableData data;
  data.generator = "fuzz";
  data.generator_options = "tiny";
  const struct { Distribution distribution; Side side; std::vector<double> shapes; } sets[] = {
      {Distribution::weibull, Side::tail, {1.5, 2.0, 2.5}},
      {Distribution::weibull, Side::bounded, {1.5, 2.0, 2.5}},
      {Distribution::gaussian, Side::tail, {2.0}}};
  for (const auto& spec : sets) {
    CurveSet set;
    set.distribution = spec.distribution;
    set.side = spec.side;
    set.shapes = spec.shapes;
    set.shape_min = spec.shapes.front();
    set.shape_max = spec.shapes.back();
    set.layout = scale_knot_density(default_layout(spec.distribution, spec.side), 0.05);
    for (std::size_t i = 0; i < set.shapes.size() * set.curve_stride(); ++i)
      set.knots.push_back(0.125 * static_cast<double>(i % 9) - 0.5);
    // its pieces do not meet: the stored error says so
    set.max_rel_error.assign(set.shapes.size() * order_count, 1.0);
    // a coarse lookup grid: the (discontinuous) curves are served in microseconds
    set.grid_tolerance.assign(set.shapes.size(), 1e-2);
    for (std::size_t i = 0; i < set.shapes.size(); ++i) set.grid_separations.insert(set.grid_separations.end(), {-1e300, 1e300});
    data.sets.push_back(set);
  }
  return data;
}

// Queries every set of a table that loaded: the lookups must hold whatever the (bounded) knots.
inline double exercise(const Table& table) {
  double sum = 0;
  for (const CurveSet& set : table.data().sets) {
    const Curve curve = table.curve(set.distribution, set.side, set.shapes.front());
    const double separations[] = {-1e6, -30, -1, -1e-3, 0, 1e-3, 0.5, 1, 5, 40, 1e6};
    double out[sizeof separations / sizeof separations[0]];
    for (int order = 0; order < order_count; ++order) {
      for (double separation : separations) sum += curve.log_value(order, separation);
      curve.log_value_batch(order, separations, out, sizeof separations / sizeof separations[0]);
      for (double value : out) sum += value;
    }
  }
  return sum;
}

}  // namespace asperity::fuzz
