// What the lookup kernel needs of one segment of a curve, flattened for the hot path: the
// map from separation to the segment variable u (layout.hpp) as precomputed constants, and
// where the segment's interval coefficients start. Plain data; the kernel that reads it is
// runtime/core/kernel/curve_kernel.hpp.
#pragma once

namespace asperity::detail {

// The segment kinds of layout.hpp, with the far tail split by distribution (its map differs).
enum class KernelKind : int {
  reciprocal, linear, graded, graded_exponent, weibull_far, gaussian_far, log_tau, log_distance, bounded_far,
  gaussian_linear
};

struct KernelSegment {
  double s_hi = 0;            // the largest separation the segment covers
  double u_lo = 0;            // knots are uniform in u from u_lo with 1 / step = inv_step
  double inv_step = 0;
  double last_interval = 0;   // knots - 2, as a double (the clamp of the interval index)
  double p0 = 0;              // reciprocal: s1 (< 0); graded: the start of the segment
  double inv_range = 0;       // graded: 1 / (p1 - p0)
  double shape = 0;           // Weibull a (weibull_far, graded_exponent, log_tau)
  double shape_log_p1 = 0;    // graded_exponent: a ln p1, so that s^a = exp(a ln(s / p1) + a ln p1)
  double inv_span = 0;        // bounded_far: 1 / ln(s_lo / s_hi)
  double inv_power = 1.0 / 6; // graded: u = ((s - p0) / (p1 - p0))^inv_power
  KernelKind kind = KernelKind::linear;
  int first_interval = 0;     // index of the segment's first interval in the curve's coefficients
};

}  // namespace asperity::detail
