// Physical quantities of docs/model.md section 3 from a resolved curve, and the two separation
// conventions of section 6. contact_at and ContactModel (contact_model.hpp) compute the same way:
// Curve::contact_products (one kernel call) where it applies, else contact_state_from_logs; both
// take the ratio by detail/contact_ratio.hpp's rule.
#pragma once
#include <cmath>

#include "asperity/contact_scales.hpp"
#include "asperity/curve.hpp"
#include "asperity/record_fields.hpp"

namespace asperity {

// The four scales a curve's quantities need: N summits of radius R, height scale sigma_s
// (Gaussian: rms summit height sigma), modulus E*. A RoughSurface (surface.hpp) is the surface
// in SI units they come from.
struct SurfaceScales {
  double summit_count = 1;    // N
  double summit_radius = 1;   // R
  double height_scale = 1;    // sigma_s
  double contact_modulus = 1; // E* (plane strain)
};

// The former name, kept for existing code (deprecated: to be removed; use SurfaceScales).
using Surface = SurfaceScales;

// contact_at's answer, in the units of the SurfaceScales given; its fields, defined once (a
// record's list, record_fields.hpp): the C API's asperity_contact_state, the Fortran type and
// Python's ContactState are checked against it (test_physical_state_fields). stiffness_ratio is
// taken from the logs: finite where the values underflow, NaN where there is no contact (X_3/2 = 0).
#define ASPERITY_CONTACT_STATE_FIELDS(X)                                                    \
  X(double, count, "count", "N X_0")                                                        \
  X(double, area, "area", "pi N R sigma_s X_1")                                             \
  X(double, load, "load", "(4/3) N E* R^1/2 sigma_s^3/2 X_3/2")                             \
  X(double, stiffness, "stiffness", "2 N E* R^1/2 sigma_s^1/2 X_1/2 (= -dP/d(separation))") \
  X(double, stiffness_ratio, "stiffness_ratio", "-(dP/ds)/P = (3/2) X_1/2 / X_3/2, in separation units")

struct ContactState {
  ASPERITY_CONTACT_STATE_FIELDS(ASPERITY_RECORD_MEMBER)
};
ASPERITY_DEFINE_RECORD(ContactState, ASPERITY_CONTACT_STATE_FIELDS)

// The factors of docs/model.md section 3, quantity = factor * X_n (ContactScales: contact_scales.hpp)
ContactScales contact_scales(const SurfaceScales& surface) noexcept;

// The state from ln X and X of orders 0, 1/2, 1, 3/2 (Curve::contact_orders).
ContactState contact_state_from_logs(const ContactScales& scales, const double logs[4], const double values[4]) noexcept;

// Returns false (and NaNs) for a non-physical surface (a value <= 0 or not finite), a
// NaN/infinite separation, or one the curve does not serve (Curve::serves: outside a scene
// table's range). Never throws or allocates. Inline (below): one call to the kernel
// built for this CPU, which computes the factors too (Curve::contact_products_of_surface); the
// rare rest out of line.
bool contact_at(const Curve& curve, const SurfaceScales& surface, double separation, ContactState& out) noexcept;
// The same with the factors computed once (contact_scales(surface)): a surface queried at many
// separations saves their square root and products on every query (bench_lookup
// BM_ContactAllFour against BM_ContactAllFourScales). False (and NaNs) where a factor is not in
// (0, DBL_MAX] or the separation is NaN, infinite or not served.
// (A name of its own: braces, contact_at(curve, {N, R, sigma_s, E*}, s, out), stay a SurfaceScales.)
bool contact_at_scales(const Curve& curve, const ContactScales& scales, double separation, ContactState& out) noexcept;

namespace detail {
inline ContactScales contact_scales_of(const SurfaceScales& surface) noexcept {
  return contact_scales_of(surface.summit_count, surface.summit_radius, surface.height_scale, surface.contact_modulus);
}
// contact_at off its fast path: the surface (or the factors) and the separation checked, then
// contact_orders and contact_state_from_logs
bool contact_at_checked(const Curve& curve, const SurfaceScales& surface, double separation, ContactState& out) noexcept;
bool contact_at_checked(const Curve& curve, const ContactScales& scales, double separation,
                        ContactState& out) noexcept;
}  // namespace detail

// The kernel tests the factors: all four in (0, DBL_MAX] holds only where N, R, sigma_s and E*
// are all > 0 and finite (count = N, area ~ N R sigma_s, stiffness ~ N E* (R sigma_s)^(1/2),
// load ~ stiffness sigma_s); where it fails, contact_at_checked tests the surface itself.
inline bool contact_at(const Curve& curve, const SurfaceScales& surface, double separation, ContactState& out) noexcept {
  static_assert(sizeof(ContactState) == 5 * sizeof(double), "Curve::contact_products writes the state as five doubles");
  if (__builtin_expect(curve.contact_products_of_surface(separation, surface.summit_count, surface.summit_radius,
                                                         surface.height_scale, surface.contact_modulus, &out.count),
                       1))
    return true;
  return detail::contact_at_checked(curve, surface, separation, out);
}

inline bool contact_at_scales(const Curve& curve, const ContactScales& scales, double separation,
                              ContactState& out) noexcept {
  if (__builtin_expect(curve.contact_products(separation, scales.count, scales.area, scales.load, scales.stiffness,
                                              &out.count),
                       1))
    return true;
  return detail::contact_at_checked(curve, scales, separation, out);
}

// Standardized separation (s - mu_a)/c_a (from the mean summit height, in rms units) and back.
// For the Gaussian both conventions coincide.
double standardized_from_origin(const Curve& curve, double separation) noexcept;
double origin_from_standardized(const Curve& curve, double standardized) noexcept;

}  // namespace asperity
