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
  // the fixed-grips pull-off, -(3/4)(pi^2 dgamma^2 R / E*^2)^(1/3) (= -3 6^(-2/3) d_s) as written,
  // where the asperity is still in contact: the response there is the branch's end, P = -(5/6) pi
  // dgamma R (docs/contact-laws.md, "Branches")
  law.lowest_interference =
      -0.75 * std::cbrt(detail::pi * detail::pi * work_of_adhesion * work_of_adhesion * radius / (modulus * modulus));
  return law;
}

namespace detail {
namespace {

// Pbar = A^3 - sqrt(6) A^3/2, D = A^2 - sqrt(8/3) A^1/2 (x = A^1/2 >= 6^(-1/6)).
constexpr double jkr_c = 1.6329931618554520655;  // sqrt(8/3)
double jkr_x_min() noexcept { return std::pow(6.0, -1.0 / 6.0); }  // the branch's end, A = 6^(-1/3)
double jkr_root(double d) noexcept {
  const double x_min = jkr_x_min();
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

// Beyond D = 1e24 JKR is Hertz to rounding: the adhesive term's share, sqrt 6 D^(-3/4), is below
// 2.5e-18 (and D = omega / d_s may overflow where Hertz's area and stiffness do not)
constexpr double jkr_hertz_from = 1e24;

// dD/dA = 2 A - sqrt(2/3) A^-1/2 = 2 (x^3 - 6^(-1/2)) / x; 0 (not negative by rounding) at the
// branch's end, where the load's slope dP/domega is -inf (it falls as omega rises from there)
double jkr_dd_da(double x) noexcept {
  return x <= jkr_x_min() ? 0.0 : std::fmax(0.0, 2 * (x * x * x - 1 / std::sqrt(6.0)) / x);
}

// x = A^1/2 at omega = D d_s: the end's at the lowest interference (there D is flat in A, so that
// solving for A from a D rounded near it would lose half the digits of P)
double jkr_x(const ContactLaw& law, double w, double d) noexcept {
  return w <= law.lowest_interference ? jkr_x_min() : jkr_root(d);
}

AsperityResponse response(const ContactLaw& law, double w) noexcept {
  const double d = w / law.critical_interference;
  if (!(d < jkr_hertz_from)) return hertz(law.radius, law.modulus, w);
  const double x = jkr_x(law, w, d), a = x * x, a32 = a * x;
  const double p = a * a * a - std::sqrt(6.0) * a32;
  // dPbar/dD = (3 A^2 - (3/2) sqrt 6 A^1/2) / (2 A - sqrt(2/3) A^-1/2)
  const double dd_da = jkr_dd_da(x);
  const double dp = dd_da > 0 ? (3 * a * a - 1.5 * std::sqrt(6.0) * x) / dd_da : -inf;
  return adhesive_response(law, a, p, dp);
}

AsperityLoadSplit load_split(const ContactLaw& law, double w, const AsperityResponse& r) noexcept {
  // Pbar = A^3 - sqrt(6) A^3/2, x = A^1/2
  const double pc = law.critical_load, kc = law.critical_load / law.critical_interference;
  const double d = w / law.critical_interference;
  if (!(d < jkr_hertz_from)) {  // the tension sqrt 6 D^(3/4) P_c beside Hertz's load (r)
    const double tension = pc * std::sqrt(6.0) * std::pow(w, 0.75) / std::pow(law.critical_interference, 0.75);
    return {r.load + tension, tension, r.stiffness + 0.75 * tension / w, 0.75 * tension / w};
  }
  const double x = jkr_x(law, w, d), a = x * x;
  const double dd_da = jkr_dd_da(x);
  if (!(dd_da > 0)) return {pc * a * a * a, pc * std::sqrt(6.0) * a * x, inf, inf};  // both grow without bound
  return {pc * a * a * a, pc * std::sqrt(6.0) * a * x, kc * 3 * a * a / dd_da, kc * 1.5 * std::sqrt(6.0) * x / dd_da};
}

constexpr LawParameterUse parameters[] = {{LawParameter::work_of_adhesion, true, 0}};

}  // namespace

const ContactLawDescriptor jkr_law_descriptor = {
    ContactLawKind::jkr, "jkr", "Johnson-Kendall-Roberts 1971", "adhesive elastic spheres (Maugis' lambda -> infinity)",
    LawFamily::adhesive, parameters, 1, make, response, load_split, 0, {0, 0, 0, 0}, false};

}  // namespace detail
}  // namespace asperity
