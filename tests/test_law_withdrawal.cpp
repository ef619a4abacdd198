// The withdrawal branch of an adhesive law's rough-surface curves (issue 41, item 2;
// docs/contact-laws.md section 8): after an approach to s0 the flat is withdrawn under fixed
// grips; a summit that touched at s0 stays in contact down to its law's lowest interference.
// The generator's tables against an independent reference computed here in 50-digit arithmetic
// from the single asperity's own equations (JKR's closed form, Maugis-Dugdale's three equations in
// its parameter t), not from asperity_response or the generator: the integral over the summit
// heights in the branch's parameter (smooth through the branch's end, where dP/domega is
// infinite), the stiffness by parts (the edge's load times its density, and the load against the
// density's slope). Then the sphere limit (JKR's unloading curve and its pull-offs) and
// Fuller-Tabor's table of docs/contact-laws.md section 5.
#include <gtest/gtest.h>

#include <boost/math/quadrature/gauss.hpp>
#include <boost/math/quadrature/tanh_sinh.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <vector>

#include "asperity/asperity.h"
#include "asperity/contact_curves.hpp"
#include "asperity/contact_law.hpp"
#include "asperity/error.hpp"
#include "asperity/generator/law_curves.hpp"
#include "asperity/scene.hpp"
#include "test_subsample.hpp"

namespace {

using Real = boost::multiprecision::cpp_bin_float_50;
using namespace asperity;

const Real pi = boost::math::constants::pi<Real>();

// The test's surface and material (docs/contact-laws.md's adhesive tables'): E*, R, dgamma, eta
constexpr double modulus = 1.13e11, radius = 1e-4, work = 0.5, density = 4e8, area = 1e-4;

// One asperity on its law's stable branch in a parameter q, in Maugis' units (K = 4E*/3,
// a_s = (pi dgamma R^2 / K)^(1/3), d_s = a_s^2 / R, load in pi dgamma R): D(q) rising with q from
// the branch's end q_end, the load Pbar, the contact radius Abar, and dD/dq.
// Also dPbar/dq and dAbar/dq (the load's slope in omega is their dP/dq over dD/dq).
struct BranchPoint {
  Real d, slope, load, radius, load_slope, radius_slope;
};

// JKR: q = Abar, D = A^2 - (2/3) sqrt(6 A), P = A^3 - sqrt(6) A^(3/2); the end A = 6^(-1/3)
BranchPoint jkr_point(const Real& a) {
  const Real s6 = sqrt(Real(6)), root = sqrt(a);
  return {a * a - Real(2) / 3 * s6 * root, 2 * a - s6 / (3 * root), a * a * a - s6 * a * root, a,
          3 * a * a - Real(3) / 2 * s6 * root, Real(1)};
}

// Maugis-Dugdale, q = -ln t (m = c/a, t = sqrt(m^2 - 1)): for t the first equation is a
// quadratic in A, (lambda A^2/2)[t + (m^2-2) atan t] + (4 lambda^2 A/3)[t atan t - m + 1] = 1;
// P = A^3 - lambda A^2 [t + m^2 atan t], D = A^2 - (4/3) A lambda t. dD/dq by implicit
// differentiation of the quadratic.
BranchPoint md_point(const Real& lambda, const Real& q) {
  const Real t = exp(-q), m2 = 1 + t * t, m = sqrt(m2), at = atan(t);
  const Real c2 = lambda / 2 * (t + (m2 - 2) * at), c1 = 4 * lambda * lambda / 3 * (t * at - m + 1);
  const Real a = (-c1 + sqrt(c1 * c1 + 4 * c2)) / (2 * c2);
  const Real dc2 = lambda * (t * at + t * t / m2), dc1 = 4 * lambda * lambda / 3 * (at + t / m2 - t / m);
  const Real da_dt = -(dc2 * a * a + dc1 * a) / (2 * c2 * a + c1);
  const Real dd_dt = 2 * a * da_dt - Real(4) / 3 * lambda * (da_dt * t + a);
  const Real g = t + m2 * at, dp_dt = 3 * a * a * da_dt - lambda * (2 * a * da_dt * g + a * a * (2 + 2 * t * at));
  return {a * a - Real(4) / 3 * a * lambda * t, -t * dd_dt, a * a * a - lambda * a * a * g, a, -t * dp_dt, -t * da_dt};
}

struct Branch {
  std::function<BranchPoint(const Real&)> at;
  Real q_end;
};

// MD's branch end: its turning point dD/dq = 0 (lambda >= 0.94), by bisection in q. Below
// (lambda <= 0.93) D rises with q everywhere and the branch ends where the contact vanishes,
// t -> inf (A -> 0, D and P to finite limits: the summit leaves with a finite tension, as DMT's):
// there at t = 1e12, the law's stated end (maugis_dugdale.cpp's md_t_max; D within 1e-12 of its limit,
// which the test measures)
Branch md_branch(double lambda) {
  const Real l = lambda;
  Real lo = -std::log(1e6), hi = std::log(1e6);  // dD/dq < 0 beyond the turning point (t larger)
  if (!(md_point(l, lo).slope < 0)) return {[l](const Real& q) { return md_point(l, q); }, -log(Real(1e12))};
  for (int i = 0; i < 200; ++i) {
    const Real mid = (lo + hi) / 2;
    (md_point(l, mid).slope > 0 ? hi : lo) = mid;
  }
  return {[l](const Real& q) { return md_point(l, q); }, hi};
}
Branch jkr_branch() { return {jkr_point, pow(Real(6), Real(-1) / 3)}; }

// q on the branch where D(q) = target (D rises with q from q_end)
Real solve_branch(const Branch& b, const Real& target) {
  Real lo = b.q_end, step = 1, hi = lo + step;
  while (b.at(hi).d < target) lo = hi, step *= 2, hi = lo + step;
  // Newton from the bracket's middle, kept inside it by bisection
  Real q = (lo + hi) / 2;
  for (int i = 0; i < 200; ++i) {
    const BranchPoint p = b.at(q);
    const Real f = p.d - target;
    (f < 0 ? lo : hi) = q;
    Real next = q - f / p.slope;
    if (!(next > lo && next < hi)) next = (lo + hi) / 2;
    if (abs(next - q) < Real(1e-45) * (1 + abs(q)) || hi - lo < Real(1e-45) * (1 + abs(q))) return next;
    q = next;
  }
  return q;
}

// The summits' heights h (units of sigma_s, origin convention; a summit at h has interference
// sigma_s (h - s)): the density, its slope, and where it is integrated. Gaussian: the whole line
// to h = 13 (the density below 1e-36 of its peak beyond). Weibull (docs/model.md section 1, shape
// a): on the tail side phi_a(h) = a h^(a-1) exp(-h^a), h >= 0, to where exp(-h^a) < 1e-36; on the
// bounded side the heights mirrored, phi_a(-h), h <= 0, up to its top h = 0, where for a < 1 the
// density is infinite (integrable) and its slope is not integrable: there the load is integrated
// directly, its stiffness from dP/domega (`direct_top`), in w = (-h)^a, where phi_a(-h) dh = e^-w dw.
struct Heights {
  std::function<Real(const Real&)> density, slope;
  Real lowest, highest;  // the support's ends (the Gaussian's lowest: -inf)
  bool direct_top = false;
  Real shape = 0;
};

Heights gaussian_heights() {
  return {[](const Real& h) { return exp(-h * h / 2) / sqrt(2 * pi); },
          [](const Real& h) { return -h * exp(-h * h / 2) / sqrt(2 * pi); }, Real(-1e9), Real(13)};
}

Heights weibull_heights(double shape, Side side) {
  const Real a = shape;
  const Real highest = pow(log(Real(10)) * 36, 1 / a);  // exp(-h^a) = 1e-36
  if (side == Side::tail)
    return {[a](const Real& h) { return a * pow(h, a - 1) * exp(-pow(h, a)); },
            [a](const Real& h) { return a * pow(h, a - 2) * exp(-pow(h, a)) * (a - 1 - a * pow(h, a)); }, Real(0),
            highest};
  return {[a](const Real& h) { return a * pow(-h, a - 1) * exp(-pow(-h, a)); },
          [a](const Real& h) { return -a * pow(-h, a - 2) * exp(-pow(-h, a)) * (a - 1 - a * pow(-h, a)); }, -highest,
          Real(0), true, a};
}

// The reference at dimensionless separation s after an approach to s0 (summits of scale sigma):
// net pressure and its parts [Pa], stiffness and its parts [Pa/m], area fraction
struct Reference {
  double pressure, compressive, tensile, stiffness, compressive_stiffness, tensile_stiffness, area_fraction;
};

// `kink`: the generator's, in double (s0 - omega_min / sigma_s with the law's omega_min): at it the
// right side (summits detaching), as the curves are served at a break.
//
// p = eta I, I(s) = int_{h_e}^{top} P(sigma (h - s)) phi(h) dh, h_e = max(s0, s + omega_min/sigma, the
// support's lowest): fixed at s0 (or the support) before the kink, moving after it. The stiffness
// -(eta/sigma) dI/ds, split at h_m: below it by parts in v = h - s, [P phi] at the fixed edge and
// int P phi' dh (no dP/domega, infinite at the branch's end), less P phi at h_m; above it (only where
// the density's top is singular) -sigma int dP/domega phi dh, the limits fixed.
Reference withdrawal_reference(const Branch& b, const Heights& heights, double sigma_d, double s0_d, double s_d,
                               double kink) {
  const Real K = Real(4) / 3 * modulus, R = radius, dgamma = work, sigma = sigma_d, eta = density;
  const Real a_s = cbrt(pi * dgamma * R * R / K), d_s = a_s * a_s / R, unit = pi * dgamma * R;
  const Real s0 = s0_d, s = s_d;
  const bool detaching = s_d >= kink;
  const Real h_detach = s + b.at(b.q_end).d * d_s / sigma;  // where omega = omega_min
  // detaching: the edge moves with s, unless the support's lowest end is above it (a Weibull tail
  // whose every summit touched at s0 < 0), which is then the fixed edge
  const Real fixed = s0 > heights.lowest ? s0 : heights.lowest;
  const bool moving = detaching && h_detach > heights.lowest;
  const Real h_e = moving ? h_detach : detaching ? Real(heights.lowest) : fixed;
  const Real h_m = heights.direct_top ? (h_e + heights.highest) / 2 : heights.highest;
  const Real q_e = moving ? b.q_end : solve_branch(b, sigma * (h_e - s) / d_s);
  auto h_of = [&](const BranchPoint& p) { return s + p.d * d_s / sigma; };
  // pieces of 1/2 in h from the edge to h_m (and the piece that ends there)
  std::vector<Real> cuts{q_e};
  for (Real h = h_of(b.at(q_e)) + 0.5; h < h_m; h += 0.5) cuts.push_back(solve_branch(b, (h - s) * sigma / d_s));
  cuts.push_back(solve_branch(b, (h_m - s) * sigma / d_s));
  // integrals of the load's parts and the area against phi dh, and the parts against phi' dh
  Real c = 0, p = 0, a = 0, c_slope = 0, p_slope = 0;
  using Gauss = boost::math::quadrature::gauss<Real, 40>;
  const auto& x = Gauss::abscissa();
  const auto& w = Gauss::weights();
  const auto compressive_of = [&](const BranchPoint& point) { return K * pow(point.radius * a_s, 3) / R; };
  for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
    const Real mid = (cuts[i] + cuts[i + 1]) / 2, half = (cuts[i + 1] - cuts[i]) / 2;
    for (std::size_t k = 0; k < x.size(); ++k)
      for (int sign : {-1, 1}) {
        if (k == 0 && sign == 1 && x[0] == 0) continue;  // the middle abscissa once
        const Real q = mid + sign * half * x[k];
        const BranchPoint point = b.at(q);
        const Real h = h_of(point), dh = point.slope * d_s / sigma * half * w[k];
        const Real density_value = heights.density(h), density_slope = heights.slope(h);
        const Real load = point.load * unit, compressive = compressive_of(point);
        c += compressive * density_value * dh;
        p += load * density_value * dh;
        a += pi * pow(point.radius * a_s, 2) * density_value * dh;
        c_slope += compressive * density_slope * dh;
        p_slope += load * density_slope * dh;
      }
  }
  // the fixed edge's terms (before the kink the edge is h = s0, where the interference is above omega_min)
  Real edge_c = 0, edge_p = 0;
  if (!moving) {
    const BranchPoint point = b.at(q_e);
    edge_c = compressive_of(point) * heights.density(h_e);
    edge_p = point.load * unit * heights.density(h_e);
  }
  // the direct piece above h_m: in w = (-h)^a from 0 to (-h_m)^a, pieces of 1/4 in w
  if (heights.direct_top) {
    const BranchPoint at_m = b.at(cuts.back());
    edge_c -= compressive_of(at_m) * heights.density(h_m);
    edge_p -= at_m.load * unit * heights.density(h_m);
    const Real w_m = pow(-h_m, heights.shape);
    const int pieces = static_cast<int>(ceil(static_cast<double>(w_m) * 4));
    for (int i = 0; i < pieces; ++i) {
      const Real mid = w_m * (2 * i + 1) / (2 * pieces), half = w_m / (2 * pieces);
      for (std::size_t k = 0; k < x.size(); ++k)
        for (int sign : {-1, 1}) {
          if (k == 0 && sign == 1 && x[0] == 0) continue;
          const Real wv = mid + sign * half * x[k], h = -pow(wv, 1 / heights.shape);
          const BranchPoint point = b.at(solve_branch(b, sigma * (h - s) / d_s));
          const Real weight = exp(-wv) * half * w[k];  // phi dh
          // dP/domega sigma = (dP/dq)/(dD/dq) unit sigma / d_s; the compressive part's likewise
          const Real per_d = sigma / (point.slope * d_s);
          const Real compressive = compressive_of(point);
          const Real compressive_slope = 3 * compressive / point.radius * point.radius_slope;
          c += compressive * weight;
          p += point.load * unit * weight;
          a += pi * pow(point.radius * a_s, 2) * weight;
          c_slope -= compressive_slope * per_d * weight;
          p_slope -= point.load_slope * unit * per_d * weight;
        }
    }
  }
  Reference out;
  out.compressive = static_cast<double>(eta * c);
  out.tensile = static_cast<double>(eta * (c - p));
  out.pressure = static_cast<double>(eta * p);
  out.compressive_stiffness = static_cast<double>(-eta / sigma * (edge_c + c_slope));
  out.stiffness = static_cast<double>(-eta / sigma * (edge_p + p_slope));
  out.tensile_stiffness = static_cast<double>(-eta / sigma * (edge_c - edge_p + c_slope - p_slope));
  out.area_fraction = static_cast<double>(eta * a);
  return out;
}

// JKR's delta_c = (3/4)(pi^2 dgamma^2 R / E*^2)^(1/3): Fuller-Tabor's unit of sigma
double delta_c() { return 0.75 * std::cbrt(M_PI * M_PI * work * work * radius / (modulus * modulus)); }

// The summits of a case: Gaussian, or Weibull of a shape on a side
struct Summits {
  Distribution distribution = Distribution::gaussian;
  double shape = 0.0 / 0.0;
  Side side = Side::tail;
  Heights heights() const {
    return distribution == Distribution::gaussian ? gaussian_heights() : weibull_heights(shape, side);
  }
  std::string name() const {
    char text[64];
    if (distribution == Distribution::gaussian) return "Gaussian";
    std::snprintf(text, sizeof text, "Weibull %s a = %g", side == Side::tail ? "tail" : "bounded", shape);
    return text;
  }
};

SceneLaw withdrawal_scene(ContactLawKind kind, double lambda, double sigma, double s0, double s_max,
                          double tolerance = 1e-6, const Summits& summits = Summits()) {
  SceneLawInputs in;
  in.law = kind;
  in.material.set(LawParameter::work_of_adhesion, work);
  if (kind == ContactLawKind::maugis_dugdale) in.material.set(LawParameter::maugis_parameter, lambda);
  in.contact_modulus = modulus;
  in.distribution = summits.distribution;
  if (summits.distribution == Distribution::weibull) {
    in.shape = summits.shape;
    in.side = summits.side;
    in.side_given = true;
  }
  in.height_scale = sigma;
  in.summit_radius = radius;
  in.summit_density = density;
  in.nominal_area = area;
  in.range_min = s0;
  in.range_max = s_max;
  in.max_rel_error = tolerance;
  in.approach_separation = s0;
  return make_scene_law(in, LawNaming::scene_key);
}

struct Worst {
  double pressure = 0, stiffness = 0, area = 0, parts = 0;
};

// The served curves against the reference at s, relative to the gross (docs/contact-laws.md)
void compare(const ContactCurves& curves, const Reference& r, double sigma, double s, Worst& worst) {
  const double u = sigma * s;
  const ContactCurvesState state = curves.at_separation(u), part = curves.tensile_part(u);
  const double gross = r.compressive + r.tensile;
  const double gross_k = std::fabs(r.compressive_stiffness) + std::fabs(r.tensile_stiffness);
  const double ep = std::fabs(state.pressure - r.pressure) / gross;
  const double ek = std::fabs(state.stiffness - r.stiffness) / gross_k;
  const double ea = std::fabs(state.area_fraction - r.area_fraction) / r.area_fraction;
  const double parts = std::max({std::fabs(part.pressure - r.tensile) / gross,
                                 std::fabs(state.pressure + part.pressure - r.compressive) / gross,
                                 std::fabs(part.stiffness - r.tensile_stiffness) / gross_k,
                                 std::fabs(state.stiffness + part.stiffness - r.compressive_stiffness) / gross_k});
  if (std::getenv("WITHDRAWAL_DEBUG")) std::printf("  s = %.17g: p %.2e k %.2e a %.2e parts %.2e\n", s, ep, ek, ea, parts);
  worst.pressure = std::max(worst.pressure, ep);
  worst.stiffness = std::max(worst.stiffness, ek);
  worst.area = std::max(worst.area, ea);
  worst.parts = std::max(worst.parts, parts);
}

// The withdrawal table of a law against the reference where the method is weakest: just above s0,
// both sides of the kink s0 - omega_min / sigma_s, both sides of the pull-off; and 20 spread points
void check_against_reference(ContactLawKind kind, double lambda, const Branch& branch, double dc, double s0,
                             const char* label, const Summits& summits = Summits(), double s_max = 0.0 / 0.0) {
  const double sigma = dc * delta_c();
  if (std::isnan(s_max)) s_max = s0 + 6;
  const Heights heights = summits.heights();
  const SceneLaw law = withdrawal_scene(kind, lambda, sigma, s0, s_max, 1e-6, summits);
  const auto start = std::chrono::steady_clock::now();
  const generator::LawCurvesResult result = generator::generate_law_curves(law);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const ContactCurves curves(result.data);
  const double kink = generator::withdrawal_kink(law), span = s_max - s0;
  ASSERT_GT(kink, s0);
  ASSERT_LT(kink, s_max);
  std::vector<double> points{s0, s0 + 1e-9 * span, s0 + 1e-6 * span, s0 + 1e-3 * span, kink, s_max};
  for (double offset : {1e-9, 1e-7, 1e-5, 1e-3, 1e-2})
    for (int sign : {-1, 1}) points.push_back(kink + sign * offset * span);
  const double pull_off = curves.pull_off_separation() / sigma;
  ASSERT_TRUE(std::isfinite(pull_off)) << label;
  for (double offset : {1e-6, 1e-3, 1e-2})
    for (int sign : {-1, 1}) points.push_back(pull_off + sign * offset * span);
  for (std::size_t i = 0; i < 20; i += test::subsample_stride()) points.push_back(s0 + span * (i + 0.37) / 20);
  points.erase(std::remove_if(points.begin(), points.end(), [&](double s) { return !(s >= s0 && s <= s_max); }),
               points.end());
  Worst worst;
  for (double s : points) compare(curves, withdrawal_reference(branch, heights, sigma, s0, s, kink), sigma, s, worst);
  // the pull-off against the reference's least pressure, by golden section about the served one
  double lo = std::max(s0, pull_off - 0.05), hi = std::min(s_max, pull_off + 0.05);
  const double r = (std::sqrt(5.0) - 1) / 2;
  auto pressure = [&](double s) { return withdrawal_reference(branch, heights, sigma, s0, s, kink).pressure; };
  double c = hi - r * (hi - lo), d = lo + r * (hi - lo), pc = pressure(c), pd = pressure(d);
  for (int i = 0; i < 30; ++i) {  // golden section, one new evaluation a step
    if (pc < pd) hi = d, d = c, pd = pc, c = hi - r * (hi - lo), pc = pressure(c);
    else lo = c, c = d, pc = pd, d = lo + r * (hi - lo), pd = pressure(d);
  }
  const Reference least = withdrawal_reference(branch, heights, sigma, s0, 0.5 * (lo + hi), kink);
  const double pull_off_error = std::fabs(curves.pull_off_pressure() - least.pressure) / (least.compressive + least.tensile);
  const double tolerance = law.max_rel_error;
  const double* bound = result.data.max_rel_error;
  std::printf("| %s, %s, dc = %g, s0 = %g [%g, %g] | %d | %.2f s | %.2e / %.2e / %.2e | %.2e / %.2e / %.2e / %.2e "
              "| %.4f (%.1e, %.1e sigma_s) |\n",
              label, summits.name().c_str(), dc, s0, s0, s_max, result.nodes, seconds, bound[0], bound[1], bound[2], worst.pressure, worst.stiffness,
              worst.area, worst.parts, pull_off, pull_off_error, std::fabs(pull_off - 0.5 * (lo + hi)));
  EXPECT_LE(worst.pressure, bound[0]) << label;
  EXPECT_LE(worst.stiffness, bound[1]) << label;
  EXPECT_LE(worst.area, bound[2]) << label;
  EXPECT_LE(worst.parts, std::max(bound[0], bound[1])) << label;
  EXPECT_LE(worst.pressure, tolerance) << label;
  EXPECT_LE(worst.area, tolerance) << label;
  EXPECT_LE(pull_off_error, bound[0]) << label;
}

}  // namespace

// Under the sanitizers (ASPERITY_TEST_SUBSAMPLE, CI) one case of each law: the code is the same, and
// each case's 50-digit references take minutes there (the whole test 476 s under ASan, 23 s without).
TEST(LawWithdrawal, JkrAgainstItsClosedFormReference) {
  check_against_reference(ContactLawKind::jkr, 0, jkr_branch(), 1.0, -1.0, "JKR");
  if (test::subsample_stride() == 1) check_against_reference(ContactLawKind::jkr, 0, jkr_branch(), 0.5, 0.0, "JKR");
}

TEST(LawWithdrawal, MaugisDugdaleAgainstItsExactEquations) {
  check_against_reference(ContactLawKind::maugis_dugdale, 1, md_branch(1), 1.0, -1.0, "MD lambda = 1");
  if (test::subsample_stride() == 1)
    check_against_reference(ContactLawKind::maugis_dugdale, 3, md_branch(3), 1.0, 0.0, "MD lambda = 3");
}

// JKR on Weibull summits (issue 41, item 2): a tail a = 2 with an edge at s0 > 0 (the summits below
// never touched), and a bounded a = 0.5, whose density is infinite at its top h = 0 (integrated
// there in w = (-h)^a, its stiffness from dP/domega: the density's slope is not integrable there)
TEST(LawWithdrawal, JkrOnWeibullSummitsAgainstItsClosedFormReference) {
  Summits tail{Distribution::weibull, 2, Side::tail}, bounded{Distribution::weibull, 0.5, Side::bounded};
  // under the sanitizers the bounded side alone (its table the cheaper; the direct piece is the test's own code)
  if (test::subsample_stride() == 1) check_against_reference(ContactLawKind::jkr, 0, jkr_branch(), 1.0, 0.5, "JKR", tail, 6.5);
  check_against_reference(ContactLawKind::jkr, 0, jkr_branch(), 1.0, -3.0, "JKR", bounded, -0.02);
}

// Maugis-Dugdale below its turning point (lambda <= 0.93: D rises with t to the end, where the contact
// vanishes and the summit leaves at a finite tension): one asperity's unloading against the reference's
// three equations solved here, its lowest interference against the branch's limit, and the withdrawal
// table against the reference
TEST(LawWithdrawal, MaugisDugdaleWithoutATurningPoint) {
  const double K = 4 * modulus / 3, a_s = std::cbrt(M_PI * work * radius * radius / K), d_s = a_s * a_s / radius;
  for (double lambda : {0.1, 0.5, 0.93}) {
    const Branch b = md_branch(lambda);
    ASSERT_GT(b.at(b.q_end + Real(1e-3)).slope, 0) << lambda;  // no turning point: D rises from the end
    const ContactLaw law = maugis_dugdale_law(radius, modulus, work, lambda);
    // the end: the law's omega_min against D at t = 1e12 and at the limit (t = 1e30)
    const double end = static_cast<double>(b.at(b.q_end).d), limit = static_cast<double>(b.at(-log(Real(1e30))).d);
    EXPECT_NEAR(law.lowest_interference / d_s, end, 1e-12 * std::fabs(end)) << lambda;
    EXPECT_NEAR(end, limit, 1e-10 * std::fabs(limit)) << lambda;
    // the unloading: from the law's end (omega_min < 0, the summit in tension) up to omega = 2 d_s
    double worst = 0, worst_stiffness = 0;
    for (int i = 0; i <= 100; i += static_cast<int>(test::subsample_stride())) {
      const double omega = law.lowest_interference + (2 * d_s - law.lowest_interference) * std::pow(i / 100.0, 2);
      const BranchPoint point = b.at(solve_branch(b, omega / d_s));
      const AsperityResponse r = asperity_response(law, omega);
      const double unit = M_PI * work * radius, load = static_cast<double>(point.load) * unit;
      const double stiffness = static_cast<double>(point.load_slope / point.slope) * unit / d_s;
      worst = std::max(worst, std::fabs(r.load - load) / unit);
      if (i > 0) worst_stiffness = std::max(worst_stiffness, std::fabs(r.stiffness - stiffness) / std::fabs(stiffness));
    }
    std::printf("MD lambda = %g: omega_min / d_s = %.15g (limit %.15g); 101 interferences to 2 d_s: load within %.1e pi dgamma "
                "R, stiffness %.1e\n", lambda, end, limit, worst, worst_stiffness);
    EXPECT_LT(worst, 1e-10) << lambda;
    EXPECT_LT(worst_stiffness, 1e-6) << lambda;
  }
  // the table (under the sanitizers not: its code is MD lambda = 1's, checked above)
  if (test::subsample_stride() == 1)
    check_against_reference(ContactLawKind::maugis_dugdale, 0.5, md_branch(0.5), 1.0, -1.0, "MD lambda = 0.5");
}

namespace {

// Fuller-Tabor's ratio of docs/contact-laws.md section 5 from a withdrawal table: the pull-off over
// what the summits that touched at s0 would carry on a smooth surface, each its law's greatest
// tension (JKR (3/2) pi dgamma R; MD the least of its branch's load, by golden section here)
double fuller_tabor_ratio(ContactLawKind kind, double lambda, double dc, double s0) {
  const double sigma = dc * delta_c();
  SceneLaw probe = withdrawal_scene(kind, lambda, sigma, s0, s0 + 1);
  const double kink = generator::withdrawal_kink(probe);
  const SceneLaw law = withdrawal_scene(kind, lambda, sigma, s0, kink + 4);
  const ContactCurves curves(generator::generate_law_curves(law).data);
  double smooth = 1.5;
  if (kind == ContactLawKind::maugis_dugdale) {
    const Branch b = md_branch(lambda);
    Real lo = b.q_end, hi = b.q_end + 20;
    const Real r = (sqrt(Real(5)) - 1) / 2;
    for (int i = 0; i < 200; ++i) {
      const Real c = hi - r * (hi - lo), d = lo + r * (hi - lo);
      if (b.at(c).load < b.at(d).load) hi = d;
      else lo = c;
    }
    smooth = -static_cast<double>(b.at((lo + hi) / 2).load);
  }
  const double touched = density * 0.5 * std::erfc(s0 / std::sqrt(2.0));
  return curves.pull_off_pressure() / (-smooth * M_PI * work * radius * touched);
}

// JKR's closed form on its stable branch: the load [N] at interference omega [m] (A by bisection)
double jkr_load(double omega) {
  const double K = 4 * modulus / 3, a_s = std::cbrt(M_PI * work * radius * radius / K), d_s = a_s * a_s / radius;
  double lo = std::pow(6.0, -1.0 / 3), hi = 1e3;
  for (int i = 0; i < 200; ++i) {
    const double a = 0.5 * (lo + hi);
    (a * a - 2.0 / 3 * std::sqrt(6 * a) < omega / d_s ? lo : hi) = a;
  }
  const double a = 0.5 * (lo + hi);
  return (a * a * a - std::sqrt(6.0) * std::pow(a, 1.5)) * M_PI * work * radius;
}

}  // namespace

// docs/contact-laws.md's Fuller-Tabor table (section 5, computed by the reference of
// tests/contact_law_reference.hpp): the tabulated withdrawal's pull-off reproduces it to its 4 digits
TEST(LawWithdrawal, FullerTaborTable) {
  struct Row {
    ContactLawKind kind;
    double lambda, s0, dc, table;
  };
  const Row rows[] = {
      {ContactLawKind::jkr, 0, 0, 0.2, 0.9917},           {ContactLawKind::jkr, 0, 0, 1, 0.8091},
      {ContactLawKind::jkr, 0, 0, 2, 0.2880},             {ContactLawKind::jkr, 0, -2, 0.5, 0.8312},
      {ContactLawKind::jkr, 0, -2, 1.5, 0.2876},          {ContactLawKind::maugis_dugdale, 1, 0, 0.5, 0.9556},
      {ContactLawKind::maugis_dugdale, 1, 0, 2, 0.3328},  {ContactLawKind::maugis_dugdale, 3, 0, 1, 0.8127},
  };
  // every subsample_stride()-th row under the sanitizers (JKR's first and MD lambda = 1's first at 5)
  for (std::size_t k = 0; k < std::size(rows); k += test::subsample_stride()) {
    const Row& row = rows[k];
    const double ratio = fuller_tabor_ratio(row.kind, row.lambda, row.dc, row.s0);
    std::printf("Fuller-Tabor %s lambda %g s0 %g dc %g: %.6f (table %.4f)\n", contact_law_name(row.kind), row.lambda,
                row.s0, row.dc, ratio, row.table);
    EXPECT_NEAR(ratio, row.table, 5.01e-5) << contact_law_name(row.kind) << " dc " << row.dc << " s0 " << row.s0;
  }
}

// The sphere limit: summits whose heights spread over 1/100 of delta_c (Fuller-Tabor's dc =
// 0.01), all touched (s0 = -6), unload as one JKR sphere: the curve per summit is JKR's P(omega)
// at omega = -u to O(dc^2), the pull-off its fixed-load -(3/2) pi dgamma R, and the stiffness's
// jump at the kink (summits leaving at the fixed-grips end) eta phi(s0)/sigma_s times JKR's load
// there, -(5/6) pi dgamma R
TEST(LawWithdrawal, JkrSphereLimit) {
  const double dc = 0.01, sigma = dc * delta_c(), s0 = -6;
  SceneLaw probe = withdrawal_scene(ContactLawKind::jkr, 0, sigma, s0, s0 + 1);
  const double kink = generator::withdrawal_kink(probe);
  const SceneLaw law = withdrawal_scene(ContactLawKind::jkr, 0, sigma, s0, kink + 6);
  const ContactCurves curves(generator::generate_law_curves(law).data);
  const double touched = density * 0.5 * std::erfc(s0 / std::sqrt(2.0)), unit = M_PI * work * radius;
  for (double omega_over_dc : {0.05, 0.0, -0.2, -0.4, -0.6}) {
    const double omega = omega_over_dc * delta_c();
    EXPECT_NEAR(curves.pressure(-omega) / touched / unit, jkr_load(omega) / unit, 1e-3) << "omega/delta_c " << omega_over_dc;
  }
  EXPECT_NEAR(curves.pull_off_pressure() / touched / unit, -1.5, 1e-4);
  // the pull-off where JKR's load is least: A^3 = 3/2, omega = d_s (A^2 - (2/3) sqrt(6 A))
  const double K = 4 * modulus / 3, a_s = std::cbrt(M_PI * work * radius * radius / K), d_s = a_s * a_s / radius;
  const double a = std::cbrt(1.5), omega_pull = d_s * (a * a - 2.0 / 3 * std::sqrt(6 * a));
  EXPECT_NEAR(curves.pull_off_separation(), -omega_pull, 1e-3 * delta_c());
  // the break: the stiffness left and right of the kink, as stored
  const ContactCurvesData& data = curves.data();
  std::size_t at = 0;
  for (std::size_t i = 1; i < data.separation.size(); ++i)
    if (data.separation[i] == data.separation[i - 1]) at = i;
  ASSERT_GT(at, 0u);
  EXPECT_EQ(data.separation[at], sigma * kink);
  const double jump = (data.stiffness[at] - data.tensile_stiffness[at]) - (data.stiffness[at - 1] - data.tensile_stiffness[at - 1]);
  const double phi = std::exp(-0.5 * s0 * s0) / std::sqrt(2 * M_PI);
  // to the rounding of the stored stiffnesses, whose difference it is
  EXPECT_NEAR(jump, -5.0 / 6 * unit * density * phi / sigma, 1e-14 * data.stiffness[at]);
}

// DMT's lowest interference is 0: its withdrawal is its approach, node for node
TEST(LawWithdrawal, DmtWithdrawalIsItsApproach) {
  const double sigma = 2e-9;
  SceneLaw withdrawal = withdrawal_scene(ContactLawKind::dmt, 0, sigma, -1, 4);
  SceneLaw approach = withdrawal;
  approach.approach_separation = std::numeric_limits<double>::quiet_NaN();
  const ContactCurvesData w = generator::generate_law_curves(withdrawal).data;
  const ContactCurvesData a = generator::generate_law_curves(approach).data;
  EXPECT_EQ(w.separation, a.separation);
  EXPECT_EQ(w.pressure, a.pressure);
  EXPECT_EQ(w.stiffness, a.stiffness);
  EXPECT_EQ(w.tensile_pressure, a.tensile_pressure);
  EXPECT_EQ(w.tensile_stiffness, a.tensile_stiffness);
  EXPECT_EQ(w.area_fraction, a.area_fraction);
  EXPECT_EQ(w.summit_count, a.summit_count);
  EXPECT_NE(w.description.find("withdrawal"), std::string::npos);
  EXPECT_NE(w.description.find("the same curves as the approach branch"), std::string::npos);
  EXPECT_EQ(ContactCurves(w).pull_off_pressure(), ContactCurves(a).pull_off_pressure());
}

// Refused, naming the key: a law without adhesion, s0 above the range, s0 not finite, the bounded side at s0 >= 0
TEST(LawWithdrawal, BadApproachSeparationsAreRefused) {
  SceneLawInputs in;
  in.law = ContactLawKind::jkr;
  in.material.set(LawParameter::work_of_adhesion, work);
  in.contact_modulus = modulus;
  in.height_scale = 2e-9;
  in.summit_radius = radius;
  in.summit_density = density;
  in.nominal_area = area;
  in.range_min = -1;
  in.range_max = 4;
  const auto refusal = [&](SceneLawInputs inputs) -> std::string {
    try {
      make_scene_law(inputs, LawNaming::option);
    } catch (const SceneLawError& error) {
      EXPECT_EQ(error.key, "approach_separation");
      return error.what();
    }
    return "";
  };
  SceneLawInputs hertz = in;
  hertz.law = ContactLawKind::hertz;
  hertz.material = LawValues();
  hertz.approach_separation = -1;
  EXPECT_NE(refusal(hertz).find("hertz has no withdrawal branch apart from its approach"), std::string::npos);
  SceneLawInputs above = in;
  above.approach_separation = -0.5;
  EXPECT_NE(refusal(above).find("--approach-separation -0.5 is above the separation range's lower end -1"),
            std::string::npos);
  SceneLawInputs infinite = in;
  infinite.approach_separation = HUGE_VAL;
  EXPECT_NE(refusal(infinite).find("must be a finite"), std::string::npos);
  SceneLawInputs bounded = in;
  bounded.distribution = Distribution::weibull;
  bounded.shape = 2;
  bounded.side = Side::bounded;
  bounded.side_given = true;
  bounded.range_min = -3;
  bounded.range_max = -0.5;
  bounded.approach_separation = 0;
  EXPECT_NE(refusal(bounded).find("must be below 0"), std::string::npos);
  SceneLawInputs good = in;
  good.approach_separation = -1.5;
  EXPECT_NO_THROW(make_scene_law(good, LawNaming::option));
}

// The table format's break: only with a tensile part, inside the range, the values continuous;
// a withdrawal table written and read back is the same
TEST(LawWithdrawal, TheBreakInTheTableFormat) {
  const SceneLaw law = withdrawal_scene(ContactLawKind::jkr, 0, 2e-9, -1, 4, 1e-4);
  const ContactCurvesData data = generator::generate_law_curves(law).data;
  const std::string path = std::string(ASPERITY_TEST_BINARY_DIR) + "/withdrawal.h5";
  write_contact_curves_file(data, path, true);
  const ContactCurvesData back = read_contact_curves_file(path);
  EXPECT_EQ(back.separation, data.separation);
  EXPECT_EQ(back.stiffness, data.stiffness);
  EXPECT_EQ(back.description, data.description);
  // the branch stated (sigma_s s0, the first node) and read back
  EXPECT_EQ(data.approach_separation, 2e-9 * -1);
  EXPECT_EQ(back.approach_separation, data.approach_separation);
  EXPECT_TRUE(back.withdrawal());
  const ContactCurves curves(back);
  std::size_t at = 0;
  for (std::size_t i = 1; i < data.separation.size(); ++i)
    if (data.separation[i] == data.separation[i - 1]) at = i;
  ASSERT_GT(at, 1u);
  // served from the right at the break, continuous in pressure across it
  EXPECT_NEAR(curves.stiffness(data.separation[at]), data.stiffness[at] - data.tensile_stiffness[at],
              1e-12 * data.stiffness[at]);
  const double below = std::nextafter(data.separation[at], -HUGE_VAL);
  EXPECT_NEAR(curves.stiffness(below), data.stiffness[at - 1] - data.tensile_stiffness[at - 1],
              1e-6 * std::fabs(data.stiffness[at - 1]));
  EXPECT_NEAR(curves.pressure(below), curves.pressure(data.separation[at]), 1e-12 * data.pressure[at]);
  // the inverse on the stable branch gives back separations on both sides of the pull-off's left
  for (double u : {data.separation.front(), 0.5 * (data.separation.front() + curves.pull_off_separation())})
    EXPECT_NEAR(curves.separation_at_pressure(curves.pressure(u)), u, 1e-9 * (data.separation.back() - data.separation.front()));
  // the C API serves the written table as C++ does: the withdrawal's pull-off, the break, the inverse
  asperity_contact_curves* c = nullptr;
  char message[256];
  ASSERT_EQ(asperity_contact_curves_load(path.c_str(), &c, message, sizeof message), ASPERITY_OK) << message;
  EXPECT_EQ(asperity_contact_curves_pull_off_pressure(c), curves.pull_off_pressure());
  EXPECT_EQ(asperity_contact_curves_pull_off_separation(c), curves.pull_off_separation());
  EXPECT_EQ(asperity_contact_curves_stiffness(c, below), curves.stiffness(below));
  EXPECT_EQ(asperity_contact_curves_stiffness(c, data.separation[at]), curves.stiffness(data.separation[at]));
  const double p = curves.pressure(data.separation.front());
  EXPECT_EQ(asperity_contact_curves_separation(c, p), curves.separation_at_pressure(p));
  asperity_contact_curves_close(c);
  const auto refused = [&](ContactCurvesData bad, const char* what) {
    try {
      bad.validate("test");
      ADD_FAILURE() << "accepted: " << what;
    } catch (const Error& error) {
      EXPECT_NE(std::string(error.what()).find(what), std::string::npos) << error.what();
    }
  };
  ContactCurvesData no_tension = data;
  no_tension.tensile_pressure.clear();
  no_tension.tensile_stiffness.clear();
  refused(no_tension, "a separation repeats (a break) in curves without a tensile part");
  ContactCurvesData jump = data;
  jump.pressure[at] *= 1 - 1e-12;
  refused(jump, "at a break (a repeated separation) the pressures");
  ContactCurvesData above_first = data;  // the approach went at least as far as the table starts
  above_first.approach_separation = std::nextafter(data.separation.front(), HUGE_VAL);
  refused(above_first, "the approach separation (a withdrawal branch's) goes with a tensile part");
  ContactCurvesData at_end = data;
  const std::size_t n = at_end.separation.size();
  at_end.separation[n - 1] = at_end.separation[n - 2];
  refused(at_end, "a break (a repeated separation) must be inside the range");
}

// Not run by default: the time of the exact means at separations (a withdrawal's), for profiling
TEST(LawWithdrawal, DISABLED_MeansTime) {
  const double lambda = std::getenv("LAMBDA") ? std::atof(std::getenv("LAMBDA")) : 3;
  const SceneLaw law = withdrawal_scene(ContactLawKind::maugis_dugdale, lambda, delta_c(), -1, 5);
  const double kink = generator::withdrawal_kink(law);
  for (double s : {-1.0, -0.5, 0.0, kink - 0.01, kink, kink + 0.01, 2.0}) {
    const auto start = std::chrono::steady_clock::now();
    const generator::LawMeans m = generator::law_means(law, s);
    std::printf("s = %g: %.3f s (load %g)\n", s, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), m.load);
  }
  // the piece at the detaching edge, in v (x = v^2), each quantity alone: its time and levels
  const double sigma = law.height_scale, omega_min = law.law.lowest_interference;
  const double above = std::nextafter(omega_min, HUGE_VAL);
  boost::math::quadrature::tanh_sinh<double> ts;
  const char* names[] = {"load", "area", "compressive", "tensile", "compressive stiffness", "tensile stiffness"};
  for (int q = 0; q < 6; ++q) {
    const double s = kink + 0.01, edge = s + omega_min / sigma;
    auto f = [&](double v) {
      const double x = v * v, z = edge + x, phi = std::exp(-0.5 * z * z);
      const double w = std::max(omega_min + sigma * x, above);
      const AsperityLoadSplit split = asperity_load_split(law.law, w);
      const double values[] = {asperity_response(law.law, w).load, asperity_response(law.law, w).area,
                               split.compressive, split.tensile, split.compressive_stiffness, split.tensile_stiffness};
      return values[q] * phi * 2 * v;
    };
    double error = 0, l1 = 0;
    std::size_t levels = 0;
    const auto start = std::chrono::steady_clock::now();
    const double value = ts.integrate(f, 0.0, std::sqrt(0.5), 1e-13, &error, &l1, &levels);
    std::printf("%s: %.3f s, %zu levels, value %.17g, error %.2e\n", names[q],
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), levels, value, error / l1);
  }
  for (double omega : {1e-12, 1e-9, 1e-6, 1e-3, 0.1, 0.5}) {
    const double w = law.law.lowest_interference * (1 - omega);
    const auto start = std::chrono::steady_clock::now();
    double sum = 0;
    for (int i = 0; i < 1000; ++i) sum += asperity_response(law.law, w * (1 + i * 1e-15)).load;
    std::printf("omega_min (1 - %g): %.3g us each (%g)\n", omega, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() * 1e3, sum);
  }
}
