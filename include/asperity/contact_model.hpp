// Contact of a flat with a physical rough surface (asperity/surface.hpp), forward and inverse:
// count, real area, load, nominal pressure and stiffness at a separation, and the separation
// that carries a load, a pressure or a real area. The inverses are tabulated once, when the
// model is made (asperity/inverse.hpp): a query is a table step and one Newton step.
//
// Separations are physical lengths [m] from the model's datum (asperity/separation_datum.hpp):
// by default the origin convention of docs/model.md, d = sigma_s * s, from the Weibull origin
// (the lowest summit on the tail side, the highest on the bounded side) or the Gaussian's mean
// summit height; or from the mean summit height (GW's and McCool's datum) or the mean plane.
// Every separation in and out (at_separation's argument, PhysicalState::separation, the
// inverses' answers) is in that datum; `mean_separation` is always from the mean summit height.
#pragma once
#include <cstddef>
#include <limits>
#include <string>

#include "asperity/contact.hpp"
#include "asperity/curve.hpp"
#include "asperity/inverse.hpp"
#include "asperity/physical_state_fields.hpp"
#include "asperity/separation_datum.hpp"
#include "asperity/surface.hpp"
#include "asperity/table.hpp"

namespace asperity {

// separation, mean_separation, count, real_area, area_fraction, load, pressure, stiffness,
// stiffness_over_load: doubles, their meanings and units in physical_state_fields.hpp
struct PhysicalState {
  ASPERITY_PHYSICAL_STATE_FIELDS(ASPERITY_RECORD_MEMBER)
};
ASPERITY_DEFINE_RECORD(PhysicalState, ASPERITY_PHYSICAL_STATE_FIELDS)
// The members in physical_state_fields' order (the writers and bindings iterate over them)
#define ASPERITY_PHYSICAL_STATE_POINTER(type, name, column, meaning) &PhysicalState::name,
inline constexpr double PhysicalState::*const physical_state_members[] = {
    ASPERITY_PHYSICAL_STATE_FIELDS(ASPERITY_PHYSICAL_STATE_POINTER)};
#undef ASPERITY_PHYSICAL_STATE_POINTER

// One field of PhysicalState, for the batch (ContactModel::at_separations); the names
// ("count", "real-area", "area-fraction", "load", "pressure", "stiffness") are the command's and Python's.
enum class ContactQuantity { count, real_area, area_fraction, load, pressure, stiffness };
inline constexpr int contact_quantity_count = 6;
const char* contact_quantity_name(ContactQuantity quantity) noexcept;
// The name as contact_quantity_name spells it, or as PhysicalState's field does ("real_area").
bool parse_contact_quantity(const std::string& name, ContactQuantity& quantity) noexcept;

// Above this real-area fraction A/A0 the model is past its validity: GW's asperities are
// independent Hertz contacts, which holds only while contacts are sparse. The command and the
// Python module warn there (asperity contact; asperity.AreaFractionWarning).
inline constexpr double gw_area_fraction_limit = 0.1;
// The one wording of that warning, for the command and Python: empty at or below the limit.
std::string gw_area_fraction_warning(double area_fraction);

// A model holds its curve and inverses by shared handles: copies are cheap and independent of
// the Table it was made from.
class ContactModel {
 public:
  ContactModel() = default;  // no surface: every query answers NaN
  // Throws asperity::Error for a bad surface (RoughSurface::validate), a table without its curve,
  // or a bad datum (separation_datum_position: mean_plane needs mean_summit_height [m], the mean
  // summit height above the mean plane; the other datums take none, NaN). An implausible surface
  // (a unit slip) is not an error: implausible_values (asperity/plausibility.hpp) says.
  ContactModel(const Table& table, const RoughSurface& surface, SeparationDatum datum = default_separation_datum,
               double mean_summit_height = std::numeric_limits<double>::quiet_NaN());

  // NaN everywhere for a NaN input. No contact (a load, pressure or area <= 0, or a separation
  // past the last summit: +inf on the tail side, >= 0 on the bounded side) gives count, area,
  // load, pressure and stiffness 0 and stiffness_over_load NaN (0/0), at separation +inf (tail
  // side) or 0 (bounded side: first contact). Infinite contact (a load, pressure or area of
  // +inf, or a separation of -inf) gives every summit in contact and infinite area, load and
  // stiffness. The inverses give the quantity asked back exactly as asked (at_pressure(p).pressure
  // is p; load and pressure differ by the nominal area's rounding), where they find a separation.
  PhysicalState at_separation(double separation) const noexcept;
  PhysicalState at_load(double load) const noexcept;
  PhysicalState at_pressure(double pressure) const noexcept;
  PhysicalState at_real_area(double real_area) const noexcept;

  // The batch: out[i] = at_separation(separations[i]).<quantity> for i < count, through the
  // curve's batch lookup (Curve::value_batch) and the factor: the same answer as at_separation
  // to the batch lookup's rounding (a few ulp of ln X: within 2e-14 (1 + |ln X|) relative,
  // tests/test_physical.cpp), and exactly at_separation's where it is not a normal positive
  // number: NaN (NaN input; outside a scene table's range), no contact (0), every summit in
  // contact (-inf), and products whose X_n under- or overflows (answered with at_separation's
  // arithmetic: its kernel call, the quantity's lane). No allocation, no throw; out may be
  // separations (not a partial overlap).
  void at_separations(ContactQuantity quantity, const double* separations, double* out,
                      std::size_t count) const noexcept;

  const RoughSurface& surface() const noexcept { return surface_; }
  const Curve& curve() const noexcept { return curve_; }
  SeparationDatum datum() const noexcept { return datum_; }
  double mean_summit_height() const noexcept { return mean_summit_height_; }  // above the mean plane; NaN unless mean_plane
  // Where the datum is, as an origin-convention separation [m] (separation_datum_position).
  double datum_position() const noexcept { return datum_offset_ * surface_.height_scale; }
  // The dimensionless separation s (origin convention) of a physical one in the model's datum.
  double dimensionless(double separation) const noexcept {
    return datum_offset_ == 0 ? separation / surface_.height_scale : separation / surface_.height_scale + datum_offset_;
  }

  // The range the model answers (a scene table's; everything for a full table's curves):
  // separations [m, the model's datum] from min_separation() to max_separation() (-inf to +inf
  // for a full table), and on the bounded side every separation at or past first contact (no
  // contact); the loads [N] and real areas [m^2] at those ends (0 to +inf for a full table).
  // Outside it every answer is NaN; `answers_separation` says where (false for NaN). The command
  // refuses such a query with this range, Python warns (asperity.OutOfRangeWarning).
  double min_separation() const noexcept;
  double max_separation() const noexcept;
  double min_load() const noexcept;
  double max_load() const noexcept;
  double min_real_area() const noexcept;
  double max_real_area() const noexcept;
  bool answers_separation(double separation) const noexcept;

 private:
  PhysicalState state_at_dimensionless(double s) const noexcept;
  PhysicalState no_contact() const noexcept;
  PhysicalState infinite_contact() const noexcept;

  RoughSurface surface_;
  Curve curve_;
  InverseCurve load_inverse_, area_inverse_;
  ContactScales scales_;
  double mean_offset_ = 0;   // the mean summit, origin convention, units of sigma_s
  SeparationDatum datum_ = default_separation_datum;
  double mean_summit_height_ = std::numeric_limits<double>::quiet_NaN();
  double datum_offset_ = 0;  // the datum, origin convention, units of sigma_s
  double physical(double s) const noexcept {
    return datum_offset_ == 0 ? s * surface_.height_scale : (s - datum_offset_) * surface_.height_scale;
  }
};

}  // namespace asperity
