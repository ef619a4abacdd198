// A curve in the table's own layout (layout.hpp): each segment's map to its variable u, the
// quintic of every interval from the stored Hermite data (H, dH/du, d2H/du2 at the knots), the
// series beyond the table and the exact values at s = 0. It answers ln X_n(s) for every s,
// one segment search and one map per call. It is the reference the runtime's fast grid is
// built from (fast_grid.hpp), and the answer where that grid does not reach.
#pragma once
#include <array>
#include <cstddef>
#include <memory>
#include <vector>

#include "asperity/asymptotic.hpp"
#include "asperity/detail/segment_map.hpp"
#include "asperity/layout.hpp"
#include "asperity/integrals.hpp"

namespace asperity::detail {

class NodeBlend;

class CompactCurve {
 public:
  CompactCurve() = default;
  // knot_data [order][knot][3] laid out by `layout`; only the orders in order_mask are kept.
  // Throws asperity::Error for a layout that does not tile the axis or a segment of fewer
  // than two knots.
  CompactCurve(Distribution distribution, Side side, double shape, const std::vector<SegmentSpec>& layout,
               const double* knot_data, unsigned order_mask);
  // The same over borrowed knots: nothing copied or converted, so made in microseconds; each
  // query makes its interval's quintic from the two knots (a few more operations). The caller
  // keeps knot_data alive as long as the curve.
  static CompactCurve borrowing(Distribution distribution, Side side, double shape,
                                const std::vector<SegmentSpec>& layout, const double* knot_data, unsigned order_mask);
  // A curve whose table part (every segment, the all-touching one too) is `blend`: a shape
  // between a table's nodes answered from the nodes (Table::direct_curve). Its series beyond
  // the table, its values at 0 and the Weibull order 0 are its own shape's.
  static CompactCurve blending(Distribution distribution, Side side, double shape,
                               const std::vector<SegmentSpec>& layout, std::shared_ptr<const NodeBlend> blend,
                               unsigned order_mask);

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
  CompactCurve(Distribution distribution, Side side, double shape, const std::vector<SegmentSpec>& layout,
               unsigned order_mask);  // the segments, series and values at 0; no interval data
  double table_log_value(int twice_order, std::size_t segment, std::ptrdiff_t interval, double position) const noexcept;
  std::ptrdiff_t knot_offset(int twice_order, std::size_t segment, std::ptrdiff_t interval) const noexcept;
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
  const double* knots_ = nullptr;          // borrowed [order][knot][3] instead of coefficients_
  std::shared_ptr<const NodeBlend> blend_;  // answers the table part instead of either
  std::array<std::ptrdiff_t, order_count> order_offset_{};
  std::array<Series, order_count> series_{};
  std::array<double, order_count> zero_log_{};
};

// Lagrange interpolation across a table's shape nodes at the same separation (Table::curve and
// Table::direct_curve between nodes): ln X_n(s) = sum_i w_i ln X_n(s; a_i), of ln X_n + s^a_i
// on the Weibull tail past s = 0, where ln X falls like -s^a and its shape dependence is
// exponential (blending ln X itself there is wrong by 1e-5 at t = 300).
class NodeBlend {
 public:
  // nodes[i] at shape shapes[i] with weight weights[i], borrowed: keep_alive owns them (and what
  // they borrow)
  NodeBlend(Distribution distribution, Side side, double shape, std::vector<double> shapes,
            std::vector<const CompactCurve*> nodes, std::vector<double> weights, std::shared_ptr<const void> keep_alive);
  // the same over nodes it owns
  NodeBlend(Distribution distribution, Side side, double shape, std::vector<double> shapes,
            std::vector<CompactCurve> owned, std::vector<double> weights);
  NodeBlend(const NodeBlend&) = delete;  // nodes_ may point into owned_
  NodeBlend& operator=(const NodeBlend&) = delete;
  // ln X_n(s) of every order into out[0..order_count) (NaN for an order the nodes do not hold)
  void log_values(double separation, double* out) const noexcept;

 private:
  std::vector<double> shapes_;
  std::vector<const CompactCurve*> nodes_;
  std::vector<double> weights_;
  double shape_;
  bool exponent_offset_;
  std::shared_ptr<const void> keep_alive_;
  std::vector<CompactCurve> owned_;
};

}  // namespace asperity::detail
