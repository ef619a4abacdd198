// Physical quantities of MODEL.md section 3 from a resolved curve, and the two separation
// conventions of section 6. contact_at and ContactModel (contact_model.hpp) compute through the
// one function here, contact_state_from_logs.
#pragma once
#include "asperity/curve.hpp"

namespace asperity {

// N summits of radius R, scale sigma_s (Gaussian: rms summit height sigma), modulus E*.
struct Surface {
  double summit_count = 1;    // N
  double summit_radius = 1;   // R
  double height_scale = 1;    // sigma_s
  double contact_modulus = 1; // E* (plane strain)
};

struct ContactState {
  double count;            // N X_0
  double area;             // pi N R sigma_s X_1
  double load;             // (4/3) N E* R^1/2 sigma_s^3/2 X_3/2
  double stiffness;        // 2 N E* R^1/2 sigma_s^1/2 X_1/2  (= -dP/d(separation))
  double stiffness_ratio;  // -(dP/ds)/P = (3/2) X_1/2 / X_3/2, in separation units (from the
                           // logs: finite where the values underflow; NaN where there is no
                           // contact, X_3/2 = 0)
};

// The factors of MODEL.md section 3: quantity = factor * X_n.
struct ContactScales {
  double count = 0;      // N
  double area = 0;       // pi N R sigma_s
  double load = 0;       // (4/3) N E* R^1/2 sigma_s^3/2
  double stiffness = 0;  // 2 N E* R^1/2 sigma_s^1/2
};
ContactScales contact_scales(const Surface& surface) noexcept;

// The state from ln X and X of orders 0, 1/2, 1, 3/2 (Curve::contact_orders).
ContactState contact_state_from_logs(const ContactScales& scales, const double logs[4], const double values[4]) noexcept;

// Returns false (and NaNs) for a non-physical surface (a value <= 0 or not finite) or a
// NaN/infinite separation. Never throws or allocates.
bool contact_at(const Curve& curve, const Surface& surface, double separation, ContactState& out) noexcept;

// Standardized separation (s - mu_a)/c_a (from the mean summit height, in rms units) and back.
// For the Gaussian both conventions coincide.
double standardized_from_origin(const Curve& curve, double separation) noexcept;
double origin_from_standardized(const Curve& curve, double standardized) noexcept;

}  // namespace asperity
