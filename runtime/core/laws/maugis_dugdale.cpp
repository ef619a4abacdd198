// Maugis 1992: the sphere's adhesion with a Dugdale zone, from DMT (lambda -> 0) to JKR
// (lambda -> inf), in Johnson & Greenwood 1997's notation (docs/contact-laws.md section 5).
#include <boost/math/tools/roots.hpp>
#include <limits>

#include "law_support.hpp"

namespace asperity {
namespace detail {
namespace {

// For contact radius A and Dugdale ratio m, t = sqrt(m^2 - 1):
//   (lambda A^2 / 2) [t + (m^2-2) atan t] + (4 lambda^2 A / 3) [t atan t - m + 1] = 1
//   Pbar = A^3 - lambda A^2 [t + m^2 atan t]
//   D    = A^2 - (4/3) A lambda t
// The first is a quadratic in A: alpha A^2 + beta A = 1.
struct MdState {
  double a, d, p;     // A, D, Pbar
  double da, dd, dp;  // their derivatives in t
  double tension, dtension;  // lambda A^2 [t + m^2 atan t] = A^3 - Pbar and its derivative in t
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
  const double f1 = t2 * at + t_minus_atan(t);              // t + (t^2 - 1) atan t
  const double f2 = t * at - t2 / (1 + s);                  // t atan t - sqrt(1+t^2) + 1
  const double f1p = 2 * t * (at + t / (1 + t2));           // d f1/dt
  const double f2p = at + t / (1 + t2) - t / s;             // d f2/dt
  const double g = t + (1 + t2) * at, gp = 2 + 2 * t * at;  // t + m^2 atan t and its derivative
  const double alpha = 0.5 * lambda * f1, beta = (4.0 / 3.0) * lambda * lambda * f2;
  const double alphap = 0.5 * lambda * f1p, betap = (4.0 / 3.0) * lambda * lambda * f2p;
  MdState st;
  st.a = 2 / (beta + std::sqrt(beta * beta + 4 * alpha));
  st.da = -(alphap * st.a * st.a + betap * st.a) / (2 * alpha * st.a + beta);
  st.d = st.a * st.a - (4.0 / 3.0) * st.a * lambda * t;
  st.dd = 2 * st.a * st.da - (4.0 / 3.0) * lambda * (st.da * t + st.a);
  st.tension = lambda * st.a * st.a * g;
  st.dtension = lambda * (2 * st.a * st.da * g + st.a * st.a * gp);
  st.p = st.a * st.a * st.a - st.tension;
  st.dp = 3 * st.a * st.a * st.da - st.dtension;
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

// t on the stable branch where D(t) = d by bracketing and TOMS 748 in ln t, or NaN: the reference
// md_parameter_at falls back to (and tests/test_contact_law.cpp compares it with).
double md_parameter_bracketed(double lambda, double t_high, double d) noexcept {
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

// D on a grid of ln t for one lambda (the last one asked, per thread: a rough surface's curves ask
// one law millions of times): where a D lies in it starts Newton's method close to its root. A
// fixed array, so that the law's evaluation never allocates.
struct MdGrid {
  static constexpr int size = 960;  // a step of 0.11 in ln t: Newton starts within about 1e-3
  static constexpr double u_first = -103.6;  // ln 1e-45: below, D is beyond any interference asked
  double lambda = nan, t_high = nan, u_step = 0, d_high = nan;  // d_high: D(t_high), the lowest
  double d[size];  // decreasing in ln t
};

const MdGrid& md_grid(double lambda, double t_high) noexcept {
  static thread_local MdGrid grid;
  if (grid.lambda == lambda && grid.t_high == t_high) return grid;
  grid.lambda = lambda, grid.t_high = t_high;
  grid.u_step = (std::log(t_high) - MdGrid::u_first) / (MdGrid::size - 1);
  grid.d_high = md_state(lambda, t_high).d;
  for (int i = 0; i < MdGrid::size; ++i)
    grid.d[i] = md_state(lambda, std::exp(MdGrid::u_first + i * grid.u_step)).d;
  return grid;
}

// t on the stable branch where D(t) = d, or NaN: Newton's method in u = ln t (dD/du = t dD/dt from
// md_state) from the grid's bracket, kept inside it (bisection where a step leaves it), to full
// precision in about 4 evaluations where the bracketing solve took about 20 (tests/test_contact_law.cpp).
double md_parameter_solved(double lambda, double turning, double d) noexcept;

// md_parameter_solved, the last answer kept per thread: asperity_load_split asks for the t its
// asperity_response has just solved for
double md_parameter_at(double lambda, double turning, double d) noexcept {
  static thread_local double last_lambda = nan, last_turning = nan, last_d = nan, last_t = nan;
  if (d == last_d && lambda == last_lambda && turning == last_turning) return last_t;
  last_t = md_parameter_solved(lambda, turning, d);
  last_lambda = lambda, last_turning = turning, last_d = d;
  return last_t;
}

double md_parameter_solved(double lambda, double turning, double d) noexcept {
  const double t_high = std::isfinite(turning) ? turning : md_t_max;
  const MdGrid& grid = md_grid(lambda, t_high);
  if (grid.d_high >= d) return t_high;  // at (or, by rounding, below) the lowest interference
  if (!(d < grid.d[0]) || !std::isfinite(d)) return md_parameter_bracketed(lambda, t_high, d);
  int low = 0, high = MdGrid::size - 1;  // grid.d[low] > d >= grid.d[high]
  while (high - low > 1) {
    const int mid = (low + high) / 2;
    (grid.d[mid] > d ? low : high) = mid;
  }
  double u_low = MdGrid::u_first + low * grid.u_step, u_high = MdGrid::u_first + high * grid.u_step;
  if (high == MdGrid::size - 1) u_high = std::log(t_high);
  // the start: linear in D between the bracket's ends
  double u = u_low + (u_high - u_low) * (grid.d[low] - d) / (grid.d[low] - grid.d[high]);
  if (!(u > u_low && u < u_high)) u = 0.5 * (u_low + u_high);
  // Near a turning point D - D_end ~ (u - u_end)^2 (dD/du = 0 there), where Newton on D only halves
  // the distance each step (over 50 evaluations at the interferences a withdrawal's quadrature
  // visits, within 1e-10 of the end): Newton on sqrt(D - D_end), a simple root again
  const bool turning_point = std::isfinite(turning);
  const double target = turning_point ? std::sqrt(d - grid.d_high) : d;
  for (int iteration = 0; iteration < 100; ++iteration) {
    const double t = std::exp(u);
    const MdState st = md_state(lambda, t);
    const double root = turning_point ? std::sqrt(std::fmax(st.d - grid.d_high, 0.0)) : st.d;
    const double f = root - target;
    if (f == 0) return t;
    (f > 0 ? u_low : u_high) = u;  // D falls as t grows
    // df/du: t dD/dt, over 2 sqrt(D - D_end) near a turning point (NaN at the end: a bisection)
    const double slope = turning_point ? (root > 0 ? t * st.dd / (2 * root) : std::nan("")) : t * st.dd;
    const double step = f / slope, close = 4 * std::numeric_limits<double>::epsilon() * std::fmax(1.0, std::fabs(u));
    if (std::fabs(step) <= close) return std::exp(u - step);  // converged (before the bracket: a step below u's ulp)
    double next = u - step;
    if (!(next > u_low && next < u_high)) next = 0.5 * (u_low + u_high);  // Newton left the bracket: bisect
    if (!(u_high - u_low > close)) return std::exp(next);
    u = next;
  }
  return md_parameter_bracketed(lambda, t_high, d);
}

// Far into contact (t -> 0) Maugis-Dugdale becomes Hertz. There, with eps = A^(-1/3) and
// t = s eps^2, the first equation is (2/3) lambda s^3 + (2/3) lambda^2 eps s^2 = 1 (t's leading
// terms; the next are t^2 below them), the tension is lambda A^2 (t + m^2 atan t) = 2 lambda s
// A^(4/3) and D = A^2 less (4/3) lambda s eps^5 of it. Where both shares, 2 lambda s eps^5, are
// below 1e-17 (D over about 1e24 for lambda <= 1; D = omega / d_s may overflow there while Hertz's
// area and stiffness do not), the load, area and stiffness are Hertz's and the tension its
// asymptote: true = Hertz's regime, with the tension [N] and its slope [N/m].
struct MdTension {
  double tension, slope;
};
bool md_hertz_regime(const ContactLaw& law, double w, MdTension& out) noexcept {
  const double lambda = law.maugis_parameter, wc = law.critical_interference;
  if (!(w / wc > 1e20)) return false;
  const double eps = std::pow(wc, 1.0 / 6) / std::pow(w, 1.0 / 6);  // D^(-1/6), D not formed
  const double c3 = (2.0 / 3) * lambda, c2 = (2.0 / 3) * lambda * lambda * eps;
  // Newton from above on an increasing convex cubic: from the smaller one-term root
  double s = std::fmin(std::cbrt(1 / c3), std::sqrt(1 / c2));
  for (int i = 0; i < 100; ++i) {
    const double step = (c3 * s * s * s + c2 * s * s - 1) / (3 * c3 * s * s + 2 * c2 * s);
    if (!(step > 1e-17 * s)) break;
    s -= step;
  }
  if (!(2 * lambda * s * std::pow(eps, 5) < 1e-17)) return false;
  // tension T = 2 lambda s D^(2/3) P_c; dT/dD = (T/D) (2/3 - (eps / (6 s)) ds/deps)
  const double ds_deps = -(c2 / eps) * s * s / (3 * c3 * s * s + 2 * c2 * s);
  const double d23 = std::pow(w, 2.0 / 3) / std::pow(wc, 2.0 / 3);
  out.tension = law.critical_load * 2 * lambda * s * d23;
  out.slope = out.tension / w * (2.0 / 3 - eps / (6 * s) * ds_deps);
  return true;
}

ContactLaw make(double radius, double modulus, const LawValues& v) noexcept {
  return maugis_dugdale_law(radius, modulus, v[LawParameter::work_of_adhesion], v[LawParameter::maugis_parameter]);
}

// t at omega: the branch's end at the lowest interference (D is flat in t at a turning point, so
// that solving for t from a D rounded near it would lose half the digits of P)
double md_parameter_of(const ContactLaw& law, double w) noexcept {
  if (w <= law.lowest_interference) return std::isfinite(law.md_turning) ? law.md_turning : md_t_max;
  return md_parameter_at(law.maugis_parameter, law.md_turning, w / law.critical_interference);
}

AsperityResponse response(const ContactLaw& law, double w) noexcept {
  MdTension far;
  if (md_hertz_regime(law, w, far)) return hertz(law.radius, law.modulus, w);
  const double t = md_parameter_of(law, w);
  if (std::isnan(t)) return {nan, nan, nan};
  const MdState st = md_state(law.maugis_parameter, t);
  // at the turning point (the fixed-grips pull-off) dD/dt = 0: the load falls as omega rises from there
  if (t == law.md_turning) return adhesive_response(law, st.a, st.p, -inf);
  return adhesive_response(law, st.a, st.p, st.dp / st.dd);
}

AsperityLoadSplit load_split(const ContactLaw& law, double w, const AsperityResponse& r) noexcept {
  MdTension far;
  if (md_hertz_regime(law, w, far)) return {r.load + far.tension, far.tension, r.stiffness + far.slope, far.slope};
  const double t = md_parameter_of(law, w);
  if (std::isnan(t)) return {nan, nan, nan, nan};
  const MdState st = md_state(law.maugis_parameter, t);
  const double pc = law.critical_load, kc = law.critical_load / law.critical_interference;
  const double compressive = st.a * st.a * st.a;
  // the tension as computed, not A^3 - Pbar (which cancels far into contact)
  if (t == law.md_turning) return {pc * compressive, pc * st.tension, inf, inf};  // both grow without bound
  const double dcompressive = 3 * st.a * st.a * st.da / st.dd;
  return {pc * compressive, pc * st.tension, kc * dcompressive, kc * st.dtension / st.dd};
}

constexpr LawParameterUse parameters[] = {{LawParameter::work_of_adhesion, true, 0},
                                          {LawParameter::maugis_parameter, true, 0}};

}  // namespace

const ContactLawDescriptor maugis_dugdale_law_descriptor = {
    ContactLawKind::maugis_dugdale, "maugis-dugdale", "Maugis-Dugdale 1992",
    "adhesive elastic spheres with a Dugdale zone, DMT (lambda -> 0) to JKR (lambda -> infinity)",
    LawFamily::adhesive, parameters, 2, make, response, load_split, 0, {0, 0, 0, 0}, false};

}  // namespace detail

// lambda = 2 sigma_0 (R / (pi dgamma K^2))^(1/3), K = (4/3) E*.
ContactLaw maugis_dugdale_law(double radius, double modulus, double work_of_adhesion, double maugis_parameter) noexcept {
  const auto kind = ContactLawKind::maugis_dugdale;
  if (!detail::positive(radius) || !detail::positive(modulus) || !detail::positive(work_of_adhesion) ||
      !detail::positive(maugis_parameter))
    return detail::bad_law(kind);
  ContactLaw law = detail::law_with(kind, radius, modulus);
  law.work_of_adhesion = work_of_adhesion;
  law.maugis_parameter = maugis_parameter;
  detail::set_adhesive_scales(law);
  law.md_turning = detail::md_turning_point(maugis_parameter);
  if (std::isnan(law.md_turning)) return detail::bad_law(kind);
  const double t_end = std::isfinite(law.md_turning) ? law.md_turning : detail::md_t_max;
  // the branch's end, where the asperity is still in contact (the response there is the end's)
  law.lowest_interference = detail::md_state(maugis_parameter, t_end).d * law.critical_interference;
  return law;
}

MaugisDugdalePoint maugis_dugdale_point(double maugis_parameter, double t) noexcept {
  if (!detail::positive(maugis_parameter) || !detail::positive(t)) return {detail::nan, detail::nan, detail::nan, detail::nan};
  const detail::MdState st = detail::md_state(maugis_parameter, t);
  return {t, st.a, st.d, st.p};
}

}  // namespace asperity
