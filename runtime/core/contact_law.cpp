// The contact laws of asperity/contact_law.hpp: each law's formulas as its paper gives them
// (sources in docs/contact-laws.md).
#include "asperity/contact_law.hpp"

#include "asperity/law_combination.hpp"

#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>

#include <boost/math/tools/roots.hpp>

namespace asperity {
namespace {

constexpr double pi = 3.14159265358979323846;
constexpr double nan = std::numeric_limits<double>::quiet_NaN();
constexpr double inf = std::numeric_limits<double>::infinity();

bool positive(double x) noexcept { return std::isfinite(x) && x > 0; }
bool poisson_ok(double nu) noexcept { return std::isfinite(nu) && nu >= 0 && nu <= 0.5; }

// The law's kind with every number NaN: what a factory returns for bad parameters.
ContactLaw bad_law(ContactLawKind kind) noexcept {
  ContactLaw law;
  law.kind = kind;
  law.radius = law.modulus = law.hardness = law.yield_strength = law.poisson = nan;
  law.pressure_factor = law.work_of_adhesion = law.maugis_parameter = nan;
  law.critical_interference = law.critical_load = law.critical_area = nan;
  law.jackson_green_b = law.jackson_green_c = law.md_turning = nan;
  law.lowest_interference = law.valid_up_to = nan;
  return law;
}

// Hertz: P = (4/3) E* R^1/2 w^3/2, A = pi R w, dP/dw = 2 E* (R w)^1/2: the numbers are
// law_combination.hpp's hertz_combination, the same that the rough-surface kernels multiply
constexpr const double (&hertz_numbers)[4] = hertz_combination.multiplier;  // count, area, load, stiffness
AsperityResponse hertz(double radius, double modulus, double w) noexcept {
  const double root = std::sqrt(radius * w);
  return {hertz_numbers[2] * modulus * root * w, hertz_numbers[1] * radius * w, hertz_numbers[3] * modulus * root};
}
double hertz_load(double radius, double modulus, double w) noexcept {
  return hertz_numbers[2] * modulus * std::sqrt(radius * w) * w;
}

// Elastic-plastic laws share: R, E*, omega_c, P_c = Hertz at omega_c, A_c = pi R omega_c.
void set_critical(ContactLaw& law, double critical) noexcept {
  law.critical_interference = critical;
  law.critical_load = hertz_load(law.radius, law.modulus, critical);
  law.critical_area = pi * law.radius * critical;
  law.lowest_interference = 0;
  law.valid_up_to = inf;
}

// ---- Maugis-Dugdale (dimensionless, t = sqrt(m^2 - 1)) ----
// Maugis 1992, with Johnson & Greenwood 1997's notation: for contact radius A and Dugdale ratio m,
//   (lambda A^2 / 2) [sqrt(m^2-1) + (m^2-2) atan sqrt(m^2-1)]
//     + (4 lambda^2 A / 3) [sqrt(m^2-1) atan sqrt(m^2-1) - m + 1] = 1
//   Pbar = A^3 - lambda A^2 [sqrt(m^2-1) + m^2 atan sqrt(m^2-1)]
//   D    = A^2 - (4/3) A lambda sqrt(m^2-1)
// With t = sqrt(m^2-1) the first is a quadratic in A: alpha A^2 + beta A = 1.
struct MdState {
  double a, d, p;        // A, D, Pbar
  double da, dd, dp;     // their derivatives in t
};

// t - atan t without cancellation for small t
double t_minus_atan(double t) noexcept {
  if (t >= 0.5) return t - std::atan(t);
  const double t2 = t * t;
  double term = t * t2, sum = 0;
  for (int k = 1; k < 60; ++k) {
    const double add = term / (2 * k + 1);
    sum += (k % 2) ? add : -add;
    if (add < 1e-18 * sum) break;
    term *= t2;
  }
  return sum;
}

MdState md_state(double lambda, double t) noexcept {
  const double at = std::atan(t), t2 = t * t, s = std::sqrt(1 + t2);
  const double f1 = t2 * at + t_minus_atan(t);               // t + (t^2 - 1) atan t
  const double f2 = t * at - t2 / (1 + s);                   // t atan t - sqrt(1+t^2) + 1
  const double f1p = 2 * t * (at + t / (1 + t2));            // d f1/dt
  const double f2p = at + t / (1 + t2) - t / s;              // d f2/dt
  const double g = t + (1 + t2) * at, gp = 2 + 2 * t * at;   // t + m^2 atan t and its derivative
  const double alpha = 0.5 * lambda * f1, beta = (4.0 / 3.0) * lambda * lambda * f2;
  const double alphap = 0.5 * lambda * f1p, betap = (4.0 / 3.0) * lambda * lambda * f2p;
  MdState st;
  st.a = 2 / (beta + std::sqrt(beta * beta + 4 * alpha));
  st.da = -(alphap * st.a * st.a + betap * st.a) / (2 * alpha * st.a + beta);
  st.d = st.a * st.a - (4.0 / 3.0) * st.a * lambda * t;
  st.dd = 2 * st.a * st.da - (4.0 / 3.0) * lambda * (st.da * t + st.a);
  st.p = st.a * st.a * st.a - lambda * st.a * st.a * g;
  st.dp = 3 * st.a * st.a * st.da - lambda * (2 * st.a * st.da * g + st.a * st.a * gp);
  return st;
}

constexpr double md_t_min = 1e-30, md_t_max = 1e12;

// The first t where dD/dt turns non-negative (the end of the fixed-grips stable branch), or inf.
double md_turning_point(double lambda) noexcept {
  double previous = md_t_min * 1e20;  // 1e-10
  for (int i = 1; i <= 16 * 40; ++i) {
    // up to t = 1e6: beyond, D is within rounding of its limit (a turning point found there is
    // rounding, and one that is real changes the lowest interference by less than 1e-6)
    const double t = 1e-10 * std::pow(10.0, i / 40.0);
    if (t > 1e6) break;
    if (md_state(lambda, t).dd > 0) {
      try {
        boost::uintmax_t iterations = 200;
        const auto bracket = boost::math::tools::toms748_solve(
            [&](double u) { return md_state(lambda, u).dd; }, previous, t,
            boost::math::tools::eps_tolerance<double>(50), iterations);
        return 0.5 * (bracket.first + bracket.second);
      } catch (...) {
        return nan;
      }
    }
    previous = t;
  }
  return inf;
}

// t on the stable branch where D(t) = d, or NaN.
double md_parameter_at(double lambda, double turning, double d) noexcept {
  const double t_high = std::isfinite(turning) ? turning : md_t_max;
  if (md_state(lambda, t_high).d >= d) return t_high;  // at (or, by rounding, below) the lowest interference
  double t_low = std::fmin(1e-3, t_high / 2);
  for (int i = 0; md_state(lambda, t_low).d <= d; ++i) {
    if (i > 40) return nan;
    t_low /= 10;
  }
  try {
    boost::uintmax_t iterations = 300;
    // in ln t: D spans decades in t
    const auto bracket = boost::math::tools::toms748_solve(
        [&](double u) { return md_state(lambda, std::exp(u)).d - d; }, std::log(t_low), std::log(t_high),
        boost::math::tools::eps_tolerance<double>(52), iterations);
    return std::exp(0.5 * (bracket.first + bracket.second));
  } catch (...) {
    return nan;
  }
}

// JKR in the same units: Pbar = A^3 - sqrt(6) A^3/2, D = A^2 - sqrt(8/3) A^1/2 (x = A^1/2 >= 6^(-1/6)).
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

// Adhesive laws' scales (Maugis' K = (4/3) E*): a_s = (pi dgamma R^2 / K)^(1/3), d_s = a_s^2 / R.
void set_adhesive_scales(ContactLaw& law) noexcept {
  const double k = (4.0 / 3.0) * law.modulus;
  const double a_s = std::cbrt(pi * law.work_of_adhesion * law.radius * law.radius / k);
  law.critical_interference = a_s * a_s / law.radius;
  law.critical_load = pi * law.work_of_adhesion * law.radius;
  law.critical_area = pi * a_s * a_s;
  law.valid_up_to = inf;
}

// From dimensionless (A, Pbar, dPbar/dD) to physical
AsperityResponse adhesive_response(const ContactLaw& law, double a, double p, double dp_dd) noexcept {
  return {law.critical_load * p, law.critical_area * a * a, law.critical_load / law.critical_interference * dp_dd};
}

// Jackson-Green 2005 beyond 1.9 omega_c: A = pi R w (w*/1.9)^B;
// P/P_c = exp(-w*^(5/12)/4) w*^(3/2) + (4 H_G/(C S_y)) (1 - exp(-w*^(5/9)/25)) w*.
AsperityResponse jackson_green_plastic(const ContactLaw& law, double w) noexcept {
  const double x = w / law.critical_interference, b = law.jackson_green_b, c = law.jackson_green_c;
  const double r = law.radius;
  const double grow = std::pow(x / 1.9, b);
  const double area = pi * r * w * grow;
  const double darea = pi * r * (1 + b) * grow;
  const double a = std::sqrt(area / pi), da = darea / (2 * pi * a);
  const double u = a / r, du = da / r;
  double h, dh_du;  // H_G / S_y and its derivative in a/R
  if (law.jackson_green_hardness == JacksonGreenHardness::cosine_2005) {
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

}  // namespace

const char* contact_law_name(ContactLawKind kind) noexcept {
  switch (kind) {
    case ContactLawKind::hertz: return "hertz";
    case ContactLawKind::chang_etsion_bogy: return "chang-etsion-bogy";
    case ContactLawKind::zhao_maietta_chang: return "zhao-maietta-chang";
    case ContactLawKind::kogut_etsion: return "kogut-etsion";
    case ContactLawKind::jackson_green: return "jackson-green";
    case ContactLawKind::dmt: return "dmt";
    case ContactLawKind::jkr: return "jkr";
    case ContactLawKind::maugis_dugdale: return "maugis-dugdale";
  }
  return "unknown";
}

bool contact_law_kind_of(const char* name, ContactLawKind& kind) noexcept {
  if (!name) return false;
  for (ContactLawKind candidate : contact_law_kinds) {
    const char *a = name, *b = contact_law_name(candidate);
    while (*a && *a == *b) ++a, ++b;
    if (*a == 0 && *b == 0) {
      kind = candidate;
      return true;
    }
  }
  return false;
}

ContactLaw hertz_law(double radius, double modulus) noexcept {
  if (!positive(radius) || !positive(modulus)) return bad_law(ContactLawKind::hertz);
  ContactLaw law;
  law.kind = ContactLawKind::hertz;
  law.radius = radius;
  law.modulus = modulus;
  law.critical_interference = law.critical_load = law.critical_area = nan;  // no yield in an elastic law
  law.lowest_interference = 0;
  law.valid_up_to = inf;
  return law;
}

ContactLaw chang_etsion_bogy_law(double radius, double modulus, double hardness, double poisson) noexcept {
  const auto kind = ContactLawKind::chang_etsion_bogy;
  if (!positive(radius) || !positive(modulus) || !positive(hardness) || !poisson_ok(poisson)) return bad_law(kind);
  ContactLaw law;
  law.kind = kind;
  law.radius = radius;
  law.modulus = modulus;
  law.hardness = hardness;
  law.poisson = poisson;
  law.pressure_factor = 0.454 + 0.41 * poisson;
  const double q = pi * law.pressure_factor * hardness / (2 * modulus);
  set_critical(law, q * q * radius);
  return law;
}

ContactLaw zhao_maietta_chang_law(double radius, double modulus, double hardness, double pressure_factor) noexcept {
  const auto kind = ContactLawKind::zhao_maietta_chang;
  if (!positive(radius) || !positive(modulus) || !positive(hardness) || !positive(pressure_factor) ||
      pressure_factor >= 1)
    return bad_law(kind);
  ContactLaw law;
  law.kind = kind;
  law.radius = radius;
  law.modulus = modulus;
  law.hardness = hardness;
  law.pressure_factor = pressure_factor;
  const double q = 3 * pi * pressure_factor * hardness / (4 * modulus);
  set_critical(law, q * q * radius);
  return law;
}

ContactLaw kogut_etsion_law(double radius, double modulus, double yield_strength, double poisson) noexcept {
  const auto kind = ContactLawKind::kogut_etsion;
  if (!positive(radius) || !positive(modulus) || !positive(yield_strength) || !poisson_ok(poisson))
    return bad_law(kind);
  ContactLaw law;
  law.kind = kind;
  law.radius = radius;
  law.modulus = modulus;
  law.yield_strength = yield_strength;
  law.hardness = 2.8 * yield_strength;
  law.poisson = poisson;
  law.pressure_factor = 0.454 + 0.41 * poisson;
  const double q = pi * law.pressure_factor * law.hardness / (2 * modulus);
  set_critical(law, q * q * radius);
  return law;
}

ContactLaw jackson_green_law(double radius, double modulus, double yield_strength, double poisson,
                             JacksonGreenHardness hardness) noexcept {
  const auto kind = ContactLawKind::jackson_green;
  if (!positive(radius) || !positive(modulus) || !positive(yield_strength) || !poisson_ok(poisson) ||
      (hardness != JacksonGreenHardness::cosine_2005 && hardness != JacksonGreenHardness::exponential_2006))
    return bad_law(kind);
  ContactLaw law;
  law.kind = kind;
  law.radius = radius;
  law.modulus = modulus;
  law.yield_strength = yield_strength;
  law.poisson = poisson;
  law.jackson_green_hardness = hardness;
  law.jackson_green_c = 1.295 * std::exp(0.736 * poisson);
  law.jackson_green_b = 0.14 * std::exp(23 * yield_strength / modulus);
  const double q = pi * law.jackson_green_c * yield_strength / (2 * modulus);
  set_critical(law, q * q * radius);
  // H_G(a/R) is fitted for a < R (the cosine form turns back beyond): omega where a = R,
  // R^2 = R w (w / (1.9 w_c))^B, or Hertz's w = R if that is still elastic
  const double b = law.jackson_green_b, transition = 1.9 * law.critical_interference;
  const double w_full = std::pow(radius * std::pow(transition, b), 1 / (1 + b));
  law.valid_up_to = radius <= transition ? radius : w_full;
  return law;
}

ContactLaw dmt_law(double radius, double modulus, double work_of_adhesion) noexcept {
  const auto kind = ContactLawKind::dmt;
  if (!positive(radius) || !positive(modulus) || !positive(work_of_adhesion)) return bad_law(kind);
  ContactLaw law;
  law.kind = kind;
  law.radius = radius;
  law.modulus = modulus;
  law.work_of_adhesion = work_of_adhesion;
  set_adhesive_scales(law);
  law.lowest_interference = 0;
  return law;
}

ContactLaw jkr_law(double radius, double modulus, double work_of_adhesion) noexcept {
  const auto kind = ContactLawKind::jkr;
  if (!positive(radius) || !positive(modulus) || !positive(work_of_adhesion)) return bad_law(kind);
  ContactLaw law;
  law.kind = kind;
  law.radius = radius;
  law.modulus = modulus;
  law.work_of_adhesion = work_of_adhesion;
  set_adhesive_scales(law);
  law.maugis_parameter = inf;
  law.lowest_interference = -3 * std::pow(6.0, -2.0 / 3.0) * law.critical_interference;
  return law;
}

ContactLaw maugis_dugdale_law(double radius, double modulus, double work_of_adhesion, double maugis_parameter) noexcept {
  const auto kind = ContactLawKind::maugis_dugdale;
  if (!positive(radius) || !positive(modulus) || !positive(work_of_adhesion) || !positive(maugis_parameter))
    return bad_law(kind);
  ContactLaw law;
  law.kind = kind;
  law.radius = radius;
  law.modulus = modulus;
  law.work_of_adhesion = work_of_adhesion;
  law.maugis_parameter = maugis_parameter;
  set_adhesive_scales(law);
  law.md_turning = md_turning_point(maugis_parameter);
  if (std::isnan(law.md_turning)) return bad_law(kind);
  const double t_end = std::isfinite(law.md_turning) ? law.md_turning : md_t_max;
  law.lowest_interference = md_state(maugis_parameter, t_end).d * law.critical_interference;
  return law;
}

MaugisDugdalePoint maugis_dugdale_point(double maugis_parameter, double t) noexcept {
  if (!positive(maugis_parameter) || !positive(t)) return {nan, nan, nan, nan};
  const MdState st = md_state(maugis_parameter, t);
  return {t, st.a, st.d, st.p};
}

AsperityResponse asperity_response(const ContactLaw& law, double w) noexcept {
  const AsperityResponse bad{nan, nan, nan}, none{0, 0, 0};
  if (std::isnan(w) || !positive(law.radius) || !positive(law.modulus) || std::isnan(law.lowest_interference))
    return bad;
  if (w < law.lowest_interference || (w == law.lowest_interference && law.lowest_interference == 0 &&
                                      law.kind != ContactLawKind::dmt))
    return none;
  if (w == inf) return {inf, inf, inf};
  const double r = law.radius, e = law.modulus, wc = law.critical_interference;
  switch (law.kind) {
    case ContactLawKind::hertz:
      return hertz(r, e, w);
    case ContactLawKind::chang_etsion_bogy: {
      if (w <= wc) return hertz(r, e, w);
      const double kh = law.pressure_factor * law.hardness, area = pi * r * (2 * w - wc);
      return {kh * area, area, 2 * pi * r * kh};
    }
    case ContactLawKind::zhao_maietta_chang: {
      if (w <= wc) return hertz(r, e, w);
      const double w2 = 54 * wc, h = law.hardness;
      if (w >= w2) return {2 * pi * r * w * h, 2 * pi * r * w, 2 * pi * r * h};
      const double span = w2 - wc, x = (w - wc) / span, logs = std::log(54.0);
      const double blend = 1 - 2 * x * x * x + 3 * x * x, dblend = (6 * x - 6 * x * x) / span;
      const double area = pi * r * w * blend, darea = pi * r * (blend + w * dblend);
      const double mean = h * (1 - (1 - law.pressure_factor) * std::log(w2 / w) / logs);
      const double dmean = h * (1 - law.pressure_factor) / (w * logs);
      return {mean * area, area, dmean * area + mean * darea};
    }
    case ContactLawKind::kogut_etsion: {
      // the branch by w against the switch points as switch_points() gives them (x = w/wc
      // rounds to 6 within an ulp or two of 6 wc: the load's jump there was lost)
      const double x = w / wc, pc = law.critical_load, ac = law.critical_area;
      if (w <= wc) return hertz(r, e, w);
      double cp, ep, ca, ea;  // P/P_c = cp x^ep, A/A_c = ca x^ea
      if (w <= 6 * wc) {
        cp = 1.03, ep = 1.425, ca = 0.93, ea = 1.136;
      } else if (w <= 110 * wc) {
        cp = 1.40, ep = 1.263, ca = 0.94, ea = 1.146;
      } else {
        cp = 3 / law.pressure_factor, ep = 1, ca = 2, ea = 1;  // fully plastic: A = 2 pi R w, P = H A
      }
      const double power = std::pow(x, ep);
      return {pc * cp * power, ac * ca * std::pow(x, ea), pc / wc * cp * ep * power / x};
    }
    case ContactLawKind::jackson_green:
      if (w < 1.9 * wc) return hertz(r, e, w);
      return jackson_green_plastic(law, w);
    case ContactLawKind::dmt: {
      AsperityResponse response = hertz(r, e, w);
      response.load -= 2 * pi * law.work_of_adhesion * r;
      return response;
    }
    case ContactLawKind::jkr: {
      const double x = jkr_root(w / wc), a = x * x, a32 = a * x;
      const double p = a * a * a - std::sqrt(6.0) * a32;
      // dPbar/dD = (3 A^2 - (3/2) sqrt 6 A^1/2) / (2 A - sqrt(2/3) A^-1/2)
      const double dp = (3 * a * a - 1.5 * std::sqrt(6.0) * x) / (2 * a - std::sqrt(2.0 / 3.0) / x);
      return adhesive_response(law, a, p, dp);
    }
    case ContactLawKind::maugis_dugdale: {
      const double t = md_parameter_at(law.maugis_parameter, law.md_turning, w / wc);
      if (std::isnan(t)) return bad;
      const MdState st = md_state(law.maugis_parameter, t);
      return adhesive_response(law, st.a, st.p, st.dp / st.dd);
    }
  }
  return bad;
}

bool is_adhesive(ContactLawKind kind) noexcept {
  return kind == ContactLawKind::dmt || kind == ContactLawKind::jkr || kind == ContactLawKind::maugis_dugdale;
}

AsperityLoadSplit asperity_load_split(const ContactLaw& law, double w) noexcept {
  const AsperityResponse response = asperity_response(law, w);
  if (std::isnan(response.load)) return {nan, nan, nan, nan};
  // out of contact (an adhesive law's lowest interference is where its contact ends): zeros
  if (!is_adhesive(law.kind) || w < law.lowest_interference) return {response.load, 0, response.stiffness, 0};
  if (w == inf) return {inf, inf, inf, inf};
  const double pc = law.critical_load, kc = law.critical_load / law.critical_interference;
  switch (law.kind) {
    case ContactLawKind::dmt: {
      const double tension = 2 * pi * law.work_of_adhesion * law.radius;
      return {response.load + tension, tension, response.stiffness, 0};
    }
    case ContactLawKind::jkr: {
      // Pbar = A^3 - sqrt(6) A^3/2, x = A^1/2; dD/dA = 2 A - sqrt(2/3) A^-1/2
      const double x = jkr_root(w / law.critical_interference), a = x * x;
      const double dd_da = 2 * a - std::sqrt(2.0 / 3.0) / x;
      return {pc * a * a * a, pc * std::sqrt(6.0) * a * x, kc * 3 * a * a / dd_da,
              kc * 1.5 * std::sqrt(6.0) * x / dd_da};
    }
    case ContactLawKind::maugis_dugdale: {
      const double t = md_parameter_at(law.maugis_parameter, law.md_turning, w / law.critical_interference);
      if (std::isnan(t)) return {nan, nan, nan, nan};
      const MdState st = md_state(law.maugis_parameter, t);
      const double compressive = st.a * st.a * st.a, dcompressive = 3 * st.a * st.a * st.da / st.dd;
      return {pc * compressive, pc * (compressive - st.p), kc * dcompressive, kc * (dcompressive - st.dp / st.dd)};
    }
    default: break;
  }
  return {nan, nan, nan, nan};
}

SwitchPoints switch_points(const ContactLaw& law) noexcept {
  SwitchPoints points;
  if (std::isnan(law.lowest_interference) || !positive(law.radius)) return points;
  const double wc = law.critical_interference;
  auto add = [&](double w) { points.interference[points.count++] = w; };
  switch (law.kind) {
    case ContactLawKind::chang_etsion_bogy: add(wc); break;
    case ContactLawKind::zhao_maietta_chang: add(wc), add(54 * wc); break;
    case ContactLawKind::kogut_etsion: add(wc), add(6 * wc), add(110 * wc); break;
    case ContactLawKind::jackson_green: add(1.9 * wc); break;
    case ContactLawKind::dmt: add(0); break;
    default: break;
  }
  return points;
}

double plasticity_index(const ContactLaw& law, double summit_scale) noexcept {
  if (!positive(summit_scale)) return nan;
  switch (law.kind) {
    case ContactLawKind::chang_etsion_bogy:
    case ContactLawKind::zhao_maietta_chang:
    case ContactLawKind::kogut_etsion:
    case ContactLawKind::jackson_green:
      return std::sqrt(summit_scale / law.critical_interference);
    default:
      return nan;
  }
}

double greenwood_williamson_plasticity_index(double modulus, double hardness, double summit_scale,
                                             double radius) noexcept {
  if (!positive(modulus) || !positive(hardness) || !positive(summit_scale) || !positive(radius)) return nan;
  return modulus / hardness * std::sqrt(summit_scale / radius);
}

double adhesion_parameter(const ContactLaw& law, double summit_scale) noexcept {
  if (!is_adhesive(law.kind) || !positive(summit_scale) || !positive(law.work_of_adhesion)) return nan;
  const double dgamma = law.work_of_adhesion, e = law.modulus;
  const double delta_c = 0.75 * std::cbrt(pi * pi * dgamma * dgamma * law.radius / (e * e));
  return summit_scale / delta_c;
}

}  // namespace asperity
