// Jackson & Green 2005: Hertz to 1.9 omega_c, then finite-element fits with a geometric hardness
// H_G(a/R) (docs/contact-laws.md section 2).
#include "law_support.hpp"

namespace asperity {
namespace detail {
namespace {
AsperityResponse plastic(const ContactLaw& law, double w) noexcept;
}  // namespace
}  // namespace detail

// omega_c = (pi C S_y / (2 E*))^2 R, C = 1.295 exp(0.736 nu).
ContactLaw jackson_green_law(double radius, double modulus, double yield_strength, double poisson,
                             JacksonGreenHardness hardness) noexcept {
  const auto kind = ContactLawKind::jackson_green;
  if (!detail::positive(radius) || !detail::positive(modulus) || !detail::positive(yield_strength) ||
      !detail::poisson_ok(poisson) ||
      (hardness != JacksonGreenHardness::cosine && hardness != JacksonGreenHardness::exponential))
    return detail::bad_law(kind);
  ContactLaw law = detail::law_with(kind, radius, modulus);
  law.yield_strength = yield_strength;
  law.poisson = poisson;
  law.jackson_green_hardness = hardness;
  law.jackson_green_c = 1.295 * std::exp(0.736 * poisson);
  law.jackson_green_b = 0.14 * std::exp(23 * yield_strength / modulus);
  const double q = detail::pi * law.jackson_green_c * yield_strength / (2 * modulus);
  detail::set_critical(law, q * q * radius);
  // H_G(a/R) is fitted for a < R (the cosine form turns back beyond): omega where a = R,
  // R^2 = R w (w / (1.9 w_c))^B, or Hertz's w = R if that is still elastic
  const double b = law.jackson_green_b, transition = 1.9 * law.critical_interference;
  const double w_full = std::pow(radius * std::pow(transition, b), 1 / (1 + b));
  law.valid_up_to = radius <= transition ? radius : w_full;
  // Where the fit starts below Hertz at 1.9 omega_c (S_y/E* above about 0.03, both forms: -2.9% at
  // 0.08, -14% at 0.2), its load falls as the interference grows: outside what the fit describes,
  // so that the law is supported only below there (its Hertz part, to the double below 1.9 omega_c;
  // a table over summits beyond is refused, naming valid_up_to). Measured, the fit's load rises
  // everywhere else up to a = R.
  if (law.valid_up_to >= transition &&
      !(detail::plastic(law, transition).load >= detail::hertz(radius, modulus, transition).load))
    law.valid_up_to = std::nextafter(transition, 0.0);
  return law;
}

namespace detail {
namespace {

ContactLaw make(double radius, double modulus, const LawValues& v) noexcept {
  const auto hardness = v[LawParameter::geometric_hardness] == 1 ? JacksonGreenHardness::exponential
                                                                 : JacksonGreenHardness::cosine;
  return jackson_green_law(radius, modulus, v[LawParameter::yield_strength], v[LawParameter::poisson], hardness);
}

// Beyond 1.9 omega_c: A = pi R w (w*/1.9)^B;
// P/P_c = exp(-w*^(5/12)/4) w*^(3/2) + (4 H_G/(C S_y)) (1 - exp(-w*^(5/9)/25)) w*.
AsperityResponse plastic(const ContactLaw& law, double w) noexcept {
  const double x = w / law.critical_interference, b = law.jackson_green_b, c = law.jackson_green_c;
  const double r = law.radius;
  const double grow = std::pow(x / 1.9, b);
  const double area = pi * r * w * grow;
  const double darea = pi * r * (1 + b) * grow;
  const double a = std::sqrt(area / pi), da = darea / (2 * pi * a);
  const double u = a / r, du = da / r;
  double h, dh_du;  // H_G / S_y and its derivative in a/R
  if (law.jackson_green_hardness == JacksonGreenHardness::cosine) {
    h = 2.84 - 0.92 * (1 - std::cos(pi * u));
    dh_du = -0.92 * pi * std::sin(pi * u);
  } else {
    const double e = std::exp(-0.82 * std::pow(u, -0.7));
    h = 2.84 * (1 - e);
    dh_du = -2.84 * e * 0.82 * 0.7 * std::pow(u, -1.7);
  }
  const double dh = dh_du * du * law.critical_interference;  // dh/dx
  const double e1 = std::exp(-0.25 * std::pow(x, 5.0 / 12.0));
  const double e2 = std::exp(-std::pow(x, 5.0 / 9.0) / 25);
  const double f = e1 * std::pow(x, 1.5) + (4 * h / c) * (1 - e2) * x;
  const double df = e1 * std::sqrt(x) * (1.5 - 0.25 * (5.0 / 12.0) * std::pow(x, 5.0 / 12.0)) +
                    (4 / c) * (dh * (1 - e2) * x + h * ((5.0 / 9.0 / 25) * std::pow(x, 5.0 / 9.0) * e2 + (1 - e2)));
  return {law.critical_load * f, area, law.critical_load / law.critical_interference * df};
}

AsperityResponse response(const ContactLaw& law, double w) noexcept {
  if (w < 1.9 * law.critical_interference) return hertz(law.radius, law.modulus, w);
  return plastic(law, w);
}

constexpr LawParameterUse parameters[] = {{LawParameter::yield_strength, true, 0},
                                          {LawParameter::poisson, true, 0},
                                          {LawParameter::geometric_hardness, false, 0}};

}  // namespace

const ContactLawDescriptor jackson_green_law_descriptor = {
    ContactLawKind::jackson_green, "jackson-green", "Jackson-Green 2005",
    "Hertz to 1.9 omega_c, then FE fits with a geometric hardness", LawFamily::elastic_plastic, parameters, 3, make,
    response, nullptr, 1, {1.9, 0, 0, 0}, false};

}  // namespace detail
}  // namespace asperity
