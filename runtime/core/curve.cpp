#include "asperity/curve.hpp"

#include <cmath>
#include <limits>

#include "asperity/detail/quintic_hermite.hpp"
#include "asperity/error.hpp"
#include "kernel/curve_kernel.hpp"
#include "kernel/kernels.hpp"

namespace asperity {
namespace {

detail::KernelKind kernel_kind(const SegmentMap& map) {
  switch (map.kind) {
    case SegmentKind::reciprocal: return detail::KernelKind::reciprocal;
    case SegmentKind::linear: return detail::KernelKind::linear;
    case SegmentKind::graded: return map.exponent_offset ? detail::KernelKind::graded_exponent : detail::KernelKind::graded;
    case SegmentKind::log_exponent:
      return map.distribution == Distribution::gaussian ? detail::KernelKind::gaussian_far
                                                        : detail::KernelKind::weibull_far;
    case SegmentKind::log_tau: return detail::KernelKind::log_tau;
    case SegmentKind::log_distance: return detail::KernelKind::log_distance;
    case SegmentKind::bounded_far: return detail::KernelKind::bounded_far;
    case SegmentKind::gaussian_linear: return detail::KernelKind::gaussian_linear;
  }
  throw Error("unknown segment kind");
}

constexpr double not_a_number = std::numeric_limits<double>::quiet_NaN();

}  // namespace

Curve::Curve(Distribution distribution, Side side, double shape, const std::vector<SegmentSpec>& layout,
             const double* knot_data, unsigned order_mask)
    : distribution_(distribution), side_(side), shape_(shape), kernels_(&detail::kernels_for(InstructionSet::automatic)),
      order_mask_(order_mask & all_orders) {
  if (order_mask_ == 0) throw Error("a curve needs at least one order");
  if (layout.empty() || layout.size() > static_cast<std::size_t>(max_segments))
    throw Error("curve layout must have 1 to 6 segments");
  segment_count_ = static_cast<int>(layout.size());
  const std::vector<SegmentMap> maps = SegmentMap::resolve(layout, distribution, side, shape);
  int intervals = 0;
  for (int index = 0; index < segment_count_; ++index) {
    const SegmentMap& map = maps[index];
    detail::KernelSegment& segment = segments_[index];
    segment.kind = kernel_kind(map);
    segment.s_hi = map.s_hi;
    segment.u_lo = map.u_lo;
    segment.inv_step = (layout[index].knots - 1) / (map.u_hi - map.u_lo);
    segment.last_interval = layout[index].knots - 2;
    segment.p0 = map.p0;
    segment.inv_range = map.kind == SegmentKind::graded ? 1 / (map.p1 - map.p0) : 0;
    segment.shape = map.shape;
    segment.shape_log_p1 = segment.kind == detail::KernelKind::graded_exponent ? map.shape * std::log(map.p1) : 0;
    segment.inv_span = map.kind == SegmentKind::bounded_far ? 1 / map.span : 0;
    segment.inv_power = 1 / map.power;
    segment.first_interval = intervals;
    intervals += layout[index].knots - 1;
  }
  for (int k = 0; k < max_segments - 1; ++k)
    segment_ends_[k] = k < segment_count_ - 1 ? segments_[k].s_hi : std::numeric_limits<double>::infinity();
  table_min_separation_ = maps[segment_count_ > 1 ? 1 : 0].s_lo;
  table_max_separation_ = maps[segment_count_ - 1].s_hi;

  // Hermite data (H, dH/du, d2H/du2 at each knot) -> the quintic of each interval in x in [0, 1].
  const std::size_t order_stride = static_cast<std::size_t>(intervals) * 6;
  std::ptrdiff_t held = 0;
  for (int order = 0; order < order_count; ++order)
    order_offset_[order] = has_order(order) ? static_cast<std::ptrdiff_t>(order_stride) * held++ : -1;
  coefficients_.resize(order_stride * static_cast<std::size_t>(held));
  int total_knots = 0;
  for (const SegmentSpec& spec : layout) total_knots += spec.knots;
  for (int order = 0; order < order_count; ++order) {
    if (!has_order(order)) continue;
    int knot_offset = 0;
    for (int index = 0; index < segment_count_; ++index) {
      const detail::KernelSegment& segment = segments_[index];
      const double step = 1 / segment.inv_step;
      const double* knot = knot_data + (static_cast<std::size_t>(order) * total_knots + knot_offset) * 3;
      double* out = &coefficients_[order_offset_[order] + static_cast<std::ptrdiff_t>(segment.first_interval) * 6];
      for (int j = 0; j + 1 < layout[index].knots; ++j, knot += 3, out += 6) {
        const double left[3] = {knot[0], knot[1] * step, knot[2] * step * step};
        const double right[3] = {knot[3], knot[4] * step, knot[5] * step * step};
        detail::quintic_hermite_coefficients(left, right, out);
      }
      knot_offset += layout[index].knots;
    }
  }
  for (int order = 0; order < order_count; ++order) {
    const double n = order_of(order);
    if (side == Side::bounded) series_[order] = bounded_contact_series(shape, n);
    else if (distribution == Distribution::gaussian) series_[order] = gaussian_tail_series(n);
    else series_[order] = weibull_tail_series(shape, n);
  }
}

double Curve::log_value_outside(int twice_order, double separation) const noexcept {
  if (std::isnan(separation) || std::isinf(separation)) return not_a_number;
  const double n = order_of(twice_order);
  if (side_ == Side::bounded) {
    if (separation >= 0) return -std::numeric_limits<double>::infinity();
    return bounded_contact_log(series_[twice_order], shape_, n, separation);
  }
  if (distribution_ == Distribution::gaussian) return gaussian_tail_log(series_[twice_order], n, separation);
  return weibull_tail_log(series_[twice_order], shape_, n, separation);
}

// Inside the table: the number of segment ends below s (unused ends are +inf), without a
// data-dependent branch: a search loop mispredicts on separations that jump between segments.
ASPERITY_ALWAYS_INLINE const detail::KernelSegment& Curve::segment_of(double separation) const noexcept {
  const int index = (separation > segment_ends_[0]) + (separation > segment_ends_[1]) +
                    (separation > segment_ends_[2]) + (separation > segment_ends_[3]) +
                    (separation > segment_ends_[4]);
  return segments_[index];
}

namespace {
// Finite and not beyond the table's last knot (NaN fails both compares).
inline bool inside_table(double separation, double table_end) noexcept {
  return separation <= table_end && separation >= -std::numeric_limits<double>::max();
}
}  // namespace

double Curve::log_value(int twice_order, double separation) const noexcept {
  if (!has_order(twice_order)) return not_a_number;  // also a default Curve: it holds no order
  if (!inside_table(separation, table_max_separation_)) return log_value_outside(twice_order, separation);
  return detail::log_value_scalar<detail::LibraryMath>(segment_of(separation), order_coefficients(twice_order),
                                                       order_of(twice_order), separation);
}

double Curve::value(int twice_order, double separation) const noexcept {
  if (!has_order(twice_order)) return not_a_number;  // also a default Curve: it holds no order
  if (!inside_table(separation, table_max_separation_)) return std::exp(log_value_outside(twice_order, separation));
  return std::exp(detail::log_value_scalar<detail::LibraryMath>(segment_of(separation), order_coefficients(twice_order),
                                                                order_of(twice_order), separation));
}

void Curve::log_values(double separation, double out[order_count]) const noexcept {
  log_values(separation, 0, order_count - 1, out);
}

// One segment search and one map for every order asked: the cost of several orders is one
// lookup plus a Horner step each.
void Curve::log_values(double separation, int first, int last, double* out) const noexcept {
  if (first < 0 || last >= order_count || first > last) return;
  if (segment_count_ == 0) {
    for (int k = first; k <= last; ++k) out[k - first] = not_a_number;
    return;
  }
  if (!inside_table(separation, table_max_separation_)) {
    for (int k = first; k <= last; ++k) out[k - first] = has_order(k) ? log_value_outside(k, separation) : not_a_number;
    return;
  }
  const double* pointers[order_count];
  for (int k = 0; k < order_count; ++k) pointers[k] = order_coefficients(k);
  detail::log_values_scalar<detail::LibraryMath>(segment_of(separation), pointers, separation, first, last, out);
}

void Curve::contact_orders(double separation, double log_out[4], double value_out[4]) const noexcept {
  log_values(separation, 0, 3, log_out);
  if (kernels_) kernels_->exp4(log_out, value_out);
  else
    for (int k = 0; k < 4; ++k) value_out[k] = not_a_number;
}

void Curve::value_batch(int twice_order, const double* separations, double* out, std::size_t count,
                        InstructionSet isa) const noexcept {
  batch(twice_order, separations, out, count, isa, false);
}

void Curve::log_value_batch(int twice_order, const double* separations, double* out, std::size_t count,
                            InstructionSet isa) const noexcept {
  batch(twice_order, separations, out, count, isa, true);
}

void Curve::batch(int twice_order, const double* separations, double* out, std::size_t count, InstructionSet isa,
                  bool log_output) const noexcept {
  if (!has_order(twice_order)) {
    for (std::size_t i = 0; i < count; ++i) out[i] = not_a_number;
    return;
  }
  const detail::Kernels& kernels = isa == InstructionSet::automatic ? *kernels_ : detail::kernels_for(isa);
  const detail::KernelCurve curve{segments_.data(), segment_count_, order_coefficients(twice_order)};
  int rest[detail::batch_block];
  double block_separations[detail::batch_block];  // a copy, so that out may alias separations
  for (std::size_t start = 0; start < count; start += detail::batch_block) {
    const int block = static_cast<int>(count - start < detail::batch_block ? count - start : detail::batch_block);
    for (int j = 0; j < block; ++j) block_separations[j] = separations[start + j];
    const int rest_count = kernels.block(curve, twice_order, block_separations, out + start, block, log_output, rest);
    for (int r = 0; r < rest_count; ++r) {
      const double log_value = log_value_outside(twice_order, block_separations[rest[r]]);
      out[start + rest[r]] = log_output ? log_value : std::exp(log_value);
    }
  }
}

}  // namespace asperity
