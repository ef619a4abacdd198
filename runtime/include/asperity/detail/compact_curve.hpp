// A curve in the table's own layout (layout.hpp): each segment's map to its variable u, the
// quintic of every interval from the stored Hermite data (H, dH/du, d2H/du2 at the knots), the
// series beyond the table and the exact values at s = 0. It answers ln X_n(s) for every s,
// one segment search and one map per call. It is the reference the runtime's fast grid is
// built from (fast_grid.hpp), and the answer where that grid does not reach.
#pragma once
#include <array>
#include <cstddef>
#include <vector>

#include "asperity/asymptotic.hpp"
#include "asperity/detail/segment_map.hpp"
#include "asperity/layout.hpp"
#include "asperity/integrals.hpp"

namespace asperity::detail {

class CompactCurve {
 public:
  CompactCurve() = default;
  // knot_data [order][knot][3] laid out by `layout`; only the orders in order_mask are kept.
  // Throws asperity::Error for a layout that does not tile the axis or a segment of fewer
  // than two knots.
  CompactCurve(Distribution distribution, Side side, double shape, const std::vector<SegmentSpec>& layout,
               const double* knot_data, unsigned order_mask);

  // ln X_n(s) for twice_order = first..last into out[0..]; NaN for an order not held, for NaN
  // and for infinite s, and for s outside the served range; -inf where X is exactly 0 (bounded
  // side, s >= 0, wherever the served range ends).
  void log_values(double separation, int first, int last, double* out) const noexcept;
  double log_value(int twice_order, double separation) const noexcept;

  // Frees the interval data of every segment but the first (the all-touching one, below
  // table_min): what is left answers s < table_min, s > table_max, s = 0 and |s| < 2^-70.
  void keep_outside_only();
  // The separations answered (CurveOptions::served_min_separation ...); every s at first.
  void serve_only(double min_separation, double max_separation) noexcept {
    served_min_ = min_separation;
    served_max_ = max_separation;
  }
  double served_min() const noexcept { return served_min_; }
  double served_max() const noexcept { return served_max_; }
  // s in the served range, or the bounded side at s >= 0 (exactly 0); false for NaN
  bool serves(double separation) const noexcept {
    return (separation >= served_min_ && separation <= served_max_) || (side_ == Side::bounded && separation >= 0);
  }

  Distribution distribution() const noexcept { return distribution_; }
  Side side() const noexcept { return side_; }
  double shape() const noexcept { return shape_; }
  unsigned order_mask() const noexcept { return order_mask_; }
  double table_min() const noexcept { return table_min_; }
  double table_max() const noexcept { return table_max_; }
  // ln X_n(0): exact (the Weibull moments Gamma(1 + n/a), the Gaussian's half moments); -inf
  // on the bounded side.
  double log_value_at_zero(int twice_order) const noexcept { return zero_log_[twice_order]; }
  std::size_t memory_bytes() const noexcept;

 private:
  bool has_order(int twice_order) const noexcept { return order_mask_ >> twice_order & 1u; }
  double log_value_series(int twice_order, double separation) const noexcept;
  double log_value_closed_order_zero(double separation) const noexcept;

  Distribution distribution_ = Distribution::weibull;
  Side side_ = Side::tail;
  double shape_ = 0;
  unsigned order_mask_ = 0;
  double table_min_ = 0, table_max_ = 0;
  double served_min_ = -1.0 / 0.0, served_max_ = 1.0 / 0.0;
  std::vector<SegmentMap> maps_;
  std::vector<double> inverse_step_;       // per segment: intervals per unit of u
  std::vector<std::ptrdiff_t> first_;      // per segment: its first interval
  std::vector<std::ptrdiff_t> intervals_;  // per segment: its interval count (0 once freed)
  std::ptrdiff_t total_intervals_ = 0;
  std::vector<double> coefficients_;       // [held order][interval][6], power basis of x in [0, 1]
  std::array<std::ptrdiff_t, order_count> order_offset_{};
  std::array<Series, order_count> series_{};
  std::array<double, order_count> zero_log_{};
};

}  // namespace asperity::detail
