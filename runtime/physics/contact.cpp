#include "asperity/contact.hpp"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

#include "asperity/detail/fast_math.hpp"

namespace asperity {
namespace {
// finite and > 0: as an unsigned integer, the bits of such a double lie in [1, bits of +inf)
ASPERITY_ALWAYS_INLINE std::uint64_t positive_finite(double value) {
  std::uint64_t bits;
  std::memcpy(&bits, &value, sizeof bits);
  return bits - 1 < 0x7ff0000000000000ull - 1;
}
ASPERITY_ALWAYS_INLINE std::uint64_t finite(double value) {
  std::uint64_t bits;
  std::memcpy(&bits, &value, sizeof bits);
  return (bits & 0x7fffffffffffffffull) < 0x7ff0000000000000ull;
}

// The bodies of contact_scales and contact_state_from_logs, inlined into contact_at, where no
// call or copy separates them from the lookup (bench_lookup BM_ContactAllFour).
ASPERITY_ALWAYS_INLINE ContactScales scales_of(const Surface& surface) noexcept {
  const double n = surface.summit_count, radius = surface.summit_radius, scale = surface.height_scale;
  const double modulus = surface.contact_modulus;
  ContactScales scales;
  scales.count = n;
  const double root = std::sqrt(radius * scale);  // one square root: R^(1/2) sigma^(3/2) = sigma sqrt(R sigma)
  scales.area = M_PI * n * radius * scale;
  scales.load = (4.0 / 3.0) * n * modulus * scale * root;
  scales.stiffness = 2 * n * modulus * root;
  return scales;
}

// The one rule for the stiffness/load ratio: X_1/2 / X_3/2 where both are normal doubles (one
// division), from the logs where they underflow (so that it stays finite there); NaN where
// X_3/2 is exactly 0 (no contact: 0/0).
ASPERITY_ALWAYS_INLINE void state_of(const ContactScales& scales, const double logs[4], const double values[4],
                                     ContactState& state) noexcept {
  state.count = scales.count * values[orders::count];
  state.stiffness = scales.stiffness * values[orders::stiffness];
  state.area = scales.area * values[orders::area];
  state.load = scales.load * values[orders::load];
  const double no_contact = -std::numeric_limits<double>::infinity();
  const double smallest_normal = std::numeric_limits<double>::min(), largest = std::numeric_limits<double>::max();
  const double stiffness = values[orders::stiffness], load = values[orders::load];
  if (__builtin_expect((stiffness >= smallest_normal) & (load >= smallest_normal) & (stiffness <= largest) &
                           (load <= largest),
                       1))
    state.stiffness_ratio = 1.5 * (stiffness / load);
  else
    state.stiffness_ratio = logs[orders::load] == no_contact ? std::numeric_limits<double>::quiet_NaN()
                                                             : 1.5 * std::exp(logs[orders::stiffness] - logs[orders::load]);
}
}  // namespace

ContactScales contact_scales(const Surface& surface) noexcept { return scales_of(surface); }

ContactState contact_state_from_logs(const ContactScales& scales, const double logs[4], const double values[4]) noexcept {
  ContactState state;
  state_of(scales, logs, values, state);
  return state;
}

bool contact_at(const Curve& curve, const Surface& surface, double separation, ContactState& out) noexcept {
  // on the bits, & rather than &&: one well-predicted branch for all five checks
  if (__builtin_expect(!(positive_finite(surface.summit_count) & positive_finite(surface.summit_radius) &
                         positive_finite(surface.height_scale) & positive_finite(surface.contact_modulus) &
                         finite(separation)),
                       0)) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    out = {nan, nan, nan, nan, nan};
    return false;
  }
  double logs[4], values[4];
  curve.contact_orders(separation, logs, values);  // one lookup for orders 0, 1/2, 1, 3/2
  state_of(scales_of(surface), logs, values, out);
  return true;
}

double standardized_from_origin(const Curve& curve, double separation) noexcept {
  if (curve.distribution() == Distribution::gaussian) return separation;
  const double shape = curve.shape();
  if (curve.side() == Side::bounded)  // heights mirrored: the mean summit sits at -mu_a
    return (separation + weibull_mean(shape)) / weibull_rms(shape);
  return (separation - weibull_mean(shape)) / weibull_rms(shape);
}

double origin_from_standardized(const Curve& curve, double standardized) noexcept {
  if (curve.distribution() == Distribution::gaussian) return standardized;
  const double shape = curve.shape();
  if (curve.side() == Side::bounded) return standardized * weibull_rms(shape) - weibull_mean(shape);
  return standardized * weibull_rms(shape) + weibull_mean(shape);
}

}  // namespace asperity
