// Each segment kind (segment_kind.hpp), as the generator and the runtime both use it: the map
// s -> u and its inverse u -> s agree, their derivatives are the derivatives, the offset's
// derivatives too, and a curve interpolated on the kind's knots reproduces a known function
// (the generator's side: s_of_u and offset with derivatives; the runtime's: u_of_s and
// offset_value).
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "asperity/detail/compact_curve.hpp"
#include "asperity/detail/segment_map.hpp"
#include "asperity/layout.hpp"

namespace {
using namespace asperity;
using namespace asperity::detail;  // the kinds and their maps are the library's (white box)

struct Case {
  Distribution distribution;
  Side side;
  double shape;
  std::vector<SegmentSpec> layout;
};

std::vector<Case> cases() {
  std::vector<Case> all;
  for (double shape : {0.3, 0.5, 1.7, 2.0, 20.0, 50.0}) {
    all.push_back({Distribution::weibull, Side::tail, shape, default_layout(Distribution::weibull, Side::tail)});
    all.push_back({Distribution::weibull, Side::bounded, shape, default_layout(Distribution::weibull, Side::bounded)});
    // version-1 tables: the graded kind with its offset -s^a on every order; and a linear segment
    all.push_back({Distribution::weibull, Side::tail, shape,
                   {{SegmentKind::reciprocal, 9, 0, 0},
                    {SegmentKind::linear, 9, -3.0, -0.1},
                    {SegmentKind::graded, 17, 0.0, -0.1},
                    {SegmentKind::graded, 17, 0.0, 0.1},
                    {SegmentKind::log_exponent, 33, 0.1, 760.0}}});
  }
  all.push_back({Distribution::gaussian, Side::tail, 2.0, default_layout(Distribution::gaussian, Side::tail)});
  return all;
}

TEST(SegmentKind, EveryKindIsCoveredAndNamedInTheSchema) {
  std::vector<bool> seen(16, false);
  for (const Case& c : cases())
    for (const SegmentSpec& spec : c.layout) seen[static_cast<int>(spec.kind)] = true;
  int kinds = 0;
#define COUNT_KIND(number, name, Type, text)                                                        \
  ++kinds;                                                                                          \
  EXPECT_TRUE(seen[number]) << #name " is not tested";                                             \
  EXPECT_STREQ(to_string(SegmentKind::name), #name);                                               \
  EXPECT_NE(std::strstr(segment_kind_schema_text, #number " " #name "  "), nullptr) << #name;       \
  EXPECT_TRUE(is_segment_kind(number));
  ASPERITY_SEGMENT_KINDS(COUNT_KIND)
#undef COUNT_KIND
  EXPECT_EQ(kinds, 9);
  EXPECT_FALSE(is_segment_kind(-1));
  EXPECT_FALSE(is_segment_kind(9));
}

TEST(SegmentKind, MapAndInverseAgreeWithTheirDerivatives) {
  for (const Case& c : cases()) {
    const std::vector<SegmentMap> maps = SegmentMap::resolve(c.layout, c.distribution, c.side, c.shape);
    for (const SegmentMap& map : maps) {
      const std::string what = std::string(to_string(map.kind)) + " shape " + std::to_string(c.shape) + " " +
                               to_string(c.distribution) + " " + to_string(c.side);
      for (int i = 0; i <= 200; ++i) {
        const double u = map.u_lo + (map.u_hi - map.u_lo) * i / 200;
        if (map.kind == SegmentKind::reciprocal && u == 0) continue;  // s = -inf
        double s, d1, d2;
        map.s_of_u(u, s, d1, d2);
        ASSERT_TRUE(std::isfinite(s)) << what << " u " << u;
        EXPECT_GE(s, map.s_lo - 1e-12 * (1 + std::fabs(map.s_lo))) << what;
        EXPECT_LE(s, map.s_hi + 1e-12 * (1 + std::fabs(map.s_hi))) << what;
        // forward of the inverse: u back, to the map's conditioning (an error of one rounding in
        // s moves u by eps |s| / |ds/du|: large where a map is flat, at u = 0 of the graded and
        // bounded_far segments)
        const double back = map.u_of_s(s);
        const double conditioning = d1 == 0 ? 0.0 : 8 * 2.220446049250313e-16 * std::fabs(s) / std::fabs(d1);
        EXPECT_NEAR(back, u, 1e-12 * (1 + std::fabs(u)) + std::sqrt(conditioning * std::fabs(u)) + conditioning)
            << what << " u " << u;
        double s_again, unused1, unused2;
        map.s_of_u(back, s_again, unused1, unused2);
        EXPECT_NEAR(s_again, s, 1e-13 * (1 + std::fabs(s))) << what << " u " << u;
        // derivatives by central differences, Richardson-extrapolated (error ~ h^4), with a
        // step relative to u (the reciprocal map is singular at u = 0)
        const double h = 1e-3 * (std::fabs(u) + 1e-3 * (map.u_hi - map.u_lo));
        if (u - h > map.u_lo && u + h < map.u_hi) {
          auto derivative = [&](auto f) {
            const double wide = (f(u + h) - f(u - h)) / (2 * h), narrow = (f(u + h / 2) - f(u - h / 2)) / h;
            return (4 * narrow - wide) / 3;
          };
          auto near = [](double got, double want, double scale) {
            return std::fabs(got - want) <= 1e-7 * (std::fabs(want) + scale);
          };
          auto s_at = [&](double x) { return map.separation_of_u(x); };
          auto d1_at = [&](double x) { double a, b, c; map.s_of_u(x, a, b, c); return b; };
          EXPECT_TRUE(near(derivative(s_at), d1, std::fabs(s) * 1e-3)) << what << " ds/du at u " << u;
          EXPECT_TRUE(near(derivative(d1_at), d2, std::fabs(d1) * 1e-3)) << what << " d2s/du2 at u " << u;
          for (int k = 0; k < order_count; ++k) {
            const double n = order_of(k);
            double v, o1, o2;
            map.offset(n, u, v, o1, o2);
            EXPECT_EQ(v, map.offset_value(n, u)) << what;
            auto value_at = [&](double x) { return map.offset_value(n, x); };
            auto o1_at = [&](double x) { double a, b, c; map.offset(n, x, a, b, c); return b; };
            EXPECT_TRUE(near(derivative(value_at), o1, 1e-3 * (std::fabs(v) + 1))) << what << " offset' n " << n << " u " << u;
            EXPECT_TRUE(near(derivative(o1_at), o2, 1e-3 * (std::fabs(o1) + 1))) << what << " offset'' n " << n << " u " << u;
          }
        }
      }
    }
  }
}

// A known smooth ln X(s) written onto each layout's knots through s_of_u and the offset (what
// the generator does), read back through u_of_s and offset_value (what the runtime does): it
// comes back at every knot exactly and between knots to the quintic's accuracy.
TEST(SegmentKind, GeneratorAndRuntimeAgreeOnKnotsAndBetween) {
  // smooth at every scale, so smooth in every kind's variable (also u = ln s, ln t, ...)
  auto truth = [](double s, double n) { return -0.1 * (1 + n) * std::log1p(s * s) + 0.05 * std::atan(s); };
  auto slope = [](double s, double n) { return (-0.2 * (1 + n) * s + 0.05) / (1 + s * s); };
  auto curvature = [](double s, double n) {
    return (-0.2 * (1 + n) * (1 - s * s) - 0.1 * s) / ((1 + s * s) * (1 + s * s));
  };
  for (const Case& c : cases()) {
    std::vector<SegmentSpec> layout = c.layout;
    for (SegmentSpec& spec : layout) spec.knots = 2001;  // dense: the quintic's error is negligible
    const std::vector<SegmentMap> maps = SegmentMap::resolve(layout, c.distribution, c.side, c.shape);
    int total = 0;
    for (const SegmentSpec& spec : layout) total += spec.knots;
    std::vector<double> knots(static_cast<std::size_t>(order_count) * total * 3);
    for (int k = 0; k < order_count; ++k) {
      const double n = order_of(k);
      int index = 0;
      for (std::size_t m = 0; m < maps.size(); ++m)
        for (int j = 0; j < layout[m].knots; ++j, ++index) {
          const double u = maps[m].u_lo + (maps[m].u_hi - maps[m].u_lo) * j / (layout[m].knots - 1);
          double s, d1, d2, v, o1, o2;
          maps[m].s_of_u(u, s, d1, d2);
          maps[m].offset(n, u, v, o1, o2);
          double* out = &knots[(static_cast<std::size_t>(k) * total + index) * 3];
          if (maps[m].kind == SegmentKind::reciprocal && j == 0) {  // s = -inf: any finite data
            out[0] = out[1] = out[2] = 0;
            continue;
          }
          out[0] = truth(s, n) - v;
          out[1] = slope(s, n) * d1 - o1;
          out[2] = curvature(s, n) * d1 * d1 + slope(s, n) * d2 - o2;
        }
    }
    // orders 1/2 .. 5/2 (the Weibull order 0 is answered exactly, not from the knots)
    const detail::CompactCurve curve(c.distribution, c.side, c.shape, layout, knots.data(), 0b111110u);
    for (std::size_t m = 1; m < maps.size(); ++m) {  // the all-touching segment reaches s = -inf
      const std::string what = std::string(to_string(maps[m].kind)) + " shape " + std::to_string(c.shape);
      for (int i = 1; i < 300; ++i) {
        const double u = maps[m].u_lo + (maps[m].u_hi - maps[m].u_lo) * (i + 0.37) / 301;
        const double s = maps[m].separation_of_u(u);
        if (std::fabs(s) < 1e-20) continue;  // there the curve answers its exact value at 0
        if (c.side == Side::bounded && s > curve.table_max()) continue;  // the contact series
        for (int k = 1; k < order_count; ++k)
          EXPECT_NEAR(curve.log_value(k, s), truth(s, order_of(k)), 1e-9 * (1 + std::fabs(truth(s, order_of(k)))))
              << what << " s " << s << " order " << order_of(k);
      }
    }
  }
}

}  // namespace
