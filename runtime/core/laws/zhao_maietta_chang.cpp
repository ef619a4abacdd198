// Zhao, Maietta & Chang 2000: Hertz to omega_1, a cubic blend to omega_2 = 54 omega_1, then fully
// plastic (docs/contact-laws.md section 2).
#include "law_support.hpp"

namespace asperity {

// omega_1 = (3 pi K H / (4 E*))^2 R (K = 0.6 in the paper).
ContactLaw zhao_maietta_chang_law(double radius, double modulus, double hardness, double pressure_factor) noexcept {
  const auto kind = ContactLawKind::zhao_maietta_chang;
  if (!detail::positive(radius) || !detail::positive(modulus) || !detail::positive(hardness) ||
      !detail::positive(pressure_factor) || pressure_factor >= 1)
    return detail::bad_law(kind);
  ContactLaw law = detail::law_with(kind, radius, modulus);
  law.hardness = hardness;
  law.pressure_factor = pressure_factor;
  const double q = 3 * detail::pi * pressure_factor * hardness / (4 * modulus);
  detail::set_critical(law, q * q * radius);
  return law;
}

namespace detail {
namespace {

ContactLaw make(double radius, double modulus, const LawValues& v) noexcept {
  return zhao_maietta_chang_law(radius, modulus, v[LawParameter::hardness], v[LawParameter::pressure_factor]);
}

AsperityResponse response(const ContactLaw& law, double w) noexcept {
  const double r = law.radius, wc = law.critical_interference;
  if (w <= wc) return hertz(r, law.modulus, w);
  const double w2 = 54 * wc, h = law.hardness;
  if (w >= w2) return {2 * pi * r * w * h, 2 * pi * r * w, 2 * pi * r * h};
  const double span = w2 - wc, x = (w - wc) / span, logs = std::log(54.0);
  const double blend = 1 - 2 * x * x * x + 3 * x * x, dblend = (6 * x - 6 * x * x) / span;
  const double area = pi * r * w * blend, darea = pi * r * (blend + w * dblend);
  const double mean = h * (1 - (1 - law.pressure_factor) * std::log(w2 / w) / logs);
  const double dmean = h * (1 - law.pressure_factor) / (w * logs);
  return {mean * area, area, dmean * area + mean * darea};
}

constexpr LawParameterUse parameters[] = {{LawParameter::hardness, true, 0},
                                          {LawParameter::pressure_factor, false, 0.6}};

}  // namespace

const ContactLawDescriptor zhao_maietta_chang_law_descriptor = {
    ContactLawKind::zhao_maietta_chang, "zhao-maietta-chang", "Zhao-Maietta-Chang 2000",
    "Hertz to omega_1, cubic blend to 54 omega_1, then fully plastic", LawFamily::elastic_plastic, parameters, 2,
    make, response, nullptr, 2, {1, 54, 0, 0}, false};

}  // namespace detail
}  // namespace asperity
