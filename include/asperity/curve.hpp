// One resolved curve (distribution, side, shape): the hot handle. Immutable after it is
// built, so any number of threads may query it at once.
//
// Complexity: a query is O(1): a scan of at most six segment bounds, one map to the
// segment variable (a log, or a sixth root near s = 0), one quintic Hermite step and one
// exp. No allocation, no exception, no lock.
// Errors by value: NaN for a NaN or infinite separation or an order outside 0..5;
// value 0 (log -inf) where the integral is exactly 0 (bounded side, s >= 0).
#pragma once
#include <array>
#include <cstddef>
#include <vector>

#include "asperity/asymptotic.hpp"
#include "asperity/layout.hpp"
#include "asperity/model.hpp"

namespace asperity {

inline constexpr int max_segments = 6;

class Curve {
 public:
  Curve() = default;
  // Builds a curve from knot data [order][knot][3] (H, dH/du, d2H/du2) laid out by `layout`.
  Curve(Distribution distribution, Side side, double shape, const std::vector<SegmentSpec>& layout,
        const double* knot_data);

  // ln X_n(s), twice_order = 2n in 0..5, s in the origin convention of MODEL.md.
  double log_value(int twice_order, double separation) const noexcept;
  // X_n(s); underflows to 0 below ~1e-308 (use log_value there).
  double value(int twice_order, double separation) const noexcept;
  // ln X_n(s) of all six orders at once (one segment search and one map): out[twice_order].
  void log_values(double separation, double out[order_count]) const noexcept;

  Distribution distribution() const noexcept { return distribution_; }
  Side side() const noexcept { return side_; }
  double shape() const noexcept { return shape_; }
  // The separations the knots span from the end of the all-touching segment (which reaches
  // -inf) to the start of the series beyond the table (see asymptotic.hpp).
  double table_min_separation() const noexcept { return segments_[segment_count_ > 1 ? 1 : 0].map.s_lo; }
  double table_max_separation() const noexcept { return segments_[segment_count_ - 1].map.s_hi; }
  std::size_t memory_bytes() const noexcept { return sizeof(*this) + knots_.size() * sizeof(double); }

 private:
  struct Segment {
    SegmentMap map;
    double inv_step = 0;
    int knots = 0;
    int first_knot = 0;
  };
  double beyond_table(int twice_order, double separation) const noexcept;
  void log_values(double separation, int first, int last, double* out) const noexcept;

  Distribution distribution_ = Distribution::weibull;
  Side side_ = Side::tail;
  double shape_ = 0;
  int segment_count_ = 0;
  int total_knots_ = 0;
  std::array<Segment, max_segments> segments_{};
  std::array<Series, order_count> series_{};
  std::vector<double> knots_;  // [order][knot][3], derivatives scaled by the step
};

}  // namespace asperity
