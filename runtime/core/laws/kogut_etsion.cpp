// Kogut & Etsion 2002: finite-element fits on [1, 6] and [6, 110] omega_c, fully plastic beyond
// (docs/contact-laws.md section 2).
#include "law_support.hpp"

namespace asperity {

// H = 2.8 Y, K = 0.454 + 0.41 nu, omega_c = (pi K H / (2 E*))^2 R.
ContactLaw kogut_etsion_law(double radius, double modulus, double yield_strength, double poisson) noexcept {
  const auto kind = ContactLawKind::kogut_etsion;
  if (!detail::positive(radius) || !detail::positive(modulus) || !detail::positive(yield_strength) ||
      !detail::poisson_ok(poisson))
    return detail::bad_law(kind);
  ContactLaw law = detail::law_with(kind, radius, modulus);
  law.yield_strength = yield_strength;
  law.hardness = 2.8 * yield_strength;
  law.poisson = poisson;
  law.pressure_factor = 0.454 + 0.41 * poisson;
  const double q = detail::pi * law.pressure_factor * law.hardness / (2 * modulus);
  detail::set_critical(law, q * q * radius);
  return law;
}

namespace detail {
namespace {

ContactLaw make(double radius, double modulus, const LawValues& v) noexcept {
  return kogut_etsion_law(radius, modulus, v[LawParameter::yield_strength], v[LawParameter::poisson]);
}

AsperityResponse response(const ContactLaw& law, double w) noexcept {
  // the branch by w against the switch points as switch_points() gives them (x = w/wc rounds to 6
  // within an ulp or two of 6 wc: the load's jump there was lost)
  const double wc = law.critical_interference, x = w / wc, pc = law.critical_load, ac = law.critical_area;
  if (w <= wc) return hertz(law.radius, law.modulus, w);
  double cp, ep, ca, ea;  // P/P_c = cp x^ep, A/A_c = ca x^ea
  if (w <= 6 * wc) {
    cp = 1.03, ep = 1.425, ca = 0.93, ea = 1.136;
  } else if (w <= 110 * wc) {
    cp = 1.40, ep = 1.263, ca = 0.94, ea = 1.146;
  } else if (std::isfinite(x) || !(wc > 0)) {  // fully plastic: A = 2 pi R w, P = H A, dP/dw = 2 pi R H
    // (x^0 = 1; an omega_c that underflowed to 0 stays NaN, 0 inf: the law divides by it)
    const double plastic = 3 / law.pressure_factor;  // P/P_c = (3/K) x, A/A_c = 2 x
    return {pc * plastic * x, ac * 2 * x, pc / wc * plastic};
  } else {  // w / w_c beyond the doubles (w > 1e300 m or so): the same in physical units (A may not overflow)
    const double area = 2 * pi * law.radius * w;
    return {law.hardness * area, area, 2 * pi * law.radius * law.hardness};
  }
  const double power = std::pow(x, ep);
  return {pc * cp * power, ac * ca * std::pow(x, ea), pc / wc * cp * ep * power / x};
}

constexpr LawParameterUse parameters[] = {{LawParameter::yield_strength, true, 0}, {LawParameter::poisson, true, 0}};

}  // namespace

const ContactLawDescriptor kogut_etsion_law_descriptor = {
    ContactLawKind::kogut_etsion, "kogut-etsion", "Kogut-Etsion 2002",
    "FE fits on [1, 6] and [6, 110] omega_c, fully plastic beyond", LawFamily::elastic_plastic, parameters, 2, make,
    response, nullptr, 3, {1, 6, 110, 0}, false};

}  // namespace detail
}  // namespace asperity
