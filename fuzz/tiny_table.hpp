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

// The same with an adhesive law's parts (a tensile part crossing the compressive one inside the
// range: a pull-off) and a summit count.
inline ContactCurvesData tiny_adhesive_contact_curves() {
  ContactCurvesData data = tiny_contact_curves();
  data.source = "contact-law jkr";
  data.tensile_pressure = {3e7, 2e7, 1.3e7, 9e6, 6e6};
  data.tensile_stiffness = {1e14, 7e13, 4.5e13, 3e13, 2e13};
  data.summit_count = {1e9, 5e8, 2e8, 1e8, 5e7};
  data.summit_count_max_rel_error = 0.02;
  return data;
}

// Adhesive curves: inside the range every value is finite, the pull-off (where stated) is the
// least pressure the inverse serves, the inverse lands on the stable branch; outside, NaN.
inline double exercise_adhesive(const ContactCurves& curves) {
  double sum = 0;
  const double low = curves.min_separation(), high = curves.max_separation(), end = curves.stable_branch_end();
  if (!(end >= low && end <= high)) __builtin_trap();
  if (!std::isnan(curves.pull_off_pressure()) && curves.pull_off_pressure() != curves.min_pressure()) __builtin_trap();
  for (int i = 0; i <= 64; ++i) {
    const double u = i == 64 ? high : low + (high - low) * i / 64;
    const ContactCurvesState s = curves.at_separation(u);
    const ContactCurvesState t = curves.tensile_part(u);
    if (!(std::isfinite(s.pressure) && std::isfinite(s.stiffness) && s.area_fraction > 0 &&
          s.area_fraction <= 1.0000000001 && t.pressure > 0 && std::isfinite(t.stiffness)))
      __builtin_trap();
    const double count = curves.summit_count(u);
    if (!(std::isnan(count) || count > 0)) __builtin_trap();
    const double p = curves.min_pressure() + (curves.max_pressure() - curves.min_pressure()) * i / 64;
    const double back = curves.separation_at_pressure(p);
    if (!(back >= low && back <= end)) __builtin_trap();
    sum += s.pressure + s.stiffness + s.area_fraction + back + t.pressure;
  }
  if (!std::isnan(curves.pressure(high + (high - low))) || !std::isnan(curves.pressure(NAN)) ||
      !std::isnan(curves.summit_count(NAN)))
    __builtin_trap();
  return sum;
}

// Queries contact curves that loaded: inside the range every value is finite and in its
// bounds, the pressure falls, the inverse lands inside; outside, NaN. A broken promise traps.
inline double exercise(const ContactCurves& curves) {
  if (curves.has_tension()) return exercise_adhesive(curves);
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
