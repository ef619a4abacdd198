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
#include <memory>

#include "asperity/curve.hpp"
#include "asperity/inverse.hpp"
#include "asperity/surface.hpp"
#include "asperity/table.hpp"

namespace asperity {

struct PhysicalState {
  double separation;           // d [m], origin convention
  double mean_separation;      // [m], from the mean summit height
  double count;                // summits in contact
  double real_area;            // A [m^2]
  double area_fraction;        // A / A0
  double load;                 // P [N]
  double pressure;             // P / A0 [Pa]
  double stiffness;            // K = -dP/dd [N/m]
  double stiffness_over_load;  // K / P [1/m]
};

class ContactModel {
 public:
  // Throws asperity::Error for a bad surface or a table without its curve.
  ContactModel(const Table& table, const PhysicalSurface& surface);
  ContactModel(const ContactModel&) = delete;
  ContactModel& operator=(const ContactModel&) = delete;
  ContactModel(ContactModel&&) = default;
  ContactModel& operator=(ContactModel&&) = default;

  // NaN everywhere for a NaN input; a load, pressure or area <= 0 gives the state at no contact
  // (tail side: separation +inf; bounded side: first contact, separation 0).
  PhysicalState at_separation(double separation) const noexcept;
  PhysicalState at_load(double load) const noexcept;
  PhysicalState at_pressure(double pressure) const noexcept;
  PhysicalState at_real_area(double real_area) const noexcept;

  const PhysicalSurface& surface() const noexcept { return surface_; }
  const Curve& curve() const noexcept { return *curve_; }
  // the dimensionless separation s of a physical one, and back
  double dimensionless(double separation) const noexcept { return separation / surface_.height_scale; }

 private:
  PhysicalState state_at_dimensionless(double s) const noexcept;

  PhysicalSurface surface_;
  std::unique_ptr<Curve> curve_;  // on the heap: the inverses point at it, and the model may move
  std::unique_ptr<InverseCurve> load_inverse_, area_inverse_;
  double count_scale_ = 0, area_scale_ = 0, load_scale_ = 0, stiffness_scale_ = 0, mean_offset_ = 0;
};

}  // namespace asperity
