#include "asperity/detail/compact_curve.hpp"

#include <algorithm>
#include <boost/math/special_functions/gamma.hpp>
#include <cmath>
#include <limits>

#include "asperity/detail/quintic_hermite.hpp"
#include "asperity/error.hpp"

namespace asperity::detail {
namespace {

constexpr double not_a_number = std::numeric_limits<double>::quiet_NaN();
constexpr double minus_infinity = -std::numeric_limits<double>::infinity();
// Below this |s| the tail and Gaussian curves are their value at 0 to rounding: the terms that
// move them, c s and c |s|^(n + a) with n + a >= 0.8, are below 1e-16 relative there.
constexpr double zero_zone = 8.470329472543003e-22;  // 2^-70

// ln X_n(0) of the tail side: the Weibull moments Gamma(1 + n/a); the Gaussian's half-line
// moments 2^((n-1)/2) Gamma((n+1)/2) / sqrt(2 pi).
double exact_log_value_at_zero(Distribution distribution, Side side, double shape, double order) {
  if (side == Side::bounded) return minus_infinity;
  if (distribution == Distribution::gaussian)
    return 0.5 * (order - 1) * std::log(2.0) + boost::math::lgamma(0.5 * (order + 1)) - 0.91893853320467274178;
  return boost::math::lgamma(1 + order / shape);
}

}  // namespace

CompactCurve::CompactCurve(Distribution distribution, Side side, double shape, const std::vector<SegmentSpec>& layout,
                           const double* knot_data, unsigned order_mask)
    : distribution_(distribution), side_(side), shape_(distribution == Distribution::gaussian ? 2.0 : shape),
      order_mask_(order_mask & ((1u << order_count) - 1)) {
  if (order_mask_ == 0) throw Error("a curve needs at least one order");
  if (layout.empty()) throw Error("a curve layout needs at least one segment");
  for (const SegmentSpec& spec : layout)
    if (spec.knots < 2) throw Error("a layout segment needs at least two knots");
  maps_ = SegmentMap::resolve(layout, distribution, side, shape_);
  const std::size_t segments = maps_.size();
  inverse_step_.resize(segments);
  first_.resize(segments);
  intervals_.resize(segments);
  for (std::size_t i = 0; i < segments; ++i) {
    first_[i] = total_intervals_;
    intervals_[i] = layout[i].knots - 1;
    inverse_step_[i] = intervals_[i] / (maps_[i].u_hi - maps_[i].u_lo);
    total_intervals_ += intervals_[i];
  }
  table_min_ = maps_[segments > 1 ? 1 : 0].s_lo;
  table_max_ = maps_.back().s_hi;

  // Hermite data (H, dH/du, d2H/du2 at each knot) -> the quintic of each interval in x in [0, 1].
  std::ptrdiff_t held = 0;
  for (int order = 0; order < order_count; ++order)
    order_offset_[order] = has_order(order) ? total_intervals_ * 6 * held++ : -1;
  coefficients_.resize(static_cast<std::size_t>(total_intervals_) * 6 * held);
  const std::ptrdiff_t total_knots = total_intervals_ + static_cast<std::ptrdiff_t>(segments);
  for (int order = 0; order < order_count; ++order) {
    if (!has_order(order)) continue;
    std::ptrdiff_t knot_offset = 0;
    for (std::size_t i = 0; i < segments; ++i) {
      const double step = 1 / inverse_step_[i];
      const double* knot = knot_data + (order * total_knots + knot_offset) * 3;
      double* out = &coefficients_[order_offset_[order] + first_[i] * 6];
      for (std::ptrdiff_t j = 0; j < intervals_[i]; ++j, knot += 3, out += 6) {
        const double left[3] = {knot[0], knot[1] * step, knot[2] * step * step};
        const double right[3] = {knot[3], knot[4] * step, knot[5] * step * step};
        quintic_hermite_coefficients(left, right, out);
      }
      knot_offset += layout[i].knots;
    }
  }
  for (int order = 0; order < order_count; ++order) {
    const double n = order_of(order);
    if (side == Side::bounded) series_[order] = bounded_contact_series(shape_, n);
    else if (distribution == Distribution::gaussian) series_[order] = gaussian_tail_series(n);
    else series_[order] = weibull_tail_series(shape_, n);
    zero_log_[order] = exact_log_value_at_zero(distribution, side, shape_, n);
  }
}

void CompactCurve::keep_outside_only() {
  const std::ptrdiff_t kept = intervals_[0];
  std::vector<double> outside;
  std::ptrdiff_t held = 0;
  for (int order = 0; order < order_count; ++order) {
    if (!has_order(order)) continue;
    const auto begin = coefficients_.begin() + order_offset_[order] + first_[0] * 6;
    outside.insert(outside.end(), begin, begin + kept * 6);
    order_offset_[order] = kept * 6 * held++;
  }
  coefficients_.swap(outside);
  coefficients_.shrink_to_fit();
  first_[0] = 0;
  for (std::size_t i = 1; i < intervals_.size(); ++i) intervals_[i] = 0;
  total_intervals_ = kept;
}

std::size_t CompactCurve::memory_bytes() const noexcept {
  return sizeof(*this) + coefficients_.capacity() * sizeof(double) + maps_.capacity() * sizeof(SegmentMap) +
         (inverse_step_.capacity() + first_.capacity() + intervals_.capacity()) * sizeof(double);
}

double CompactCurve::log_value_series(int twice_order, double separation) const noexcept {
  const double n = order_of(twice_order);
  if (side_ == Side::bounded) return bounded_contact_log(series_[twice_order], shape_, n, separation);
  if (distribution_ == Distribution::gaussian) return gaussian_tail_log(series_[twice_order], n, separation);
  return weibull_tail_log(series_[twice_order], shape_, n, separation);
}

// ln J_0 = -s^a (s > 0), ln K_0 = ln(1 - exp(-d^a)): exact, never from the table.
double CompactCurve::log_value_closed_order_zero(double separation) const noexcept {
  if (side_ == Side::tail) return separation > 0 ? -std::pow(separation, shape_) : 0.0;
  if (separation >= 0) return minus_infinity;
  // ln(1 - e^-tau), tau = d^a: from ln tau where tau would underflow (first contact)
  const double log_tau = shape_ * std::log(-separation);
  if (log_tau < -40) return log_tau - 0.5 * std::exp(log_tau);  // ln tau + ln(1 - tau/2 + ...)
  return std::log(-std::expm1(-std::exp(log_tau)));
}

void CompactCurve::log_values(double separation, int first, int last, double* out) const noexcept {
  if (first < 0 || last >= order_count || first > last) return;
  const bool finite = std::isfinite(separation);
  const bool inside = separation >= served_min_ && separation <= served_max_;
  const bool weibull = distribution_ == Distribution::weibull;
  std::size_t segment = maps_.size();  // not looked up yet
  double u = 0, position = 0;
  std::ptrdiff_t interval = 0;
  for (int k = first; k <= last; ++k) {
    double& result = out[k - first];
    if (!has_order(k) || !finite) {
      result = not_a_number;
    } else if (side_ == Side::bounded && separation >= 0) {
      result = minus_infinity;
    } else if (!inside) {  // beyond what a scene table modelled: refused, never a guess
      result = not_a_number;
    } else if (weibull && k == 0) {
      result = log_value_closed_order_zero(separation);
    } else if (side_ == Side::tail && std::fabs(separation) < zero_zone) {
      result = zero_log_[k];
    } else if (separation > table_max_) {
      result = log_value_series(k, separation);
    } else {
      if (segment == maps_.size()) {  // one segment search and one map for every order
        segment = 0;
        while (segment + 1 < maps_.size() && separation > maps_[segment].s_hi) ++segment;
        const SegmentMap& map = maps_[segment];
        u = map.u_of_s(separation);
        position = (u - map.u_lo) * inverse_step_[segment];
        position = position > 0 ? position : 0.0;
        const double last_cell = static_cast<double>(intervals_[segment] - 1);
        const double cell = position < last_cell ? std::floor(position) : last_cell;
        interval = static_cast<std::ptrdiff_t>(cell);
        position -= cell;
      }
      if (intervals_[segment] == 0) {  // freed by keep_outside_only: the caller's grid answers here
        result = not_a_number;
        continue;
      }
      const double* c = &coefficients_[order_offset_[k] + (first_[segment] + interval) * 6];
      const double x = position;
      const double h = c[0] + x * (c[1] + x * (c[2] + x * (c[3] + x * (c[4] + x * c[5]))));
      result = h + maps_[segment].offset_value(order_of(k), u);
    }
  }
}

double CompactCurve::log_value(int twice_order, double separation) const noexcept {
  double result = not_a_number;
  if (twice_order >= 0 && twice_order < order_count) log_values(separation, twice_order, twice_order, &result);
  return result;
}

}  // namespace asperity::detail
