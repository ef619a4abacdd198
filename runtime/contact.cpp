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
  double logs[order_count];
  curve.log_values(separation, logs);  // one lookup for all four quantities
  const double log_half = logs[1], log_three_halves = logs[3];
  out.count = n * std::exp(logs[0]);
  out.area = M_PI * n * radius * scale * std::exp(logs[2]);
  out.load = (4.0 / 3.0) * n * modulus * std::sqrt(radius) * scale * std::sqrt(scale) * std::exp(log_three_halves);
  out.stiffness = 2 * n * modulus * std::sqrt(radius * scale) * std::exp(log_half);
  out.stiffness_ratio = std::isinf(log_three_halves) ? nan : 1.5 * std::exp(log_half - log_three_halves);
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
