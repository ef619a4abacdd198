// Johnson, Kendall & Roberts 1971: the sphere's adhesive contact (Maugis-Dugdale's lambda -> inf),
// in Maugis' units (docs/contact-laws.md section 5).
#include "law_support.hpp"

namespace asperity {

ContactLaw jkr_law(double radius, double modulus, double work_of_adhesion) noexcept {
  const auto kind = ContactLawKind::jkr;
  if (!detail::positive(radius) || !detail::positive(modulus) || !detail::positive(work_of_adhesion))
    return detail::bad_law(kind);
  ContactLaw law = detail::law_with(kind, radius, modulus);
  law.work_of_adhesion = work_of_adhesion;
  detail::set_adhesive_scales(law);
  law.maugis_parameter = detail::inf;
  law.lowest_interference = -3 * std::pow(6.0, -2.0 / 3.0) * law.critical_interference;
  return law;
}

namespace detail {
namespace {

// Pbar = A^3 - sqrt(6) A^3/2, D = A^2 - sqrt(8/3) A^1/2 (x = A^1/2 >= 6^(-1/6)).
constexpr double jkr_c = 1.6329931618554520655;  // sqrt(8/3)
double jkr_root(double d) noexcept {
  const double x_min = std::pow(6.0, -1.0 / 6.0);
  double x = std::fmax(2.0, std::pow(2 * std::fabs(d), 0.25));
  // Newton from above on a convex increasing function: decreasing iterates, never past the root
  for (int i = 0; i < 400; ++i) {
    const double f = x * x * x * x - jkr_c * x - d, fp = 4 * x * x * x - jkr_c;
    if (!(fp > 0) || f <= 0) break;
    const double step = f / fp;
    x -= step;
    if (x <= x_min) return x_min;
    if (step <= 4e-16 * x) break;  // converged to rounding (f may stay a few ulps above 0)
  }
  return x;
}

ContactLaw make(double radius, double modulus, const LawValues& v) noexcept {
  return jkr_law(radius, modulus, v[LawParameter::work_of_adhesion]);
}

AsperityResponse response(const ContactLaw& law, double w) noexcept {
  const double x = jkr_root(w / law.critical_interference), a = x * x, a32 = a * x;
  const double p = a * a * a - std::sqrt(6.0) * a32;
  // dPbar/dD = (3 A^2 - (3/2) sqrt 6 A^1/2) / (2 A - sqrt(2/3) A^-1/2)
  const double dp = (3 * a * a - 1.5 * std::sqrt(6.0) * x) / (2 * a - std::sqrt(2.0 / 3.0) / x);
  return adhesive_response(law, a, p, dp);
}

AsperityLoadSplit load_split(const ContactLaw& law, double w, const AsperityResponse&) noexcept {
  // Pbar = A^3 - sqrt(6) A^3/2, x = A^1/2; dD/dA = 2 A - sqrt(2/3) A^-1/2
  const double pc = law.critical_load, kc = law.critical_load / law.critical_interference;
  const double x = jkr_root(w / law.critical_interference), a = x * x;
  const double dd_da = 2 * a - std::sqrt(2.0 / 3.0) / x;
  return {pc * a * a * a, pc * std::sqrt(6.0) * a * x, kc * 3 * a * a / dd_da, kc * 1.5 * std::sqrt(6.0) * x / dd_da};
}

constexpr LawParameterUse parameters[] = {{LawParameter::work_of_adhesion, true, 0}};

}  // namespace

const ContactLawDescriptor jkr_law_descriptor = {
    ContactLawKind::jkr, "jkr", "Johnson-Kendall-Roberts 1971", "adhesive elastic spheres (Maugis' lambda -> infinity)",
    LawFamily::adhesive, parameters, 1, make, response, load_split, 0, {0, 0, 0, 0}, false};

}  // namespace detail
}  // namespace asperity
