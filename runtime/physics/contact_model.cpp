#include "asperity/contact_model.hpp"

#include <cmath>
#include <limits>

#include "asperity/error.hpp"

namespace asperity {
namespace {
constexpr double nan = std::numeric_limits<double>::quiet_NaN();
}  // namespace

ContactModel::ContactModel(const Table& table, const RoughSurface& surface) : surface_(surface) {
  surface_.validate();
  curve_ = table.curve(surface_.distribution, surface_.side, surface_.shape, contact_order_mask);
  load_inverse_ = InverseCurve(curve_, orders::load);
  area_inverse_ = InverseCurve(curve_, orders::area);
  scales_ = contact_scales({surface_.summit_count(), surface_.summit_radius, surface_.height_scale,
                            surface_.contact_modulus});
  if (surface_.distribution == Distribution::weibull)
    mean_offset_ = (surface_.side == Side::bounded ? -1 : 1) * weibull_mean(surface_.shape);
}

PhysicalState ContactModel::no_contact() const noexcept {
  PhysicalState state{};
  const bool bounded = surface_.side == Side::bounded;
  state.separation = bounded ? 0.0 : std::numeric_limits<double>::infinity();
  state.mean_separation = bounded ? -mean_offset_ * surface_.height_scale : state.separation;
  state.stiffness_over_load = nan;
  return state;
}

PhysicalState ContactModel::infinite_contact() const noexcept {
  const double inf = std::numeric_limits<double>::infinity();
  PhysicalState state{};
  state.separation = state.mean_separation = -inf;
  state.count = scales_.count;
  state.real_area = state.area_fraction = state.load = state.pressure = state.stiffness = inf;
  state.stiffness_over_load = 0;  // (3/2) X_1/2 / X_3/2 ~ (3/2)/|s| as s -> -inf
  return state;
}

PhysicalState ContactModel::state_at_dimensionless(double s) const noexcept {
  if (!curve_.has_order(orders::load)) return PhysicalState{nan, nan, nan, nan, nan, nan, nan, nan, nan};
  if (std::isnan(s)) return PhysicalState{nan, nan, nan, nan, nan, nan, nan, nan, nan};
  if (s == -std::numeric_limits<double>::infinity()) return infinite_contact();
  if (s == std::numeric_limits<double>::infinity() || (surface_.side == Side::bounded && s >= 0)) return no_contact();
  // contact_at's computation: one kernel call where it applies, else the logs and values
  ContactState contact;
  if (!curve_.contact_products(s, scales_.count, scales_.area, scales_.load, scales_.stiffness, &contact.count)) {
    double logs[4], values[4];
    curve_.contact_orders(s, logs, values);
    contact = contact_state_from_logs(scales_, logs, values);
  }
  const double sigma = surface_.height_scale;
  PhysicalState state;
  state.separation = s * sigma;
  state.mean_separation = (s - mean_offset_) * sigma;
  state.count = contact.count;
  state.real_area = contact.area;
  state.area_fraction = contact.area / surface_.nominal_area;
  state.load = contact.load;
  state.pressure = contact.load / surface_.nominal_area;
  state.stiffness = contact.stiffness;
  state.stiffness_over_load = contact.stiffness_ratio / sigma;  // K/P [1/m] = -(dP/ds)/P / sigma
  return state;
}

PhysicalState ContactModel::at_separation(double separation) const noexcept {
  return state_at_dimensionless(separation / surface_.height_scale);
}

PhysicalState ContactModel::at_load(double load) const noexcept {
  if (std::isnan(load)) return state_at_dimensionless(nan);
  if (load <= 0) return no_contact();
  if (load == std::numeric_limits<double>::infinity()) return infinite_contact();
  return state_at_dimensionless(load_inverse_.separation_at_log(std::log(load) - std::log(scales_.load)));
}

PhysicalState ContactModel::at_pressure(double pressure) const noexcept {
  return at_load(pressure * surface_.nominal_area);
}

PhysicalState ContactModel::at_real_area(double real_area) const noexcept {
  if (std::isnan(real_area)) return state_at_dimensionless(nan);
  if (real_area <= 0) return no_contact();
  if (real_area == std::numeric_limits<double>::infinity()) return infinite_contact();
  return state_at_dimensionless(area_inverse_.separation_at_log(std::log(real_area) - std::log(scales_.area)));
}

}  // namespace asperity
