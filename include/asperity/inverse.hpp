// The inverse of a monotone curve: the separation where X_n takes a given value (the load,
// n = 3/2; the area, n = 1; the count, n = 0; any n > 0). ln X_n falls strictly as s grows, so
// s(ln X_n) is a function; it is tabulated once, when the inverse is made, and each query is one
// table step (cubic Hermite in y = ln X_n, uniform, O(1)) and one Newton step on the curve itself,
// which brings it to the curve's own accuracy (the Newton step squares the table's error).
//
// Accuracy: the returned s reproduces X_n(s) = target to the curve's error (round-trip tested).
// Cost: about one forward lookup of two orders plus the table step (bench_lookup: BM_Inverse*).
// Outside the tabulated values (the far tail below ~1e-300, deep all-touching contact, a bounded
// side near first contact) the table step is replaced by Boost.Math's TOMS 748 root finder on
// the curve (slower, rare). An inverse holds its curve (a shared handle): it may be copied and
// outlive the Curve it was made from.
#pragma once
#include <vector>

#include "asperity/curve.hpp"

namespace asperity {

class InverseCurve {
 public:
  InverseCurve() = default;
  // The curve must hold twice_order and twice_order - 2 (the slope d ln X_n/ds = -n X_(n-1)/X_n);
  // for n = 1/2 the slope is not available and the inverse refuses (asperity::Error).
  InverseCurve(const Curve& curve, int twice_order);

  // s with ln X_n(s) = log_value. NaN for NaN, and where s would lie outside the separations
  // the curve serves (Curve::serves: a scene table's range); +inf gives -inf (infinite contact);
  // -inf gives +inf on the tail side (no contact) and 0 on the bounded side (first contact).
  double separation_at_log(double log_value) const noexcept;
  double separation_at(double value) const noexcept;

  int twice_order() const noexcept { return twice_order_; }
  const Curve& curve() const noexcept { return curve_; }
  std::size_t memory_bytes() const noexcept { return sizeof(*this) + knots_.size() * sizeof(double); }

 private:
  double newton(double separation, double log_value) const noexcept;
  double solve(double log_value, double lo, double hi) const noexcept;
  double untabulated(double log_value) const noexcept;
  double at_range_end(double end, double log_value) const noexcept;

  Curve curve_;
  int twice_order_ = 3;
  double y_lo_ = 0, y_hi_ = 0, inv_step_ = 0;
  int intervals_ = 0;
  std::vector<double> knots_;  // per knot: s and ds/dy (times the step)
};

}  // namespace asperity
