// Chang, Etsion & Bogy 1987: Hertz to omega_c, then volume conservation of the plastic cap at the
// mean pressure K H (docs/contact-laws.md section 2).
#include "law_support.hpp"

namespace asperity {

// omega_c = (pi K H / (2 E*))^2 R, K = 0.454 + 0.41 nu; beyond omega_c A = pi R (2 omega - omega_c), P = K H A.
ContactLaw chang_etsion_bogy_law(double radius, double modulus, double hardness, double poisson) noexcept {
  const auto kind = ContactLawKind::chang_etsion_bogy;
  if (!detail::positive(radius) || !detail::positive(modulus) || !detail::positive(hardness) ||
      !detail::poisson_ok(poisson))
    return detail::bad_law(kind);
  ContactLaw law = detail::law_with(kind, radius, modulus);
  law.hardness = hardness;
  law.poisson = poisson;
  law.pressure_factor = 0.454 + 0.41 * poisson;
  const double q = detail::pi * law.pressure_factor * hardness / (2 * modulus);
  detail::set_critical(law, q * q * radius);
  return law;
}

namespace detail {
namespace {

ContactLaw make(double radius, double modulus, const LawValues& v) noexcept {
  return chang_etsion_bogy_law(radius, modulus, v[LawParameter::hardness], v[LawParameter::poisson]);
}

AsperityResponse response(const ContactLaw& law, double w) noexcept {
  const double r = law.radius, wc = law.critical_interference;
  if (w <= wc) return hertz(r, law.modulus, w);
  // A = pi R (2 w - w_c) as 2 pi R (w - w_c/2): the same double, without 2 w overflowing at huge w
  const double kh = law.pressure_factor * law.hardness, area = 2 * pi * r * (w - 0.5 * wc);
  return {kh * area, area, 2 * pi * r * kh};
}

constexpr LawParameterUse parameters[] = {{LawParameter::hardness, true, 0}, {LawParameter::poisson, true, 0}};

}  // namespace

const ContactLawDescriptor chang_etsion_bogy_law_descriptor = {
    ContactLawKind::chang_etsion_bogy, "chang-etsion-bogy", "Chang-Etsion-Bogy 1987",
    "Hertz to omega_c, then volume conservation at mean pressure K H", LawFamily::elastic_plastic, parameters, 2,
    make, response, nullptr, 1, {1, 0, 0, 0}, false};

}  // namespace detail
}  // namespace asperity
