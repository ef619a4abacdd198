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

// The quintic of the interval between knot[0..2] and knot[3..5] (H, dH/du, d2H/du2; u steps of
// `step`) in the power basis of x in [0, 1]
void hermite_to_power_basis(const double* knot, double step, double* out) {
  const double left[3] = {knot[0], knot[1] * step, knot[2] * step * step};
  const double right[3] = {knot[3], knot[4] * step, knot[5] * step * step};
  quintic_hermite_coefficients(left, right, out);
}

}  // namespace

CompactCurve::CompactCurve(Distribution distribution, Side side, double shape, const std::vector<SegmentSpec>& layout,
                           unsigned order_mask)
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
  for (int order = 0; order < order_count; ++order) {
    const double n = order_of(order);
    if (side == Side::bounded) series_[order] = bounded_contact_series(shape_, n);
    else if (distribution == Distribution::gaussian) series_[order] = gaussian_tail_series(n);
    else series_[order] = weibull_tail_series(shape_, n);
    zero_log_[order] = exact_log_value_at_zero(distribution, side, shape_, n);
  }
}

CompactCurve::CompactCurve(Distribution distribution, Side side, double shape, const std::vector<SegmentSpec>& layout,
                           const double* knot_data, unsigned order_mask)
    : CompactCurve(distribution, side, shape, layout, order_mask) {
  // Hermite data (H, dH/du, d2H/du2 at each knot) -> the quintic of each interval in x in [0, 1].
  std::ptrdiff_t held = 0;
  for (int order = 0; order < order_count; ++order)
    order_offset_[order] = has_order(order) ? total_intervals_ * 6 * held++ : -1;
  coefficients_.resize(static_cast<std::size_t>(total_intervals_) * 6 * held);
  for (int order = 0; order < order_count; ++order) {
    if (!has_order(order)) continue;
    for (std::size_t i = 0; i < maps_.size(); ++i)
      for (std::ptrdiff_t j = 0; j < intervals_[i]; ++j) {
        hermite_to_power_basis(knot_data + knot_offset(order, i, j), 1 / inverse_step_[i],
                               &coefficients_[order_offset_[order] + (first_[i] + j) * 6]);
      }
  }
}

CompactCurve CompactCurve::borrowing(Distribution distribution, Side side, double shape,
                                     const std::vector<SegmentSpec>& layout, const double* knot_data,
                                     unsigned order_mask) {
  CompactCurve curve(distribution, side, shape, layout, order_mask);
  curve.knots_ = knot_data;
  return curve;
}

CompactCurve CompactCurve::blending(Distribution distribution, Side side, double shape,
                                    const std::vector<SegmentSpec>& layout, std::shared_ptr<const NodeBlend> blend,
                                    unsigned order_mask) {
  CompactCurve curve(distribution, side, shape, layout, order_mask);
  curve.blend_ = std::move(blend);
  return curve;
}

void CompactCurve::keep_outside_only() {
  if (coefficients_.empty()) return;  // borrowed knots or a blend: nothing of its own to free
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
  double blend_values[order_count];
  bool blended = false;
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
      if (blend_) {  // the nodes' blend, every order at once
        if (!blended) blend_->log_values(separation, blend_values);
        blended = true;
        result = blend_values[k];
      } else if (intervals_[segment] == 0) {  // freed by keep_outside_only: the caller's grid answers here
        result = not_a_number;
      } else {
        result = table_log_value(k, segment, interval, position) + maps_[segment].offset_value(order_of(k), u);
      }
    }
  }
}

// Where an interval's left knot is in knot data [order][knot][3]: a segment of n intervals has n + 1
// knots, so the knots before segment i are first_[i] + i
std::ptrdiff_t CompactCurve::knot_offset(int twice_order, std::size_t segment, std::ptrdiff_t interval) const noexcept {
  const auto segments = static_cast<std::ptrdiff_t>(maps_.size());
  return (twice_order * (total_intervals_ + segments) + first_[segment] + static_cast<std::ptrdiff_t>(segment) +
          interval) * 3;
}

// The interval's quintic at x = position in [0, 1]: converted when the curve was made, or made
// now from the borrowed knots
double CompactCurve::table_log_value(int twice_order, std::size_t segment, std::ptrdiff_t interval,
                                     double position) const noexcept {
  double made[6];
  const double* c = made;
  if (knots_) {
    hermite_to_power_basis(knots_ + knot_offset(twice_order, segment, interval), 1 / inverse_step_[segment], made);
  } else {
    c = &coefficients_[order_offset_[twice_order] + (first_[segment] + interval) * 6];
  }
  const double x = position;
  return c[0] + x * (c[1] + x * (c[2] + x * (c[3] + x * (c[4] + x * c[5]))));
}

double CompactCurve::log_value(int twice_order, double separation) const noexcept {
  double result = not_a_number;
  if (twice_order >= 0 && twice_order < order_count) log_values(separation, twice_order, twice_order, &result);
  return result;
}

NodeBlend::NodeBlend(Distribution distribution, Side side, double shape, std::vector<double> shapes,
                     std::vector<const CompactCurve*> nodes, std::vector<double> weights,
                     std::shared_ptr<const void> keep_alive)
    : shapes_(std::move(shapes)), nodes_(std::move(nodes)), weights_(std::move(weights)), shape_(shape),
      exponent_offset_(distribution == Distribution::weibull && side == Side::tail),
      keep_alive_(std::move(keep_alive)) {
  if (shapes_.size() != nodes_.size() || shapes_.size() != weights_.size() || shapes_.empty())
    throw Error("a shape blend needs as many shapes, nodes and weights, at least one");
}

NodeBlend::NodeBlend(Distribution distribution, Side side, double shape, std::vector<double> shapes,
                     std::vector<CompactCurve> owned, std::vector<double> weights)
    : NodeBlend(distribution, side, shape, std::move(shapes), std::vector<const CompactCurve*>(owned.size()),
                std::move(weights), nullptr) {
  owned_ = std::move(owned);
  for (std::size_t i = 0; i < owned_.size(); ++i) nodes_[i] = &owned_[i];
}

void NodeBlend::log_values(double separation, double* out) const noexcept {
  if (nodes_.size() == 1 && weights_[0] == 1) {  // a node itself: its values, no offset to round
    nodes_[0]->log_values(separation, 0, order_count - 1, out);
    return;
  }
  for (int k = 0; k < order_count; ++k) out[k] = 0;
  const bool offset = exponent_offset_ && separation > 0;
  double node[order_count];
  for (std::size_t i = 0; i < nodes_.size(); ++i) {
    nodes_[i]->log_values(separation, 0, order_count - 1, node);
    const double t = offset ? std::pow(separation, shapes_[i]) : 0.0;
    for (int k = 0; k < order_count; ++k) out[k] += weights_[i] * (node[k] + t);
  }
  if (offset) {
    const double t = std::pow(separation, shape_);
    for (int k = 0; k < order_count; ++k) out[k] -= t;
  }
}

}  // namespace asperity::detail
