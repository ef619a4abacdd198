// The segment kinds of the table format, each defined once: its number and name in the schema,
// the map from separation s to the segment variable u, the inverse u -> s (with derivatives),
// and the offset subtracted from ln X so that what is stored, H = ln X - offset(n, u), is
// smooth. The generator (tablegen) integrates in u and the runtime interpolates in u with
// these same functions; ASPERITY_SEGMENT_KINDS generates the dispatch (visit_segment_kind) and
// the schema text, and is checked against the public enum SegmentKind (layout.hpp), so a kind
// is added here and there. Not installed: the format's internals are the library's.
//
// t is the far-tail exponent: s^a for the Weibull, s^2/2 for the Gaussian.
#pragma once
#include <cmath>
#include <limits>

#include "asperity/integrals.hpp"
#include "asperity/layout.hpp"

namespace asperity {

// X(number, name, Type, schema text). Numbers are the file format: never reuse one.
#define ASPERITY_SEGMENT_KINDS(X)                                                                                   \
  X(0, reciprocal, Reciprocal, "s <= s1 (the next segment's start), u = sqrt(s1/s), offset n ln(-s)")                \
  X(1, linear, Linear, "p0 <= s <= p1, u = s, offset 0")                                                              \
  X(2, graded, Graded,                                                                                               \
    "s = p0 + (p1 - p0) u^q (q = 6, or ceil(2/a) for a < 1/3), offset -s^a on the Weibull tail if p0 = 0 < p1, "     \
    "else 0")                                                                                                        \
  X(3, log_exponent, LogExponent, "s >= p0 and t <= p1, u = ln t, offset -t")                                         \
  X(4, log_tau, LogTau, "tau = (-s)^a in [p0, p1], u = ln tau, offset (n + a) ln(-s)")                                \
  X(5, log_distance, LogDistance, "p0 <= s <= p1 < 0, u = ln(-s), offset 0")                                          \
  X(6, bounded_far, BoundedFar, "-s = d0 exp(L u^2), d0 = p0^(1/a), L = ln((d0 + p1)/d0), offset 0")                  \
  X(7, gaussian_linear, GaussianLinear, "p0 <= s <= p1, u = s, offset -s^2/2 (Gaussian only)")                        \
  X(8, graded_bare, GradedBare,                                                                                      \
    "s = p0 + (p1 - p0) u^6, offset -s^a for n = 0 on the Weibull tail where s > 0 (J_0 = exp(-s^a)), else 0")

// Each kind of the list is the public enum's, with the same number (an enumerator the list
// lacks: -Wswitch warns in visit_segment_kind and to_string).
#define ASPERITY_KIND_MATCHES(number, name, Type, text)                       \
  static_assert(static_cast<int>(SegmentKind::name) == number,                \
                "ASPERITY_SEGMENT_KINDS and SegmentKind (layout.hpp) differ: " #name);
ASPERITY_SEGMENT_KINDS(ASPERITY_KIND_MATCHES)
#undef ASPERITY_KIND_MATCHES

namespace detail {

// The kinds' lines of the schema text, one string literal: "<number> <name>  <text>\n" each.
#define ASPERITY_KIND_TEXT(number, name, Type, text) #number " " #name "  " text "\n"
#define ASPERITY_SEGMENT_KIND_TEXT ASPERITY_SEGMENT_KINDS(ASPERITY_KIND_TEXT)
inline constexpr const char* segment_kind_schema_text = ASPERITY_SEGMENT_KIND_TEXT;

// The kinds are numbered 0 .. segment_kind_count - 1.
#define ASPERITY_KIND_ONE(number, name, Type, text) +1
inline constexpr int segment_kind_count = 0 ASPERITY_SEGMENT_KINDS(ASPERITY_KIND_ONE);
#undef ASPERITY_KIND_ONE

// True for a number that names a kind (a file may hold any int).
constexpr bool is_segment_kind(int number) {
#define ASPERITY_KIND_TEST(id, name, Type, text) if (number == id) return true;
  ASPERITY_SEGMENT_KINDS(ASPERITY_KIND_TEST)
#undef ASPERITY_KIND_TEST
  return false;
}

constexpr bool segment_kinds_are_numbered_densely() {
  for (int number = 0; number < segment_kind_count; ++number)
    if (!is_segment_kind(number)) return false;
  return true;
}
static_assert(segment_kinds_are_numbered_densely(), "segment kinds must be numbered 0 .. count - 1");

// A segment of one curve (distribution, side, shape) with everything its map needs.
struct SegmentGeometry {
  SegmentKind kind = SegmentKind::linear;
  Distribution distribution = Distribution::weibull;
  Side side = Side::tail;
  double shape = 2;   // Weibull a (2 for the Gaussian, whose exponent is s^2/2)
  double p0 = 0, p1 = 0;
  double u_lo = 0, u_hi = 1;  // the u range the knots span
  double s_lo = 0, s_hi = 0;  // the separations the segment covers (s_lo may be -inf)
  double span = 0;      // bounded_far: L = ln(s_lo / s_hi)
  double power = 6;     // graded: the grading power
  bool exponent_offset = false;  // graded: offset -s^a (tail side, p0 = 0 < p1)
};

namespace segment_kinds {

// Each kind: set_range (u and s ranges from p0, p1; the reciprocal segment is anchored by
// the caller), u_of_s, s_of_u (with ds/du and d2s/du2), offset (with d/du and d2/du2).
struct Reciprocal {  // s = s1 / u^2
  static void set_range(SegmentGeometry& g) {
    g.u_lo = 0; g.u_hi = 1; g.s_lo = -std::numeric_limits<double>::infinity();
  }
  static double u_of_s(const SegmentGeometry& g, double s) { return std::sqrt(g.p0 / s); }
  static void s_of_u(const SegmentGeometry& g, double u, double& s, double& d1, double& d2) {
    s = g.p0 / (u * u); d1 = -2 * g.p0 / (u * u * u); d2 = 6 * g.p0 / (u * u * u * u);
  }
  static void offset(const SegmentGeometry& g, double n, double u, double& v, double& d1, double& d2) {
    v = n * (std::log(-g.p0) - 2 * std::log(u)); d1 = -2 * n / u; d2 = 2 * n / (u * u);
  }
};

struct Linear {
  static void set_range(SegmentGeometry& g) { g.u_lo = g.s_lo = g.p0; g.u_hi = g.s_hi = g.p1; }
  static double u_of_s(const SegmentGeometry&, double s) { return s; }
  static void s_of_u(const SegmentGeometry&, double u, double& s, double& d1, double& d2) { s = u; d1 = 1; d2 = 0; }
  static void offset(const SegmentGeometry&, double, double, double& v, double& d1, double& d2) { v = d1 = d2 = 0; }
};

struct GaussianLinear {
  static void set_range(SegmentGeometry& g) { g.u_lo = g.s_lo = g.p0; g.u_hi = g.s_hi = g.p1; }
  static double u_of_s(const SegmentGeometry&, double s) { return s; }
  static void s_of_u(const SegmentGeometry&, double u, double& s, double& d1, double& d2) { s = u; d1 = 1; d2 = 0; }
  static void offset(const SegmentGeometry&, double, double u, double& v, double& d1, double& d2) {
    v = -0.5 * u * u; d1 = -u; d2 = -1;
  }
};

// s = p0 + (p1 - p0) u^q: knots packed toward p0 (s = 0, where the Weibull integrals have the
// power terms s^(n + a) of a density that is singular or flat at the origin).
struct GradedPower {
  static void set_range(SegmentGeometry& g) {
    g.u_lo = 0; g.u_hi = 1; g.s_lo = std::fmin(g.p0, g.p1); g.s_hi = std::fmax(g.p0, g.p1);
  }
  static double u_of_s(const SegmentGeometry& g, double s) {
    const double ratio = (s - g.p0) / (g.p1 - g.p0);
    return g.power == 6 ? std::cbrt(std::sqrt(ratio)) : std::pow(ratio, 1 / g.power);
  }
  static void s_of_u(const SegmentGeometry& g, double u, double& s, double& d1, double& d2) {
    const double range = g.p1 - g.p0;
    if (g.power == 6) {
      const double u2 = u * u, u4 = u2 * u2;
      s = g.p0 + range * u4 * u2; d1 = 6 * range * u4 * u; d2 = 30 * range * u4;
    } else {
      s = g.p0 + range * std::pow(u, g.power);
      d1 = g.power * range * std::pow(u, g.power - 1);
      d2 = g.power * (g.power - 1) * range * std::pow(u, g.power - 2);
    }
  }
  // -s^a = -(p1 u^q)^a (p0 = 0) and its u-derivatives
  static void exponent_offset(const SegmentGeometry& g, double u, double& v, double& d1, double& d2) {
    const double exponent = g.power * g.shape, scale = std::pow(g.p1, g.shape);
    v = -scale * std::pow(u, exponent);
    d1 = -scale * exponent * std::pow(u, exponent - 1);
    d2 = exponent == 2 ? -scale * 2 : -scale * exponent * (exponent - 1) * std::pow(u, exponent - 2);
  }
};

struct Graded : GradedPower {  // version 1 tables: the offset -s^a for every order
  static void set_range(SegmentGeometry& g) {
    GradedPower::set_range(g);
    g.exponent_offset = g.distribution == Distribution::weibull && g.side == Side::tail && g.p1 > 0 && g.p0 == 0;
    if (g.distribution == Distribution::weibull) g.power = std::fmax(6.0, std::ceil(2 / g.shape - 1e-9));
  }
  static void offset(const SegmentGeometry& g, double, double u, double& v, double& d1, double& d2) {
    if (g.exponent_offset) exponent_offset(g, u, v, d1, d2);
    else v = d1 = d2 = 0;
  }
};

// The offset -s^a only for n = 0 (where it is exact: J_0 = exp(-s^a)). For n >= 1/2 an s^a in
// the offset would put a term of exponent 6a into H (u^6a, not smooth at u = 0 unless 6a is an
// integer), while ln J_n itself has only the terms s^k and s^(n + a(j+1)), n + a >= 0.8.
struct GradedBare : GradedPower {
  static void set_range(SegmentGeometry& g) {
    GradedPower::set_range(g);
    g.power = 6;
    g.exponent_offset = g.distribution == Distribution::weibull && g.side == Side::tail && g.p1 > 0 && g.p0 == 0;
  }
  static void offset(const SegmentGeometry& g, double n, double u, double& v, double& d1, double& d2) {
    if (g.exponent_offset && n == 0) exponent_offset(g, u, v, d1, d2);
    else v = d1 = d2 = 0;
  }
};

struct LogExponent {  // u = ln t, t = s^a (Gaussian s^2/2)
  static void set_range(SegmentGeometry& g) {
    const bool gaussian = g.distribution == Distribution::gaussian;
    g.u_lo = std::log(gaussian ? 0.5 * g.p0 * g.p0 : std::pow(g.p0, g.shape));
    g.u_hi = std::log(g.p1);
    g.s_lo = g.p0;
    g.s_hi = gaussian ? std::sqrt(2 * g.p1) : std::pow(g.p1, 1 / g.shape);
  }
  // t by one pow: a ln s would amplify the rounding of the log by a ln s
  static double u_of_s(const SegmentGeometry& g, double s) {
    return std::log(g.distribution == Distribution::gaussian ? 0.5 * s * s : std::pow(s, g.shape));
  }
  static void s_of_u(const SegmentGeometry& g, double u, double& s, double& d1, double& d2) {
    if (g.distribution == Distribution::gaussian) {
      s = std::sqrt(2 * std::exp(u)); d1 = s / 2; d2 = s / 4;
    } else {
      s = std::exp(u / g.shape); d1 = s / g.shape; d2 = s / (g.shape * g.shape);
    }
  }
  static void offset(const SegmentGeometry&, double, double u, double& v, double& d1, double& d2) {
    v = d1 = d2 = -std::exp(u);
  }
};

struct LogTau {  // u = ln tau = a ln(-s)
  static void set_range(SegmentGeometry& g) {
    g.u_lo = std::log(g.p0); g.u_hi = std::log(g.p1);
    g.s_lo = -std::pow(g.p1, 1 / g.shape); g.s_hi = -std::pow(g.p0, 1 / g.shape);
  }
  static double u_of_s(const SegmentGeometry& g, double s) { return g.shape * std::log(-s); }
  static void s_of_u(const SegmentGeometry& g, double u, double& s, double& d1, double& d2) {
    const double distance = std::exp(u / g.shape);
    s = -distance; d1 = -distance / g.shape; d2 = -distance / (g.shape * g.shape);
  }
  static void offset(const SegmentGeometry& g, double n, double u, double& v, double& d1, double& d2) {
    d1 = (n + g.shape) / g.shape; v = d1 * u; d2 = 0;
  }
};

struct LogDistance {  // u = ln(-s)
  static void set_range(SegmentGeometry& g) {
    g.u_lo = std::log(-g.p1); g.u_hi = std::log(-g.p0); g.s_lo = g.p0; g.s_hi = g.p1;
  }
  static double u_of_s(const SegmentGeometry&, double s) { return std::log(-s); }
  static void s_of_u(const SegmentGeometry&, double u, double& s, double& d1, double& d2) {
    const double distance = std::exp(u);
    s = -distance; d1 = -distance; d2 = -distance;
  }
  static void offset(const SegmentGeometry&, double, double, double& v, double& d1, double& d2) { v = d1 = d2 = 0; }
};

// -s = d0 exp(L u^2): the bounded side past the bulk, knots packed toward d0.
struct BoundedFar {
  static void set_range(SegmentGeometry& g) {
    const double start = std::pow(g.p0, 1 / g.shape);
    g.u_lo = 0; g.u_hi = 1; g.s_lo = -(start + g.p1); g.s_hi = -start;
    g.span = std::log(g.s_lo / g.s_hi);
  }
  static double u_of_s(const SegmentGeometry& g, double s) {
    const double ratio = std::log(s / g.s_hi) / g.span;
    return std::sqrt(ratio > 0 ? ratio : 0.0);
  }
  static void s_of_u(const SegmentGeometry& g, double u, double& s, double& d1, double& d2) {
    const double distance = -g.s_hi * std::exp(g.span * u * u);
    s = -distance; d1 = -distance * 2 * g.span * u; d2 = -distance * (2 * g.span + 4 * g.span * g.span * u * u);
  }
  static void offset(const SegmentGeometry&, double, double, double& v, double& d1, double& d2) { v = d1 = d2 = 0; }
};

}  // namespace segment_kinds

// visit(segment_kinds::Type{}) for a kind; a number that names no kind gets Linear, after
// the loaders have refused it (is_segment_kind).
template <class Visit>
decltype(auto) visit_segment_kind(SegmentKind kind, Visit&& visit) {
  switch (kind) {
#define ASPERITY_KIND_CASE(number, name, Type, text) \
  case SegmentKind::name: return visit(segment_kinds::Type{});
    ASPERITY_SEGMENT_KINDS(ASPERITY_KIND_CASE)
#undef ASPERITY_KIND_CASE
  }
  return visit(segment_kinds::Linear{});
}

}  // namespace detail
}  // namespace asperity
