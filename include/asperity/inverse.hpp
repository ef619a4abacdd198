// The inverse of a monotone curve: the separation where X_n takes a given value (the load,
// n = 3/2; the area, n = 1; the count, n = 0; any n > 0). ln X_n falls strictly as s grows, so
// s(ln X_n) is a function; it is tabulated once, when the inverse is made, and each query is one
// table step (cubic Hermite in y = ln X_n, uniform, O(1)) and one Newton step on the curve itself,
// which brings it to the curve's own accuracy (the Newton step squares the table's error). Where
// ln X_n is not smooth enough for that (the Weibull tail side near s = 0, where the density starts
// with z^(a-1)), the intervals found so when the inverse is made iterate a safeguarded Newton to
// convergence instead.
//
// Accuracy: the returned s reproduces ln X_n(s) = target within 1e-13 (1 + |target|), a tenth of
// the curve's own error, wherever the curve is continuous; where the curve itself steps by its
// rounding (between its segments, within ~1e-12 of s = 0), to that step (round-trip tested,
// densely around s = 0 and near first contact).
// Cost: about one forward lookup of two orders plus the table step (bench_lookup: BM_Inverse*);
// a few lookups in the iterated intervals.
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
  double hermite(int interval, double x) const noexcept;
  double newton(double separation, double log_value) const noexcept;
  double converge(double separation, double log_value, double lo, double hi) const noexcept;
  double solve(double log_value, double lo, double hi) const noexcept;
  double untabulated(double log_value) const noexcept;
  double solve_near_first_contact(double log_value, double lo, double hi) const noexcept;
  double at_range_end(double end, double log_value) const noexcept;

  Curve curve_;
  int twice_order_ = 3;
  double y_lo_ = 0, y_hi_ = 0, inv_step_ = 0;
  int intervals_ = 0;
  std::vector<double> knots_;  // per knot: s and ds/dy (times the step)
  int converge_first_ = 0;        // the intervals where one Newton step is not enough:
  unsigned converge_count_ = 0;   // [first, first + count), their hull
};

}  // namespace asperity
