// Contact of a flat with a physical rough surface (asperity/surface.hpp), forward and inverse:
// count, real area, load, nominal pressure and stiffness at a separation, and the separation
// that carries a load, a pressure or a real area. The inverses are tabulated once, when the
// model is made (asperity/inverse.hpp): a query is a table step and one Newton step.
//
// Separations are physical lengths [m] in the origin convention of docs/model.md: d = sigma_s * s,
// from the Weibull origin (the lowest summit on the tail side, the highest on the bounded
// side) or the Gaussian's mean summit height. `mean_separation` gives the same point measured
// from the mean summit height, the convention of GW and McCool.
#pragma once
#include "asperity/contact.hpp"
#include "asperity/curve.hpp"
#include "asperity/inverse.hpp"
#include "asperity/physical_state_fields.hpp"
#include "asperity/surface.hpp"
#include "asperity/table.hpp"

namespace asperity {

// separation, mean_separation, count, real_area, area_fraction, load, pressure, stiffness,
// stiffness_over_load: doubles, their meanings and units in physical_state_fields.hpp
struct PhysicalState {
#define ASPERITY_PHYSICAL_STATE_MEMBER(name, column, meaning) double name;
  ASPERITY_PHYSICAL_STATE_FIELDS(ASPERITY_PHYSICAL_STATE_MEMBER)
#undef ASPERITY_PHYSICAL_STATE_MEMBER
};
// The members in physical_state_fields' order (the writers and bindings iterate over them)
#define ASPERITY_PHYSICAL_STATE_POINTER(name, column, meaning) &PhysicalState::name,
inline constexpr double PhysicalState::*const physical_state_members[] = {
    ASPERITY_PHYSICAL_STATE_FIELDS(ASPERITY_PHYSICAL_STATE_POINTER)};
#undef ASPERITY_PHYSICAL_STATE_POINTER

// A model holds its curve and inverses by shared handles: copies are cheap and independent of
// the Table it was made from.
class ContactModel {
 public:
  ContactModel() = default;  // no surface: every query answers NaN
  // Throws asperity::Error for a bad surface (RoughSurface::validate) or a table without its curve.
  ContactModel(const Table& table, const RoughSurface& surface);

  // NaN everywhere for a NaN input. No contact (a load, pressure or area <= 0, or a separation
  // past the last summit: +inf on the tail side, >= 0 on the bounded side) gives count, area,
  // load, pressure and stiffness 0 and stiffness_over_load NaN (0/0), at separation +inf (tail
  // side) or 0 (bounded side: first contact). Infinite contact (a load, pressure or area of
  // +inf, or a separation of -inf) gives every summit in contact and infinite area, load and
  // stiffness.
  PhysicalState at_separation(double separation) const noexcept;
  PhysicalState at_load(double load) const noexcept;
  PhysicalState at_pressure(double pressure) const noexcept;
  PhysicalState at_real_area(double real_area) const noexcept;

  const RoughSurface& surface() const noexcept { return surface_; }
  const Curve& curve() const noexcept { return curve_; }
  // the dimensionless separation s of a physical one, and back
  double dimensionless(double separation) const noexcept { return separation / surface_.height_scale; }

 private:
  PhysicalState state_at_dimensionless(double s) const noexcept;
  PhysicalState no_contact() const noexcept;
  PhysicalState infinite_contact() const noexcept;

  RoughSurface surface_;
  Curve curve_;
  InverseCurve load_inverse_, area_inverse_;
  ContactScales scales_;
  double mean_offset_ = 0;
};

}  // namespace asperity
