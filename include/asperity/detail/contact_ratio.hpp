// The one rule for contact_at's stiffness/load ratio, -(dP/ds)/P = (3/2) X_1/2 / X_3/2: one
// division where both are normal doubles; from the logs where either underflows (so that it
// stays finite there); NaN where X_3/2 is exactly 0 (no contact: 0/0). Used by contact_at's
// kernels (runtime/core/kernel/) and by contact_state_from_logs (runtime/physics/contact.cpp).
#pragma once
#include <limits>

#include "asperity/detail/fast_math.hpp"
#include "asperity/model.hpp"

namespace asperity::detail {

// logs and values of orders 0, 1/2, 1, 3/2 (Curve::contact_orders)
static ASPERITY_ALWAYS_INLINE double contact_ratio(const double logs[4], const double values[4]) noexcept {
  const double smallest_normal = std::numeric_limits<double>::min(), largest = std::numeric_limits<double>::max();
  const double stiffness = values[orders::stiffness], load = values[orders::load];
  if (__builtin_expect((stiffness >= smallest_normal) & (load >= smallest_normal) & (stiffness <= largest) &
                           (load <= largest),
                       1))
    return 1.5 * (stiffness / load);
  if (logs[orders::load] == -std::numeric_limits<double>::infinity()) return std::numeric_limits<double>::quiet_NaN();
  return 1.5 * fast_exp(logs[orders::stiffness] - logs[orders::load]);
}

}  // namespace asperity::detail
