#include "chain_ode.hpp"

#include <array>
#include <boost/numeric/odeint.hpp>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "asperity/asymptotic.hpp"

namespace asperity::tablegen {
namespace {

using State = std::array<double, order_count>;
// Logs of X_-1/2 and X_0 .. X_5/2: log_values[0] is X_-1/2, log_values[1 + k] is twice_order k.
using Logs = std::array<double, order_count + 1>;

// phi'(z)/phi(z) for the density.
double density_log_slope(const CurveId& curve, double height) {
  if (curve.distribution == Distribution::gaussian) return -height;
  return (curve.shape - 1) / height - curve.shape * std::pow(height, curve.shape - 1);
}

double log_density(const CurveId& curve, double height) {
  return curve.distribution == Distribution::gaussian ? gaussian_log_density(height)
                                                      : weibull_log_density(curve.shape, height);
}

// First and second s-derivatives of ln X_n for every order, from the chain
// dX_n/ds = -n X_(n-1) (X_-1/2 and its slope from quadrature).
void log_derivatives(const CurveId& curve, double separation, const Logs& logs, double slope_minus_half,
                     std::array<double, order_count>& slope, std::array<double, order_count>& curvature) {
  const bool bounded = curve.side == Side::bounded;
  // Order 0: dX_0/ds = -phi(s) on the tail side, -phi(-s) on the bounded side.
  const double height = bounded ? -separation : separation;
  const bool no_density = curve.distribution == Distribution::weibull && height <= 0;
  slope[0] = no_density ? 0.0 : -std::exp(log_density(curve, height) - logs[1]);
  const double second_ratio0 =
      no_density ? 0.0 : (bounded ? -1.0 : 1.0) * density_log_slope(curve, height) * slope[0];
  curvature[0] = second_ratio0 - slope[0] * slope[0];
  for (int k = 1; k < order_count; ++k) {
    const double n = order_of(k);
    slope[k] = -n * std::exp(logs[1 + k - 2] - logs[1 + k]);
    double second_ratio;  // X''_n / X_n
    switch (k) {
      case 1: second_ratio = -0.5 * slope_minus_half * std::exp(logs[0] - logs[2]); break;
      case 2: second_ratio = -slope[0] * std::exp(logs[1] - logs[3]); break;
      case 3: second_ratio = 0.75 * std::exp(logs[0] - logs[4]); break;
      default: second_ratio = n * (n - 1) * std::exp(logs[1 + k - 4] - logs[1 + k]); break;
    }
    curvature[k] = second_ratio - slope[k] * slope[k];
  }
}

// The right-hand side of the ODE in u: dH_k/du = (d ln X_k/ds) ds/du - d offset_k/du.
struct ChainSystem {
  CurveId curve;
  SegmentMap map;
  void operator()(const State& h, State& rate, double u) const {
    double separation, ds_du, d2s_du2;
    map.s_of_u(u, separation, ds_du, d2s_du2);
    std::array<double, order_count> offset_rate{};
    for (int k = 0; k < order_count; ++k) {
      double value, d1, d2;
      map.offset(order_of(k), u, value, d1, d2);
      offset_rate[k] = d1;
    }
    if (ds_du == 0) {  // at s = 0 on a graded segment every chain term is multiplied by 0
      for (int k = 0; k < order_count; ++k) rate[k] = -offset_rate[k];
      return;
    }
    Logs logs;
    logs[0] = log_integral(curve, -0.5, separation);
    for (int k = 0; k < order_count; ++k) logs[1 + k] = h[k] + map.offset_value(order_of(k), u);
    // Only the slopes are needed here; curvature is computed at the knots.
    const bool bounded = curve.side == Side::bounded;
    const double height = bounded ? -separation : separation;
    const bool no_density = curve.distribution == Distribution::weibull && height <= 0;
    const double slope0 = no_density ? 0.0 : -std::exp(log_density(curve, height) - logs[1]);
    rate[0] = slope0 * ds_du - offset_rate[0];
    rate[1] = -0.5 * std::exp(logs[0] - logs[2]) * ds_du - offset_rate[1];
    for (int k = 2; k < order_count; ++k)
      rate[k] = -order_of(k) * std::exp(logs[1 + k - 2] - logs[1 + k]) * ds_du - offset_rate[k];
  }
};

// Knot data of every order at u from the logs there.
void knot_from_logs(const CurveId& curve, const SegmentMap& map, double u, const Logs& logs,
                    double* out /* [order][3] with stride */, std::size_t order_stride) {
  double separation, ds_du, d2s_du2;
  map.s_of_u(u, separation, ds_du, d2s_du2);
  std::array<double, order_count> slope{}, curvature{};
  if (ds_du != 0) {
    const double slope_minus_half = log_slope_minus_half(curve, separation);
    log_derivatives(curve, separation, logs, slope_minus_half, slope, curvature);
  }
  for (int k = 0; k < order_count; ++k) {
    double offset, d1, d2;
    map.offset(order_of(k), u, offset, d1, d2);
    double* knot = out + k * order_stride;
    knot[0] = logs[1 + k] - offset;
    knot[1] = ds_du == 0 ? -d1 : slope[k] * ds_du - d1;
    knot[2] = ds_du == 0 ? -d2 : curvature[k] * ds_du * ds_du + slope[k] * d2s_du2 - d2;
  }
}

double knot_u(const SegmentMap& map, int knots, int j) {
  return map.u_lo + (map.u_hi - map.u_lo) * j / (knots - 1);
}

// The reciprocal segment (every summit touching, s <= p0): quadrature at each knot; at u = 0
// (s = -inf) the limits from the moments.
void fill_reciprocal(const CurveId& curve, const SegmentMap& map, int knots, double* data, std::size_t order_stride) {
  const double scale = -map.p0;
  double mean = 0, second = 1;  // Gaussian: the whole-line moments
  if (curve.distribution == Distribution::weibull) {
    mean = weibull_moment(curve.shape, 1);
    second = weibull_moment(curve.shape, 2);
  }
  const double sign = curve.side == Side::bounded ? -1.0 : 1.0;
  for (int k = 0; k < order_count; ++k) {
    const double n = order_of(k);
    double* knot = data + k * order_stride;
    knot[0] = 0;
    knot[1] = sign * n * mean / scale;
    knot[2] = (n * (n - 1) * second - n * n * mean * mean) / (scale * scale);
  }
  for (int j = 1; j < knots; ++j) {
    const double u = knot_u(map, knots, j);
    double separation, ds_du, d2s_du2;
    map.s_of_u(u, separation, ds_du, d2s_du2);
    Logs logs;
    logs[0] = log_integral(curve, -0.5, separation);
    for (int k = 0; k < order_count; ++k) logs[1 + k] = log_integral(curve, order_of(k), separation);
    knot_from_logs(curve, map, u, logs, data + j * 3, order_stride);
  }
}

Logs seed_logs(const CurveId& curve, double separation) {
  Logs logs;
  for (int k = -1; k < order_count; ++k) {
    const double n = 0.5 * k;
    double value;
    if (curve.side == Side::bounded)
      value = bounded_contact_log(bounded_contact_series(curve.shape, n), curve.shape, n, separation);
    else if (curve.distribution == Distribution::gaussian)
      value = gaussian_tail_log(gaussian_tail_series(n), n, separation);
    else
      value = weibull_tail_log(weibull_tail_series(curve.shape, n), curve.shape, n, separation);
    logs[1 + k] = value;
  }
  return logs;
}

}  // namespace

std::vector<double> integrate_curve(const CurveId& curve, const std::vector<SegmentSpec>& layout,
                                    const ChainOptions& options) {
  namespace odeint = boost::numeric::odeint;
  const double shape = curve.distribution == Distribution::gaussian ? 2.0 : curve.shape;
  int total = 0;
  std::vector<int> first(layout.size());
  for (std::size_t i = 0; i < layout.size(); ++i) { first[i] = total; total += layout[i].knots; }
  const std::size_t order_stride = static_cast<std::size_t>(total) * 3;
  std::vector<double> data(order_stride * order_count, std::numeric_limits<double>::quiet_NaN());

  // Start at the far end of the last segment (smallest values: far tail, or first contact)
  // and integrate toward decreasing separation, where every X_n grows.
  const int last = static_cast<int>(layout.size()) - 1;
  Logs logs{};
  bool have_state = false;
  for (int index = last; index >= 0; --index) {
    const SegmentMap map = SegmentMap::make(layout[index], curve.distribution, curve.side, shape);
    const int knots = layout[index].knots;
    double* segment_data = data.data() + static_cast<std::size_t>(first[index]) * 3;
    if (map.kind == SegmentKind::reciprocal) {
      fill_reciprocal(curve, map, knots, segment_data, order_stride);
      continue;
    }
    double s_lo, s_hi, unused1, unused2;
    map.s_of_u(map.u_lo, s_lo, unused1, unused2);
    map.s_of_u(map.u_hi, s_hi, unused1, unused2);
    const bool descending = s_hi > s_lo;  // walk u so that s decreases
    std::vector<double> times(knots);
    std::vector<int> knot_index(knots);
    for (int j = 0; j < knots; ++j) {
      knot_index[j] = descending ? knots - 1 - j : j;
      times[j] = knot_u(map, knots, knot_index[j]);
    }
    double start_s, ds, d2s;
    map.s_of_u(times[0], start_s, ds, d2s);
    if (!have_state) logs = seed_logs(curve, start_s);
    State state;
    for (int k = 0; k < order_count; ++k) state[k] = logs[1 + k] - map.offset_value(order_of(k), times[0]);

    ChainSystem system{curve, map};
    int observed = 0;
    auto observer = [&](const State& h, double u) {
      Logs knot_logs;
      double separation, ds_du, d2s_du2;
      map.s_of_u(u, separation, ds_du, d2s_du2);
      const bool singular_minus_half = ds_du == 0;  // X_-1/2 may be infinite at s = 0
      knot_logs[0] = singular_minus_half ? 0.0 : log_integral(curve, -0.5, separation);
      for (int k = 0; k < order_count; ++k) knot_logs[1 + k] = h[k] + map.offset_value(order_of(k), u);
      knot_from_logs(curve, map, u, knot_logs, segment_data + static_cast<std::size_t>(knot_index[observed]) * 3,
                     order_stride);
      logs = knot_logs;
      ++observed;
    };
    const double step = (times[1] - times[0]) * 0.25;
    auto stepper = odeint::make_controlled(options.tolerance, options.tolerance,
                                           odeint::runge_kutta_fehlberg78<State>());
    odeint::integrate_times(stepper, system, state, times.begin(), times.end(), step, observer);
    if (observed != knots) throw std::runtime_error("odeint did not reach every knot");
    have_state = true;
  }
  for (double value : data)
    if (!std::isfinite(value)) throw std::runtime_error("the chain produced a value that is not finite");
  return data;
}

}  // namespace asperity::tablegen
