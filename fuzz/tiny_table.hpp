// A tiny table of the right structure (its numbers are not integrals, only bounded):
// what the fuzz targets start from, built in memory in microseconds.
#pragma once
#include <cmath>
#include <vector>

#include "asperity/contact_curves.hpp"
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

// A tiny contact-curves table (a measured surface's, in form): five nodes.
inline ContactCurvesData tiny_contact_curves() {
  ContactCurvesData data;
  data.generator = "fuzz";
  data.generator_options = "tiny";
  data.source = "exact-contact";
  data.description = "tiny";
  data.separation_datum = "the mean plane";
  data.separation = {1e-7, 2e-7, 3e-7, 4e-7, 5e-7};
  data.pressure = {1e8, 3e7, 1e7, 3e6, 1e6};
  data.stiffness = {1e15, 3e14, 1e14, 3e13, 1e13};
  data.area_fraction = {0.1, 0.04, 0.01, 0.004, 0.001};
  for (int i = 0; i < 3; ++i) {
    data.measured_rel_error[i] = 0.01;
    data.max_rel_error[i] = 0.02;
  }
  data.check_points = 4;
  data.safety_factor = 2;
  data.solver_tolerance = 1e-8;
  data.contact_modulus = 1e11;
  data.nominal_area = 1e-10;
  data.mean_summit_height = 2e-8;
  data.max_height = 6e-7;
  return data;
}

// Queries contact curves that loaded: inside the range every value is finite and in its
// bounds, the pressure falls, the inverse lands inside; outside, NaN. A broken promise traps.
inline double exercise(const ContactCurves& curves) {
  double sum = 0, last = INFINITY;
  const double low = curves.min_separation(), high = curves.max_separation();
  for (int i = 0; i <= 64; ++i) {
    const double u = i == 64 ? high : low + (high - low) * i / 64;
    const ContactCurvesState s = curves.at_separation(u);
    if (!(s.pressure > 0 && s.pressure <= last * (1 + 1e-12) && std::isfinite(s.stiffness) && s.area_fraction > 0 &&
          s.area_fraction <= 1.0000000001))
      __builtin_trap();
    last = s.pressure;
    const double back = curves.separation_at_pressure(s.pressure);
    if (!(back >= low && back <= high)) __builtin_trap();
    sum += s.pressure + s.stiffness + s.area_fraction + back;
  }
  if (!std::isnan(curves.pressure(high + (high - low))) || !std::isnan(curves.pressure(NAN))) __builtin_trap();
  return sum;
}

}  // namespace asperity::fuzz
