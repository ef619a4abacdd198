#include "asperity/generator/chain_ode.hpp"

#include <array>
#include <boost/numeric/odeint.hpp>
#include <cmath>
#include <limits>
#include <string>

#include "asperity/asymptotic.hpp"
#include "asperity/detail/segment_map.hpp"
#include "asperity/error.hpp"
#include "asperity/interrupt.hpp"

namespace asperity::generator {
namespace {

using detail::SegmentMap;

using State = std::array<double, order_count>;
// Logs of X_-1/2 and X_0 .. X_5/2: log_values[0] is X_-1/2, log_values[1 + k] is twice_order k.
using Logs = std::array<double, order_count + 1>;

// d ln X_0/ds and X_0''/X_0. For the Weibull these come from the closed forms J_0 = exp(-s^a)
// and K_0 = 1 - exp(-(-s)^a) (not from the state), so the order-0 chain carries no drift.
void order_zero(const CurveId& curve, double separation, double log_x0, double& slope, double& second_ratio) {
  if (curve.distribution == Distribution::gaussian) {  // dF_0/ds = -phi(s), F_0'' = s phi(s)
    slope = -std::exp(gaussian_log_density(separation) - log_x0);
    second_ratio = -separation * slope;
    return;
  }
  const double a = curve.shape;
  if (curve.side == Side::tail) {
    if (separation <= 0) { slope = second_ratio = 0; return; }
    const double rate = a * std::pow(separation, a - 1);  // d t/ds
    slope = -rate;
    second_ratio = rate * rate - a * (a - 1) * std::pow(separation, a - 2);
    return;
  }
  // bounded: ln K_0 = ln(1 - e^-tau), tau = d^a, d = -s
  const double distance = -separation, tau = std::pow(distance, a);
  const double rate = a * std::pow(distance, a - 1);   // d tau/dd
  const double curvature = a * (a - 1) * std::pow(distance, a - 2);
  const double g1 = 1 / std::expm1(tau);                // d ln K_0/d tau
  const double g2 = -g1 * (1 + g1);                     // d2 ln K_0/d tau2 = -e^tau/expm1(tau)^2
  slope = -g1 * rate;                                   // ds = -dd
  const double log_curvature = g2 * rate * rate + g1 * curvature;
  second_ratio = log_curvature + slope * slope;         // X''/X = (ln X)'' + (ln X)'^2
}

// First and second s-derivatives of ln X_n for every order, from the chain
// dX_n/ds = -n X_(n-1) (X_-1/2 and its slope from quadrature).
void log_derivatives(const CurveId& curve, double separation, const Logs& logs, double slope_minus_half,
                     std::array<double, order_count>& slope, std::array<double, order_count>& curvature) {
  double second_ratio0;
  order_zero(curve, separation, logs[1], slope[0], second_ratio0);
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
    poll_interrupt();  // each step's quadratures take microseconds; a curve, seconds
    double separation, ds_du, d2s_du2;
    map.s_of_u(u, separation, ds_du, d2s_du2);
    std::array<double, order_count> offset_rate{};
    for (int k = 0; k < order_count; ++k) {
      double value, d1, d2;
      map.offset(order_of(k), u, value, d1, d2);
      offset_rate[k] = d1;
    }
    if (ds_du == 0) {  // every chain term is multiplied by ds/du = 0 (s = 0 on a graded segment)
      for (int k = 0; k < order_count; ++k) rate[k] = -offset_rate[k];
      return;
    }
    Logs logs;
    logs[0] = log_integral(curve, -0.5, separation);
    for (int k = 0; k < order_count; ++k) logs[1 + k] = h[k] + map.offset_value(order_of(k), u);
    // Only the slopes are needed here; curvature is computed at the knots.
    double slope0, unused;
    order_zero(curve, separation, logs[1], slope0, unused);
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
  const bool at_origin = separation == 0;  // graded segments reach s = 0, where X_-1/2 may be infinite
  if (!at_origin) {
    const double slope_minus_half = log_slope_minus_half(curve, separation);
    log_derivatives(curve, separation, logs, slope_minus_half, slope, curvature);
  }
  for (int k = 0; k < order_count; ++k) {
    double offset, d1, d2;
    map.offset(order_of(k), u, offset, d1, d2);
    double* knot = out + k * order_stride;
    knot[0] = logs[1 + k] - offset;
    // At the origin ds/du and d2s/du2 vanish (graded map), so only the offset remains.
    knot[1] = at_origin ? -d1 : slope[k] * ds_du - d1;
    knot[2] = at_origin ? -d2 : curvature[k] * ds_du * ds_du + slope[k] * d2s_du2 - d2;
  }
}

double knot_u(const SegmentMap& map, int knots, int j) {
  return map.u_lo + (map.u_hi - map.u_lo) * j / (knots - 1);
}

// The reciprocal segment (every summit touching, s <= p0): quadrature at each knot; at u = 0
// (s = -inf) the limits from the moments.
void fill_reciprocal(const CurveId& curve, const SegmentMap& map, int knots, double* data, std::size_t order_stride) {
  const double scale = -map.p0;
  double mean = 0;  // Gaussian: the whole-line mean
  if (curve.distribution == Distribution::weibull) mean = weibull_moment(curve.shape, 1);
  const double sign = curve.side == Side::bounded ? -1.0 : 1.0;
  for (int k = 0; k < order_count; ++k) {
    const double n = order_of(k);
    double* knot = data + k * order_stride;
    // H(u) = ln E[(1 + sign z u^2/scale)^n] = sign n mean u^2/scale + O(u^4)
    knot[0] = 0;
    knot[1] = 0;
    knot[2] = 2 * sign * n * mean / scale;
  }
  for (int j = 1; j < knots; ++j) {
    poll_interrupt();
    const double u = knot_u(map, knots, j);
    double separation, ds_du, d2s_du2;
    map.s_of_u(u, separation, ds_du, d2s_du2);
    Logs logs;
    logs[0] = log_integral(curve, -0.5, separation);
    for (int k = 0; k < order_count; ++k) logs[1 + k] = log_integral(curve, order_of(k), separation);
    knot_from_logs(curve, map, u, logs, data + j * 3, order_stride);
  }
}

// H = ln X - offset at the start of the integration, from the series of asperity/asymptotic.hpp.
// In the far tail the series is written in u = ln t itself (ln X + t without forming s^a - e^u,
// whose rounding would otherwise offset every curve by ~t eps).
State seed_state(const CurveId& curve, const SegmentMap& map, double u) {
  State state;
  for (int k = 0; k < order_count; ++k) {
    const double n = order_of(k);
    if (map.kind == SegmentKind::log_exponent) {
      const double t = std::exp(u);
      if (curve.distribution == Distribution::gaussian) {  // ln s = (u + ln 2)/2
        const Series series = gaussian_tail_series(n);
        state[k] = -0.91893853320467274178 - (n + 1) * 0.5 * (u + 0.69314718055994530942) + series.log_constant +
                   std::log(sum_series(series, 1 / (2 * t)));
      } else {  // ln s = u/a
        const Series series = weibull_tail_series(curve.shape, n);
        state[k] = n * (1 / curve.shape - 1) * u + series.log_constant + std::log(sum_series(series, 1 / t));
      }
    } else if (map.kind == SegmentKind::gaussian_linear) {  // at s^2/2 = 760, the Watson series
      double separation, ds_du, d2s_du2;
      map.s_of_u(u, separation, ds_du, d2s_du2);
      state[k] = gaussian_tail_log(gaussian_tail_series(n), n, separation) - map.offset_value(n, u);
    } else {
      double separation, ds_du, d2s_du2;
      map.s_of_u(u, separation, ds_du, d2s_du2);
      state[k] = bounded_contact_log(bounded_contact_series(curve.shape, n), curve.shape, n, separation) -
                 map.offset_value(n, u);
    }
  }
  return state;
}

// Order 0 of the Weibull from its closed form instead of the integrated state, so it carries no
// drift: on the tail H_0 = ln J_0 + t = 0 exactly (J_0 = exp(-t) for s > 0, 1 for s <= 0); on
// the bounded side ln K_0 = ln(-expm1(-tau)).
void fill_order_zero(const CurveId& curve, const std::vector<SegmentMap>& maps,
                     const std::vector<SegmentSpec>& layout, double* data) {
  std::size_t knot = 0;
  for (std::size_t index = 0; index < maps.size(); ++index) {
    const SegmentMap& map = maps[index];
    for (int j = 0; j < layout[index].knots; ++j, ++knot) {
      double* out = data + knot * 3;
      if (curve.side == Side::tail) {
        out[0] = out[1] = out[2] = 0;
        continue;
      }
      const double u = knot_u(map, layout[index].knots, j);
      if (map.kind == SegmentKind::reciprocal && j == 0) {  // s = -inf: K_0 = 1
        out[0] = out[1] = out[2] = 0;
        continue;
      }
      double separation, ds_du, d2s_du2, offset, d1, d2;
      map.s_of_u(u, separation, ds_du, d2s_du2);
      map.offset(0.0, u, offset, d1, d2);
      const double log_value = std::log(-std::expm1(-std::pow(-separation, curve.shape)));
      double slope, second_ratio;
      order_zero(curve, separation, log_value, slope, second_ratio);
      const double curvature = second_ratio - slope * slope;
      out[0] = log_value - offset;
      out[1] = slope * ds_du - d1;
      out[2] = curvature * ds_du * ds_du + slope * d2s_du2 - d2;
    }
  }
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
  const std::vector<SegmentMap> maps = SegmentMap::resolve(layout, curve.distribution, curve.side, shape);
  Logs logs{};
  bool have_state = false;
  for (int index = last; index >= 0; --index) {
    const SegmentMap& map = maps[index];
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
    State state;
    if (have_state)
      for (int k = 0; k < order_count; ++k) state[k] = logs[1 + k] - map.offset_value(order_of(k), times[0]);
    else
      state = seed_state(curve, map, times[0]);

    ChainSystem system{curve, map};
    int observed = 0;
    auto observer = [&](const State& h, double u) {
      Logs knot_logs;
      double separation, ds_du, d2s_du2;
      map.s_of_u(u, separation, ds_du, d2s_du2);
      knot_logs[0] = separation == 0 ? 0.0 : log_integral(curve, -0.5, separation);  // unused at s = 0
      for (int k = 0; k < order_count; ++k) knot_logs[1 + k] = h[k] + map.offset_value(order_of(k), u);
      knot_from_logs(curve, map, u, knot_logs, segment_data + static_cast<std::size_t>(knot_index[observed]) * 3,
                     order_stride);
      logs = knot_logs;
      ++observed;
    };
    // a small first step: for large shapes the chain is stiff near the far tail (rates ~ a s^(a-1)),
    // and an over-long first step can be accepted on an error estimate that is already unstable
    const double step = (times[1] - times[0]) * 1e-3;
    auto stepper = odeint::make_controlled(options.tolerance, options.tolerance,
                                           odeint::runge_kutta_fehlberg78<State>());
    odeint::integrate_times(stepper, system, state, times.begin(), times.end(), step, observer);
    if (observed != knots) throw Error("odeint did not reach every knot");
    have_state = true;
  }
  if (curve.distribution == Distribution::weibull) fill_order_zero(curve, maps, layout, data.data());
  for (std::size_t i = 0; i < data.size(); ++i)
    if (!std::isfinite(data[i])) {
      // where: order, knot (counted over all segments), component (H, dH/du, d2H/du2)
      const std::size_t component = i % 3, knot = (i / 3) % static_cast<std::size_t>(total), order = i / order_stride;
      std::size_t segment = 0;
      while (segment + 1 < layout.size() && knot >= static_cast<std::size_t>(first[segment + 1])) ++segment;
      throw Error("the chain produced a value that is not finite (shape " + std::to_string(shape) +
                               ", order " + std::to_string(order_of(static_cast<int>(order))) + ", segment " +
                               std::to_string(segment) + ", knot " + std::to_string(knot - first[segment]) +
                               ", component " + std::to_string(component) + ")");
    }
  return data;
}

}  // namespace asperity::generator
