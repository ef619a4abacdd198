#include "asperity/contact_model.hpp"

#include <cmath>
#include <limits>

#include "asperity/error.hpp"

namespace asperity {
namespace {
constexpr double nan = std::numeric_limits<double>::quiet_NaN();
constexpr double pi = 3.14159265358979323846;
}  // namespace

ContactModel::ContactModel(const Table& table, const PhysicalSurface& surface) : surface_(surface) {
  surface_.validate();
  // orders 0, 1/2, 1, 3/2: count, stiffness, area, load
  curve_ = std::make_unique<Curve>(table.curve(surface_.distribution, surface_.side, surface_.shape, 0b1111u));
  load_inverse_ = std::make_unique<InverseCurve>(*curve_, 3);
  area_inverse_ = std::make_unique<InverseCurve>(*curve_, 2);
  const double n = surface_.summit_count(), radius = surface_.summit_radius, sigma = surface_.height_scale;
  const double modulus = surface_.contact_modulus;
  count_scale_ = n;
  area_scale_ = pi * n * radius * sigma;
  load_scale_ = (4.0 / 3.0) * n * modulus * std::sqrt(radius) * sigma * std::sqrt(sigma);
  stiffness_scale_ = 2 * n * modulus * std::sqrt(radius * sigma);
  if (surface_.distribution == Distribution::weibull)
    mean_offset_ = (surface_.side == Side::bounded ? -1 : 1) * weibull_mean(surface_.shape);
}

PhysicalState ContactModel::state_at_dimensionless(double s) const noexcept {
  PhysicalState state{};
  const double sigma = surface_.height_scale;
  state.separation = s * sigma;
  state.mean_separation = (s - mean_offset_) * sigma;
  if (std::isnan(s)) {
    state.count = state.real_area = state.area_fraction = state.load = state.pressure = state.stiffness =
        state.stiffness_over_load = nan;
    return state;
  }
  double logs[4], values[4];
  curve_->contact_orders(s, logs, values);
  state.count = count_scale_ * values[0];
  state.real_area = area_scale_ * values[2];
  state.area_fraction = state.real_area / surface_.nominal_area;
  state.load = load_scale_ * values[3];
  state.pressure = state.load / surface_.nominal_area;
  state.stiffness = stiffness_scale_ * values[1];
  // K/P = (3/2) X_1/2 / X_3/2 / sigma: from the logs where the values underflow
  state.stiffness_over_load = std::isinf(logs[3]) && logs[3] < 0 ? nan : 1.5 * std::exp(logs[1] - logs[3]) / sigma;
  return state;
}

PhysicalState ContactModel::at_separation(double separation) const noexcept {
  return state_at_dimensionless(separation / surface_.height_scale);
}

PhysicalState ContactModel::at_load(double load) const noexcept {
  if (std::isnan(load)) return state_at_dimensionless(nan);
  if (load <= 0) return state_at_dimensionless(load_inverse_->separation_at_log(-std::numeric_limits<double>::infinity()));
  return state_at_dimensionless(load_inverse_->separation_at_log(std::log(load) - std::log(load_scale_)));
}

PhysicalState ContactModel::at_pressure(double pressure) const noexcept {
  return at_load(pressure * surface_.nominal_area);
}

PhysicalState ContactModel::at_real_area(double real_area) const noexcept {
  if (std::isnan(real_area)) return state_at_dimensionless(nan);
  if (real_area <= 0)
    return state_at_dimensionless(area_inverse_->separation_at_log(-std::numeric_limits<double>::infinity()));
  return state_at_dimensionless(area_inverse_->separation_at_log(std::log(real_area) - std::log(area_scale_)));
}

}  // namespace asperity
