// The one rule for contact_at's stiffness/load ratio, -(dP/ds)/P = n X_{n-1} / X_n (the served
// combination's load order n, law_combination.hpp: Hertz's (3/2) X_1/2 / X_3/2), from
// what each path holds: contact_ratio from ln X and X (contact_state_from_logs,
// runtime/physics/contact.cpp: one division where both are normal doubles; from the logs where
// either underflows, so that it stays finite there), contact_ratio_of_parts and
// contact_ratio_of_log2s from X = m 2^k (the contact kernels, runtime/core/kernel/, whose records
// hold log2 X). NaN where X_3/2 is exactly 0 (no contact: 0/0).
#pragma once
#include <cmath>
#include <limits>

#include "asperity/detail/fast_math.hpp"
#include "asperity/contact_scales.hpp"
#include "asperity/integrals.hpp"

namespace asperity::detail {

// the paths below read the load and stiffness orders by their twice_order
static_assert(served_combination.twice_order[2] == orders::load && served_combination.twice_order[3] == orders::stiffness,
              "contact_ratio reads the served combination's load and stiffness orders");

// logs and values of orders 0, 1/2, 1, 3/2 (Curve::contact_orders)
static ASPERITY_ALWAYS_INLINE double contact_ratio(const double logs[4], const double values[4]) noexcept {
  const double smallest_normal = std::numeric_limits<double>::min(), largest = std::numeric_limits<double>::max();
  const double stiffness = values[orders::stiffness], load = values[orders::load];
  if (__builtin_expect((stiffness >= smallest_normal) & (load >= smallest_normal) & (stiffness <= largest) &
                           (load <= largest),
                       1))
    return served_combination.load_order * (stiffness / load);
  if (logs[orders::load] == -std::numeric_limits<double>::infinity()) return std::numeric_limits<double>::quiet_NaN();
  return served_combination.load_order * fast_exp(logs[orders::stiffness] - logs[orders::load]);
}

// The ratio -(dP/ds)/P = 1.5 X_1/2 / X_3/2 from X = m 2^k of each (m in [0.7, 1.5], k an
// integer): 1.5 (m_1/2 / m_3/2), rounded, then scaled by 2^(k_1/2 - k_3/2) (exactly, or rounded
// once where the result is subnormal): right where X_1/2 or X_3/2 underflows, with no test on
// them. The x86 kernels compute the same in vectors.
// x 2^k for an integer k held in a double (|k| up to 2^50: beyond +-2200 the result of a
// moderate x is 0 or inf anyway), rounded once as vscalefpd rounds: the contact kernels' scaling
static ASPERITY_ALWAYS_INLINE double scaled_by_power_of_two(double x, double k) noexcept {
  return std::ldexp(x, static_cast<int>(k < -2200 ? -2200 : k > 2200 ? 2200 : k));
}
static ASPERITY_ALWAYS_INLINE double contact_ratio_of_parts(double stiffness_mantissa, double stiffness_k,
                                                            double load_mantissa, double load_k) noexcept {
  return scaled_by_power_of_two(served_combination.load_order * (stiffness_mantissa / load_mantissa),
                                stiffness_k - load_k);
}
// The same from log2 X (the baseline build's; the x86 kernels' where a lane is not finite or
// beyond 2^50): NaN where X_3/2 = 0 (0/0) or a log is NaN, 0 where X_1/2 = 0 or X_3/2 = inf, inf
// where X_1/2 = inf
static ASPERITY_ALWAYS_INLINE double contact_ratio_of_log2s(double stiffness_log2, double load_log2) noexcept {
  constexpr double inf = __builtin_inf();
  if (!(load_log2 > -inf) || stiffness_log2 != stiffness_log2) return __builtin_nan("");
  if (stiffness_log2 == -inf || load_log2 == inf) return 0.0;
  if (stiffness_log2 == inf) return inf;
  const double stiffness_k = std::nearbyint(stiffness_log2), load_k = std::nearbyint(load_log2);
  return contact_ratio_of_parts(fast_exp2(stiffness_log2 - stiffness_k), stiffness_k, fast_exp2(load_log2 - load_k),
                                load_k);
}

}  // namespace asperity::detail
