// What the laws' files share (runtime/core/laws/): the numbers, the checks of a factory's
// arguments, Hertz (every elastic-plastic law starts as it), the critical scales, and the
// built-in descriptors the registry lists (contact_law.hpp's ASPERITY_BUILT_IN_CONTACT_LAWS).
#pragma once
#include <cmath>
#include <limits>

#include "asperity/contact_law.hpp"
#include "asperity/contact_law_registry.hpp"
#include "asperity/law_combination.hpp"

namespace asperity::detail {

constexpr double pi = 3.14159265358979323846;
constexpr double nan = std::numeric_limits<double>::quiet_NaN();
constexpr double inf = std::numeric_limits<double>::infinity();

inline bool positive(double x) noexcept { return std::isfinite(x) && x > 0; }
inline bool poisson_ok(double nu) noexcept { return std::isfinite(nu) && nu >= 0 && nu <= 0.5; }

// The law's kind with every number NaN: what a factory returns for bad parameters.
ContactLaw bad_law(ContactLawKind kind) noexcept;

// Hertz: P = (4/3) E* R^1/2 w^3/2, A = pi R w, dP/dw = 2 E* (R w)^1/2: the numbers are
// law_combination.hpp's hertz_combination, the same that the rough-surface kernels multiply.
inline AsperityResponse hertz(double radius, double modulus, double w) noexcept {
  const double(&numbers)[4] = hertz_combination.multiplier;  // count, area, load, stiffness
  const double root = std::sqrt(radius * w);
  return {numbers[2] * modulus * root * w, numbers[1] * radius * w, numbers[3] * modulus * root};
}

// A law of `kind` with R and E* set (the rest to be set by its factory).
ContactLaw law_with(ContactLawKind kind, double radius, double modulus) noexcept;
// Elastic-plastic laws share: omega_c, P_c = Hertz at omega_c, A_c = pi R omega_c.
void set_critical(ContactLaw& law, double critical) noexcept;
// Adhesive laws' scales (Maugis' K = (4/3) E*): a_s = (pi dgamma R^2 / K)^(1/3), d_s = a_s^2 / R.
void set_adhesive_scales(ContactLaw& law) noexcept;
// From dimensionless (A, Pbar, dPbar/dD) to physical.
inline AsperityResponse adhesive_response(const ContactLaw& law, double a, double p, double dp_dd) noexcept {
  return {law.critical_load * p, law.critical_area * a * a, law.critical_load / law.critical_interference * dp_dd};
}

#define ASPERITY_DECLARE_LAW_DESCRIPTOR(kind, descriptor) extern const ContactLawDescriptor descriptor;
ASPERITY_BUILT_IN_CONTACT_LAWS(ASPERITY_DECLARE_LAW_DESCRIPTOR)
#undef ASPERITY_DECLARE_LAW_DESCRIPTOR

}  // namespace asperity::detail
