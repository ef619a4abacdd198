#include "asperity/contact.hpp"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

#include "asperity/detail/contact_ratio.hpp"

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

// The state from the four orders' logs and values (the ratio: contact_ratio.hpp's rule, which
// the kernels of Curve::contact_products apply too)
ASPERITY_ALWAYS_INLINE void state_of(const ContactScales& scales, const double logs[4], const double values[4],
                                     ContactState& state) noexcept {
  state.count = scales.count * values[orders::count];
  state.stiffness = scales.stiffness * values[orders::stiffness];
  state.area = scales.area * values[orders::area];
  state.load = scales.load * values[orders::load];
  state.stiffness_ratio = detail::contact_ratio(logs, values);
}
}  // namespace

ContactScales contact_scales(const SurfaceScales& surface) noexcept { return detail::contact_scales_of(surface); }

ContactState contact_state_from_logs(const ContactScales& scales, const double logs[4], const double values[4]) noexcept {
  ContactState state;
  state_of(scales, logs, values, state);
  return state;
}

namespace {
// contact_at's answer where its arguments passed their checks: one lookup for orders 0, 1/2, 1,
// 3/2, then the state; false and NaNs where they did not
bool answer(bool usable, const Curve& curve, const ContactScales& scales, double separation, ContactState& out) noexcept {
  if (!usable) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    out = {nan, nan, nan, nan, nan};
    return false;
  }
  double logs[4], values[4];
  curve.contact_orders(separation, logs, values);
  state_of(scales, logs, values, out);
  return true;
}
}  // namespace

// A physical surface's factors may overflow to inf: the surface is what is checked
bool detail::contact_at_checked(const Curve& curve, const SurfaceScales& surface, double separation,
                                ContactState& out) noexcept {
  const bool usable = positive_finite(surface.summit_count) & positive_finite(surface.summit_radius) &
                      positive_finite(surface.height_scale) & positive_finite(surface.contact_modulus) &
                      finite(separation) & curve.serves(separation);
  return answer(usable, curve, contact_scales_of(surface), separation, out);
}

bool detail::contact_at_checked(const Curve& curve, const ContactScales& scales, double separation,
                                ContactState& out) noexcept {
  const bool usable = positive_finite(scales.count) & positive_finite(scales.area) & positive_finite(scales.load) &
                      positive_finite(scales.stiffness) & finite(separation) & curve.serves(separation);
  return answer(usable, curve, scales, separation, out);
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
