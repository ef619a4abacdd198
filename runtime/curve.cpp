#include "asperity/curve.hpp"

#include <cmath>
#include <limits>

#include "asperity/detail/quintic_hermite.hpp"
#include "asperity/error.hpp"

namespace asperity {

Curve::Curve(Distribution distribution, Side side, double shape,
             const std::vector<SegmentSpec>& layout, const double* knot_data)
    : distribution_(distribution), side_(side), shape_(shape) {
  if (layout.empty() || layout.size() > static_cast<std::size_t>(max_segments))
    throw Error("curve layout must have 1 to 6 segments");
  segment_count_ = static_cast<int>(layout.size());
  const std::vector<SegmentMap> maps = SegmentMap::resolve(layout, distribution, side, shape);
  for (int index = 0; index < segment_count_; ++index) {
    Segment& segment = segments_[index];
    segment.map = maps[index];
    segment.knots = layout[index].knots;
    segment.first_knot = total_knots_;
    segment.inv_step = (segment.knots - 1) / (segment.map.u_hi - segment.map.u_lo);
    total_knots_ += segment.knots;
  }
  knots_.assign(knot_data, knot_data + static_cast<std::size_t>(order_count) * total_knots_ * 3);
  for (int order = 0; order < order_count; ++order)
    for (int index = 0; index < segment_count_; ++index) {
      const Segment& segment = segments_[index];
      const double step = 1 / segment.inv_step;
      double* knot = &knots_[(static_cast<std::size_t>(order) * total_knots_ + segment.first_knot) * 3];
      for (int j = 0; j < segment.knots; ++j, knot += 3) {
        knot[1] *= step;
        knot[2] *= step * step;
      }
    }
  for (int order = 0; order < order_count; ++order) {
    const double n = order_of(order);
    if (side == Side::bounded) series_[order] = bounded_contact_series(shape, n);
    else if (distribution == Distribution::gaussian) series_[order] = gaussian_tail_series(n);
    else series_[order] = weibull_tail_series(shape, n);
  }
}

double Curve::value(int twice_order, double separation) const noexcept {
  return std::exp(log_value(twice_order, separation));
}

double Curve::beyond_table(int twice_order, double separation) const noexcept {
  const double n = order_of(twice_order);
  if (side_ == Side::bounded) {
    if (separation >= 0) return -std::numeric_limits<double>::infinity();
    return bounded_contact_log(series_[twice_order], shape_, n, separation);
  }
  if (distribution_ == Distribution::gaussian)
    return gaussian_tail_log(series_[twice_order], n, separation);
  return weibull_tail_log(series_[twice_order], shape_, n, separation);
}

double Curve::log_value(int twice_order, double separation) const noexcept {
  if (static_cast<unsigned>(twice_order) >= static_cast<unsigned>(order_count))
    return std::numeric_limits<double>::quiet_NaN();
  double out;
  log_values(separation, twice_order, twice_order + 1, &out);
  return out;
}

void Curve::log_values(double separation, double out[order_count]) const noexcept {
  log_values(separation, 0, order_count, out);
}

// One segment search and one map for every order in [first, last): the cost of several orders
// is one lookup plus a Hermite step and an offset each.
void Curve::log_values(double separation, int first, int last, double* out) const noexcept {
  if (!std::isfinite(separation) || segment_count_ == 0) {
    for (int k = first; k < last; ++k) out[k - first] = std::numeric_limits<double>::quiet_NaN();
    return;
  }
  if (separation > segments_[segment_count_ - 1].map.s_hi) {
    for (int k = first; k < last; ++k) out[k - first] = beyond_table(k, separation);
    return;
  }
  const Segment* segment = &segments_[0];
  while (separation > segment->map.s_hi) ++segment;
  const SegmentMap& map = segment->map;

  // u, and the offset as base + per_order * n
  double u, base = 0, per_order = 0;
  switch (map.kind) {
    case SegmentKind::reciprocal:
      u = std::sqrt(map.p0 / separation);
      per_order = std::log(-separation);
      break;
    case SegmentKind::linear:
      u = separation;
      break;
    case SegmentKind::graded:
      u = std::cbrt(std::sqrt((separation - map.p0) / (map.p1 - map.p0)));
      if (map.exponent_offset) base = -std::pow(separation, shape_);
      break;
    case SegmentKind::log_exponent: {
      // t = exp(a ln s) instead of pow(s, a): three times faster; the rounding it adds to t,
      // t (ln t + 1) eps, is below 2e-13 of X wherever X >= 1e-100 (t <= 230).
      if (distribution_ == Distribution::gaussian) {
        base = -0.5 * separation * separation;
        u = std::log(-base);
      } else {
        u = map.shape * std::log(separation);
        base = -std::exp(u);
      }
      break;
    }
    case SegmentKind::log_distance:
      u = std::log(-separation);
      break;
    case SegmentKind::bounded_far:
      u = map.u_of_s(separation);
      break;
    default:  // log_tau: (n + a) ln d = u + n u / a
      u = map.shape * std::log(-separation);
      base = u;
      per_order = u / map.shape;
      break;
  }
  double position = (u - map.u_lo) * segment->inv_step;
  int interval = static_cast<int>(position);
  if (interval < 0) interval = 0;
  if (interval > segment->knots - 2) interval = segment->knots - 2;
  position -= interval;
  const std::size_t order_stride = static_cast<std::size_t>(total_knots_) * 3;
  const double* left = &knots_[(static_cast<std::size_t>(segment->first_knot + interval)) * 3 + first * order_stride];
  for (int k = first; k < last; ++k, left += order_stride)
    out[k - first] = base + per_order * order_of(k) + detail::quintic_hermite(left, left + 3, position);
}

}  // namespace asperity
