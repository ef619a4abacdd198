// One resolved curve (distribution, side, shape): the hot handle. Immutable after it is
// built, so any number of threads may query it at once.
//
// Complexity: a query is O(1): a scan of at most six segment bounds, one map to the
// segment variable (a log, and an exp in the far tail and near s = 0), Horner's rule on the
// interval's quintic (six coefficients, one cache line) and one exp. The batch functions do
// the same arithmetic vectorized (runtime/core/kernel/). No allocation, no exception, no lock.
// Errors by value: NaN for a NaN or infinite separation or an order outside 0..5;
// value 0 (log -inf) where the integral is exactly 0 (bounded side, s >= 0).
#pragma once
#include <array>
#include <cstddef>
#include <vector>

#include "asperity/asymptotic.hpp"
#include "asperity/detail/kernel_segment.hpp"
#include "asperity/instruction_set.hpp"
#include "asperity/layout.hpp"
#include "asperity/model.hpp"

namespace asperity {
namespace detail {
struct Kernels;
}

inline constexpr int max_segments = 6;

class Curve {
 public:
  Curve() = default;
  // Builds a curve from knot data [order][knot][3] (H, dH/du, d2H/du2) laid out by `layout`,
  // keeping the orders whose bit (1 << twice_order) is set in order_mask: a curve of fewer
  // orders takes proportionally less memory, and answers NaN for the others.
  static constexpr unsigned all_orders = (1u << order_count) - 1;
  Curve(Distribution distribution, Side side, double shape, const std::vector<SegmentSpec>& layout,
        const double* knot_data, unsigned order_mask = all_orders);

  // ln X_n(s), twice_order = 2n in 0..5, s in the origin convention of docs/model.md.
  double log_value(int twice_order, double separation) const noexcept;
  // X_n(s); underflows to 0 below ~1e-308 (use log_value there).
  double value(int twice_order, double separation) const noexcept;
  // ln X_n(s) of all six orders at once (one segment search and one map): out[twice_order].
  void log_values(double separation, double out[order_count]) const noexcept;
  // ln X_n(s) for twice_order = first..last (inclusive): out[twice_order - first].
  void log_values(double separation, int first_twice_order, int last_twice_order, double* out) const noexcept;
  // Orders 0, 1/2, 1, 3/2 (count, stiffness, area, load: what contact_at needs), logs and
  // values, from one lookup and one vector exp.
  void contact_orders(double separation, double log_out[4], double value_out[4]) const noexcept;

  // The batch path: out[i] = value / log_value(twice_order, separations[i]) for i < count,
  // vectorized for the widest instruction set this CPU has (or the one named; a set it lacks
  // falls back to the best it has). Same results as the scalar functions to rounding.
  // A bad order gives NaN everywhere. out may alias separations.
  void value_batch(int twice_order, const double* separations, double* out, std::size_t count,
                   InstructionSet isa = InstructionSet::automatic) const noexcept;
  void log_value_batch(int twice_order, const double* separations, double* out, std::size_t count,
                       InstructionSet isa = InstructionSet::automatic) const noexcept;

  Distribution distribution() const noexcept { return distribution_; }
  unsigned order_mask() const noexcept { return order_mask_; }
  bool has_order(int twice_order) const noexcept {
    return static_cast<unsigned>(twice_order) < static_cast<unsigned>(order_count) && (order_mask_ >> twice_order & 1u);
  }
  Side side() const noexcept { return side_; }
  double shape() const noexcept { return shape_; }
  // The separations the knots span from the end of the all-touching segment (which reaches
  // -inf) to the start of the series beyond the table (see asymptotic.hpp).
  double table_min_separation() const noexcept { return table_min_separation_; }
  double table_max_separation() const noexcept { return table_max_separation_; }
  std::size_t memory_bytes() const noexcept { return sizeof(*this) + coefficients_.size() * sizeof(double); }

 private:
  // Where the kernel does not apply: NaN, infinities, and beyond the table (the series).
  double log_value_outside(int twice_order, double separation) const noexcept;
  const detail::KernelSegment& segment_of(double separation) const noexcept;
  void batch(int twice_order, const double* separations, double* out, std::size_t count, InstructionSet isa,
             bool log_output) const noexcept;

  Distribution distribution_ = Distribution::weibull;
  Side side_ = Side::tail;
  double shape_ = 0;
  int segment_count_ = 0;
  double table_min_separation_ = 0;
  double table_max_separation_ = 0;
  std::array<detail::KernelSegment, max_segments> segments_{};
  std::array<double, max_segments - 1> segment_ends_{};  // s_hi of all but the last, +inf padded
  const detail::Kernels* kernels_ = nullptr;  // the widest instruction set this CPU has
  std::array<Series, order_count> series_{};
  const double* order_coefficients(int twice_order) const noexcept {
    return order_offset_[twice_order] < 0 ? nullptr : coefficients_.data() + order_offset_[twice_order];
  }
  unsigned order_mask_ = 0;
  std::array<std::ptrdiff_t, order_count> order_offset_{};  // into coefficients_, -1: not held
  std::vector<double> coefficients_;   // [held order][interval][6]: the quintic in the power basis
};

}  // namespace asperity
