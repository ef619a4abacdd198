#include "asperity/inverse.hpp"

#include <algorithm>
#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <limits>

#include "asperity/error.hpp"

namespace asperity {
namespace {
constexpr double nan = std::numeric_limits<double>::quiet_NaN();
constexpr double y_step = 0.125;         // knots in y = ln X_n (cubic Hermite error ~ h^4 s''''/384)
constexpr double lowest_value = -690;    // ln 1e-300: below it the bisection path
// An interval whose single Newton step leaves ln X_n off the value by more than this (relative
// to 1 + |ln X_n|; a tenth of the tables' error, 1e-12) iterates to convergence instead. Tighter
// would take in the tables' own joins (steps of ~1e-13 in ln X_n between segments, which no
// iteration removes) and spend a second lookup there.
constexpr double accepted_miss = 1e-13;

// TOMS 748 (Boost.Math) on [a, b], f(a) and f(b) of opposite signs, to 50 bits: the final
// bracket's midpoint. Boost reports a bracket it cannot keep by exception; [a, b]'s midpoint then.
template <class Function>
double toms748_midpoint(Function f, double a, double b, double f_a, double f_b) noexcept {
  boost::uintmax_t iterations = 200;
  try {
    const auto bracket =
        boost::math::tools::toms748_solve(f, a, b, f_a, f_b, boost::math::tools::eps_tolerance<double>(50), iterations);
    return 0.5 * (bracket.first + bracket.second);
  } catch (...) {
    return 0.5 * (a + b);
  }
}
}  // namespace

// s in [lo, hi] where ln X_n(s) = log_value (ln X_n falls as s grows; lo may be -inf-ish
// deep, hi the end of contact), by TOMS 748 to a few ulps.
double InverseCurve::solve(double log_value, double lo, double hi) const noexcept {
  auto excess = [&](double separation) { return curve_.log_value(twice_order_, separation) - log_value; };
  const double at_lo = excess(lo), at_hi = excess(hi);
  if (!(at_lo >= 0)) return lo;  // deeper than lo reaches (or NaN)
  if (!(at_hi <= 0)) return hi;
  if (at_lo == 0) return lo;
  if (at_hi == 0) return hi;
  return toms748_midpoint(excess, lo, hi, at_lo, at_hi);
}

InverseCurve::InverseCurve(const Curve& curve, int twice_order) : curve_(curve), twice_order_(twice_order) {
  if (twice_order < 2 || twice_order >= order_count || !curve.has_order(twice_order) ||
      !curve.has_order(twice_order - 2))
    throw Error("an inverse needs the curve to hold orders n and n - 1, n >= 1");
  // The separations spanned: from deep contact to the far tail (tail side), or to first contact
  // (bounded side); the tabulated values are those between ln X = -690 and the deep-contact end.
  // A scene table's curve: only the separations it serves.
  const double s_deep = std::max(curve.table_min_separation() * 4, curve.served_min_separation());
  y_hi_ = curve.log_value(twice_order, s_deep);
  double hi = std::min(curve.side() == Side::bounded ? -1e-300 : curve.table_max_separation(),
                       curve.served_max_separation());
  if (curve.log_value(twice_order, hi) <= lowest_value) hi = solve(lowest_value, s_deep, hi);
  y_lo_ = curve.log_value(twice_order, hi);
  if (!(y_hi_ > y_lo_) || !std::isfinite(y_hi_) || !std::isfinite(y_lo_)) throw Error("an inverse: the curve is not monotone");
  intervals_ = std::max(4, static_cast<int>(std::ceil((y_hi_ - y_lo_) / y_step)));
  inv_step_ = intervals_ / (y_hi_ - y_lo_);
  const double step = 1 / inv_step_;
  knots_.resize(static_cast<std::size_t>(intervals_ + 1) * 2);
  // Each knot: solve ln X_n(s) = y bracketed by the previous knot, then polish.
  double previous = s_deep;
  for (int k = intervals_; k >= 0; --k) {  // from y_hi (deep contact) down, s increasing
    const double y = y_lo_ + (y_hi_ - y_lo_) * k / intervals_;
    const double separation = newton(solve(y, previous, hi), y);
    double lower[3];  // orders n - 1 (index 0) to n (index 2)
    curve.log_values(separation, twice_order - 2, twice_order, lower);
    const double slope = -0.5 * twice_order * std::exp(lower[0] - lower[2]);  // d ln X_n / ds
    knots_[2 * k] = separation;
    knots_[2 * k + 1] = step / slope;  // ds/dy times the step
    previous = separation;
  }
  // One Newton step squares the table step's error where ln X_n is smooth. Where it is not (the
  // Weibull tail side at s = 0: the density z^(a-1) starts there, so X_n's derivatives past the
  // order n + a are infinite) the step left errors up to 6e-5 in s (a = 0.5). Such intervals
  // are found here, each sampled at three points (ln X_n at the step against the value), and
  // their queries iterate to convergence (converge: safeguarded Newton); the others keep one step.
  // They lie around one point (s = 0): the iterated intervals are kept as one span, their hull,
  // so the query tests two integers beside the step's own.
  int first = intervals_, last = -1;
  for (int k = 0; k < intervals_; ++k)
    for (int j = 1; j < 4; ++j) {
      const double x = j / 4.0, y = y_lo_ + (k + x) / inv_step_;
      const double miss = curve_.log_value(twice_order_, newton(hermite(k, x), y)) - y;
      if (!(std::fabs(miss) <= accepted_miss * (1 + std::fabs(y)))) {
        first = std::min(first, k), last = std::max(last, k);
        break;
      }
    }
  converge_first_ = first;
  converge_count_ = static_cast<unsigned>(std::max(0, last - first + 1));
}

double InverseCurve::hermite(int interval, double x) const noexcept {
  const double s0 = knots_[2 * interval], d0 = knots_[2 * interval + 1];
  const double s1 = knots_[2 * interval + 2], d1 = knots_[2 * interval + 3];
  const double c2 = 3 * (s1 - s0) - 2 * d0 - d1, c3 = 2 * (s0 - s1) + d0 + d1;
  return s0 + x * (d0 + x * (c2 + x * c3));
}

// The root of ln X_n(s) = log_value in [lo, hi] from a start inside: Newton, kept inside the
// bracket that each step's sign narrows (bisection when a step leaves it), until ln X_n matches
// the value to its rounding or a step no longer moves s beyond rounding.
double InverseCurve::converge(double separation, double log_value, double lo, double hi) const noexcept {
  if (!(separation >= lo && separation <= hi)) separation = 0.5 * (lo + hi);
  for (int i = 0; i < 60; ++i) {
    double logs[3];
    curve_.log_values(separation, twice_order_ - 2, twice_order_, logs);
    const double excess = logs[2] - log_value;
    if (excess == 0 || std::isnan(excess)) return separation;
    if (excess > 0) lo = separation;  // ln X_n falls as s grows: the root lies beyond
    else hi = separation;
    const double slope = -0.5 * twice_order_ * std::exp(logs[0] - logs[2]);
    double next = separation - excess / slope;
    if (!(next >= lo && next <= hi)) next = 0.5 * (lo + hi);
    // within ln X_n's own rounding of the value: this last step is the polish
    if (std::fabs(excess) <= 4 * std::numeric_limits<double>::epsilon() * (1 + std::fabs(log_value))) return next;
    if (std::fabs(next - separation) <= 2 * std::numeric_limits<double>::epsilon() * std::fabs(separation) ||
        next == lo || next == hi)
      return next;
    separation = next;
  }
  return separation;
}

double InverseCurve::newton(double separation, double log_value) const noexcept {
  double logs[3];
  curve_.log_values(separation, twice_order_ - 2, twice_order_, logs);
  const double slope = -0.5 * twice_order_ * std::exp(logs[0] - logs[2]);
  const double next = separation - (logs[2] - log_value) / slope;
  // a step out of what the curve serves (an ulp past a scene table's range end) is no polish
  return std::isfinite(next) && curve_.serves(next) ? next : separation;
}

// A value just past the served range's end by the rounding of ln X there (a caller's
// ln(value(end))) is that end; further is NaN.
double InverseCurve::at_range_end(double end, double log_value) const noexcept {
  const double at_end = curve_.log_value(twice_order_, end);
  return std::fabs(at_end - log_value) <= 64 * std::numeric_limits<double>::epsilon() * (1 + std::fabs(log_value))
             ? end
             : nan;
}

// Values the table does not hold: deeper than its deep end (grow the bracket toward -inf), or
// below ln X = -690 (grow it toward +inf on the tail side; up to first contact on the bounded).
// The brackets stay within the separations the curve serves (a scene table's range): NaN for
// a value the served separations do not reach.
double InverseCurve::untabulated(double log_value) const noexcept {
  const double range_min = curve_.served_min_separation(), range_max = curve_.served_max_separation();
  double lo, hi;
  if (log_value > y_hi_) {
    hi = knots_[2 * intervals_];
    lo = hi;
    for (int i = 0; i < 1100 && lo > range_min && curve_.log_value(twice_order_, lo) < log_value; ++i)
      lo = std::max(lo * 2 - 1, range_min);
    if (lo <= range_min && !(curve_.log_value(twice_order_, lo) >= log_value))  // stopped by the range
      return at_range_end(lo, log_value);
  } else {
    lo = knots_[0];
    hi = curve_.side() == Side::bounded ? -1e-300 : lo + 1;  // the bounded side: up to first contact
    hi = std::min(hi, range_max);
    for (int i = 0; i < 2000 && curve_.side() == Side::tail && hi < range_max &&
                    curve_.log_value(twice_order_, hi) > log_value;
         ++i)
      hi = std::min(lo + (hi - lo) * 2, range_max);
    if (hi >= range_max && !(curve_.log_value(twice_order_, hi) <= log_value))  // stopped by the range
      return at_range_end(hi, log_value);
    if (curve_.side() == Side::bounded && hi < 0) return solve_near_first_contact(log_value, lo, hi);
  }
  return solve(log_value, lo, hi);
}

// Near a bounded side's first contact ln X_n ~ (n + a) ln|s| + c over hundreds of decades of s
// (lo ~ -1e-150 to hi = -1e-300): TOMS 748 in s itself ends its iterations with the bracket
// still decades wide, so the root is found in u = ln(-s), where ln X_n is nearly linear.
double InverseCurve::solve_near_first_contact(double log_value, double lo, double hi) const noexcept {
  auto excess = [&](double u) { return curve_.log_value(twice_order_, -std::exp(u)) - log_value; };
  const double u_lo = std::log(-hi), u_hi = std::log(-lo);  // ln X_n grows with u
  const double at_lo = excess(u_lo), at_hi = excess(u_hi);
  if (!(at_lo <= 0)) return hi;  // below what hi reaches: first contact to its rounding
  if (!(at_hi >= 0)) return lo;
  if (at_lo == 0) return hi;
  if (at_hi == 0) return lo;
  return -std::exp(toms748_midpoint(excess, u_lo, u_hi, at_lo, at_hi));
}

double InverseCurve::separation_at_log(double log_value) const noexcept {
  if (knots_.empty() || std::isnan(log_value)) return nan;
  if (log_value == std::numeric_limits<double>::infinity()) return -std::numeric_limits<double>::infinity();
  if (log_value == -std::numeric_limits<double>::infinity())
    return curve_.side() == Side::bounded ? 0.0 : std::numeric_limits<double>::infinity();
  if (!(log_value >= y_lo_ && log_value <= y_hi_)) {
    // beyond what the curve serves (a scene table's range): NaN, as its lookups there
    const double bracketed = untabulated(log_value);
    if (std::isnan(bracketed)) return nan;
    // TOMS 748's root is polished by one Newton step, unless the step crosses zero: near a
    // bounded side's first contact ln X_n ~ (n + a) ln|s|, and a step in s from 1e-167 toward
    // 1e-250 lands past first contact
    const double polished = newton(bracketed, log_value);
    const double separation = (polished < 0) == (bracketed < 0) ? polished : bracketed;
    return curve_.serves(separation) ? separation : nan;
  }
  double position = (log_value - y_lo_) * inv_step_;
  int interval = static_cast<int>(position);
  if (interval > intervals_ - 1) interval = intervals_ - 1;
  const double guess = hermite(interval, position - interval);
  if (static_cast<unsigned>(interval - converge_first_) < converge_count_)
    return converge(guess, log_value, knots_[2 * interval + 2], knots_[2 * interval]);
  return newton(guess, log_value);
}

double InverseCurve::separation_at(double value) const noexcept {
  if (std::isnan(value) || value < 0) return nan;
  return separation_at_log(std::log(value));
}

}  // namespace asperity
