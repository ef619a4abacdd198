#include "asperity/contact.hpp"

#include <cmath>
#include <limits>

namespace asperity {
namespace {
bool positive(double value) { return std::isfinite(value) && value > 0; }
}  // namespace

bool contact_at(const Curve& curve, const Surface& surface, double separation, ContactState& out) noexcept {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  out = {nan, nan, nan, nan, nan};
  if (!positive(surface.summit_count) || !positive(surface.summit_radius) ||
      !positive(surface.height_scale) || !positive(surface.contact_modulus) || !std::isfinite(separation))
    return false;
  const double n = surface.summit_count, radius = surface.summit_radius, scale = surface.height_scale;
  const double modulus = surface.contact_modulus;
  double logs[4], values[4];
  curve.contact_orders(separation, logs, values);  // one lookup for orders 0, 1/2, 1, 3/2
  const double count = values[0], half = values[1], area = values[2], three_halves = values[3];
  out.count = n * count;
  out.area = M_PI * n * radius * scale * area;
  out.load = (4.0 / 3.0) * n * modulus * std::sqrt(radius) * scale * std::sqrt(scale) * three_halves;
  out.stiffness = 2 * n * modulus * std::sqrt(radius * scale) * half;
  // the ratio from the logs where X_3/2 underflows (or is exactly 0: no contact, NaN)
  if (three_halves > 1e-300) out.stiffness_ratio = 1.5 * half / three_halves;
  else out.stiffness_ratio = std::isinf(logs[3]) ? nan : 1.5 * std::exp(logs[1] - logs[3]);
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
