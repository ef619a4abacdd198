#include "asperity/inverse.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "asperity/error.hpp"

namespace asperity {
namespace {
constexpr double nan = std::numeric_limits<double>::quiet_NaN();
constexpr double y_step = 0.125;         // knots in y = ln X_n (cubic Hermite error ~ h^4 s''''/384)
constexpr double lowest_value = -690;    // ln 1e-300: below it the bisection path
}  // namespace

InverseCurve::InverseCurve(const Curve& curve, int twice_order) : curve_(&curve), twice_order_(twice_order) {
  if (twice_order < 2 || twice_order >= order_count || !curve.has_order(twice_order) ||
      !curve.has_order(twice_order - 2))
    throw Error("an inverse needs the curve to hold orders n and n - 1, n >= 1");
  // The separations spanned: from deep contact to the far tail (tail side), or to first contact
  // (bounded side); the tabulated values are those between ln X = -690 and the deep-contact end.
  const double s_deep = curve.table_min_separation() * 4;  // reciprocal segment: well inside
  y_hi_ = curve.log_value(twice_order, s_deep);
  // the far end: where ln X_n reaches lowest_value (bisection once, here)
  double lo = s_deep, hi = curve.side() == Side::bounded ? -1e-300 : curve.table_max_separation();
  if (curve.log_value(twice_order, hi) > lowest_value) {
    y_lo_ = curve.log_value(twice_order, hi);
  } else {
    for (int i = 0; i < 400 && hi - lo > 1e-13 * (1 + std::fabs(lo)); ++i) {
      const double middle = 0.5 * (lo + hi);
      (curve.log_value(twice_order, middle) > lowest_value ? lo : hi) = middle;
    }
    y_lo_ = curve.log_value(twice_order, lo);
    hi = lo;
  }
  if (!(y_hi_ > y_lo_) || !std::isfinite(y_hi_) || !std::isfinite(y_lo_)) throw Error("an inverse: the curve is not monotone");
  intervals_ = std::max(4, static_cast<int>(std::ceil((y_hi_ - y_lo_) / y_step)));
  inv_step_ = intervals_ / (y_hi_ - y_lo_);
  const double step = 1 / inv_step_;
  knots_.resize(static_cast<std::size_t>(intervals_ + 1) * 2);
  // Each knot: solve ln X_n(s) = y by bisection bracketed by the previous knot, then polish.
  double previous = s_deep;
  for (int k = intervals_; k >= 0; --k) {  // from y_hi (deep contact) down, s increasing
    const double y = y_lo_ + (y_hi_ - y_lo_) * k / intervals_;
    double a = previous, b = hi;
    for (int i = 0; i < 200 && b - a > 4e-16 * (std::fabs(a) + std::fabs(b)) + 1e-300; ++i) {
      const double middle = 0.5 * (a + b);
      (curve.log_value(twice_order, middle) > y ? a : b) = middle;
    }
    double separation = 0.5 * (a + b);
    separation = newton(separation, y);
    double lower[3];  // orders n - 1 (index 0) to n (index 2)
    curve.log_values(separation, twice_order - 2, twice_order, lower);
    const double slope = -0.5 * twice_order * std::exp(lower[0] - lower[2]);  // d ln X_n / ds
    knots_[2 * k] = separation;
    knots_[2 * k + 1] = step / slope;  // ds/dy times the step
    previous = separation;
  }
}

double InverseCurve::newton(double separation, double log_value) const noexcept {
  double logs[3];
  curve_->log_values(separation, twice_order_ - 2, twice_order_, logs);
  const double slope = -0.5 * twice_order_ * std::exp(logs[0] - logs[2]);
  const double next = separation - (logs[2] - log_value) / slope;
  return std::isfinite(next) ? next : separation;
}

double InverseCurve::bisection(double log_value) const noexcept {
  double lo = knots_.empty() ? -1e6 : knots_[2 * intervals_], hi;
  if (log_value > y_hi_) {  // deeper than the table: grow the bracket toward -inf
    hi = lo;
    for (int i = 0; i < 1100 && curve_->log_value(twice_order_, lo) < log_value; ++i) lo = lo * 2 - 1;
  } else {  // below the tabulated values
    lo = knots_[0];
    hi = curve_->side() == Side::bounded ? -0.0 : lo + 1;
    for (int i = 0; i < 2000 && curve_->side() == Side::tail && curve_->log_value(twice_order_, hi) > log_value; ++i)
      hi = lo + (hi - lo) * 2;
  }
  for (int i = 0; i < 2200 && hi - lo > 4e-16 * (std::fabs(lo) + std::fabs(hi)) + 1e-320; ++i) {
    const double middle = 0.5 * (lo + hi);
    (curve_->log_value(twice_order_, middle) > log_value ? lo : hi) = middle;
  }
  return 0.5 * (lo + hi);
}

double InverseCurve::separation_at_log(double log_value) const noexcept {
  if (!curve_ || std::isnan(log_value)) return nan;
  if (log_value == std::numeric_limits<double>::infinity()) return -std::numeric_limits<double>::infinity();
  if (log_value == -std::numeric_limits<double>::infinity())
    return curve_->side() == Side::bounded ? 0.0 : std::numeric_limits<double>::infinity();
  if (!(log_value >= y_lo_ && log_value <= y_hi_)) return newton(bisection(log_value), log_value);
  double position = (log_value - y_lo_) * inv_step_;
  int interval = static_cast<int>(position);
  if (interval > intervals_ - 1) interval = intervals_ - 1;
  const double x = position - interval;
  const double s0 = knots_[2 * interval], d0 = knots_[2 * interval + 1];
  const double s1 = knots_[2 * interval + 2], d1 = knots_[2 * interval + 3];
  // cubic Hermite in x
  const double c2 = 3 * (s1 - s0) - 2 * d0 - d1, c3 = 2 * (s0 - s1) + d0 + d1;
  const double guess = s0 + x * (d0 + x * (c2 + x * c3));
  return newton(guess, log_value);
}

double InverseCurve::separation_at(double value) const noexcept {
  if (std::isnan(value) || value < 0) return nan;
  return separation_at_log(std::log(value));
}

}  // namespace asperity
