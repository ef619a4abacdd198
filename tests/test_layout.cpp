// Segment maps: u(s) inverts s(u), the derivatives are right, the layouts tile the axis.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "asperity/detail/segment_map.hpp"
#include "asperity/error.hpp"
#include "asperity/layout.hpp"

namespace {
using namespace asperity;
using detail::SegmentMap;

void check_maps(Distribution distribution, Side side, double shape) {
  const auto maps = SegmentMap::resolve(default_layout(distribution, side), distribution, side, shape);
  for (std::size_t i = 0; i < maps.size(); ++i) {
    const SegmentMap& map = maps[i];
    for (double fraction : {0.0, 0.1, 0.37, 0.5, 0.81, 1.0}) {
      double u = map.u_lo + fraction * (map.u_hi - map.u_lo);
      if (map.kind == SegmentKind::reciprocal && u == 0) u = 1e-3;
      double s, ds, d2s;
      map.s_of_u(u, s, ds, d2s);
      EXPECT_NEAR(map.u_of_s(s), u, 1e-12 * (1 + std::fabs(u))) << "segment " << i << " shape " << shape;
      // derivatives against central differences
      const double room = std::min({u - map.u_lo, map.u_hi - u, 1.0});
      const double h = 1e-4 * room;  // small against the distance to the ends (reciprocal: 1/u)
      if (room > 1e-6) {
        double sp, sm, unused1, unused2;
        map.s_of_u(u + h, sp, unused1, unused2);
        map.s_of_u(u - h, sm, unused1, unused2);
        EXPECT_NEAR((sp - sm) / (2 * h), ds, 1e-6 * (1 + std::fabs(ds))) << "segment " << i << " u " << u;
        for (int twice_order = 0; twice_order < order_count; ++twice_order) {
          double value, d1, d2;
          map.offset(order_of(twice_order), u, value, d1, d2);
          EXPECT_NEAR(map.offset_value(order_of(twice_order), u), value, 1e-14 * (1 + std::fabs(value)));
          const double plus = map.offset_value(order_of(twice_order), u + h);
          const double minus = map.offset_value(order_of(twice_order), u - h);
          EXPECT_NEAR((plus - minus) / (2 * h), d1, 1e-6 * (1 + std::fabs(d1)));
          EXPECT_NEAR((plus - 2 * value + minus) / (h * h), d2, 1e-3 * (1 + std::fabs(d2)));
        }
      }
    }
    if (i > 0) {
      EXPECT_NEAR(maps[i].s_lo, maps[i - 1].s_hi, 1e-12 * (1 + std::fabs(maps[i].s_lo)));
    }
  }
  EXPECT_TRUE(std::isinf(maps.front().s_lo));
}

TEST(Layout, MapsInvertAndDifferentiate) {
  for (double shape : {0.45, 0.5, 1.0, 1.7, 5.0, 20.0, 27.0}) {
    check_maps(Distribution::weibull, Side::tail, shape);
    check_maps(Distribution::weibull, Side::bounded, shape);
  }
  check_maps(Distribution::gaussian, Side::tail, 2.0);
}

TEST(Layout, TailCoversTheRequestedRange) {
  for (double shape : {0.5, 3.0, 20.0}) {
    const auto maps = SegmentMap::resolve(default_layout(Distribution::weibull, Side::tail), Distribution::weibull,
                                          Side::tail, shape);
    EXPECT_LE(maps[1].s_lo, -3.0);
    // out to where X_5/2 < 1e-300: t = s^a >= 700 suffices for every order
    EXPECT_GE(std::pow(maps.back().s_hi, shape), 700.0);
    const auto bounded = SegmentMap::resolve(default_layout(Distribution::weibull, Side::bounded),
                                             Distribution::weibull, Side::bounded, shape);
    EXPECT_LE(bounded[1].s_lo, -10.0);
  }
}

TEST(Layout, RejectsLayoutsThatDoNotTile) {
  std::vector<SegmentSpec> broken = {{SegmentKind::reciprocal, 5, 0, 0}, {SegmentKind::linear, 5, -3, -1},
                                     {SegmentKind::linear, 5, 0, 1}};
  EXPECT_THROW(SegmentMap::resolve(broken, Distribution::gaussian, Side::tail, 2), Error);
  std::vector<SegmentSpec> dangling = {{SegmentKind::linear, 5, -3, -1}, {SegmentKind::reciprocal, 5, 0, 0}};
  EXPECT_THROW(SegmentMap::resolve(dangling, Distribution::gaussian, Side::tail, 2), Error);
}

}  // namespace

namespace {
TEST(Layout, KnotDensityScalesIntervalsAndRejectsNonsense) {
  const std::vector<asperity::SegmentSpec> base = asperity::default_layout(asperity::Distribution::weibull,
                                                                           asperity::Side::tail);
  const auto half = asperity::scale_knot_density(base, 0.5);
  const auto tiny = asperity::scale_knot_density(base, 1e-3);
  const auto same = asperity::scale_knot_density(base, 1.0);
  for (std::size_t i = 0; i < base.size(); ++i) {
    EXPECT_EQ(half[i].knots - 1, (base[i].knots - 1) / 2);
    EXPECT_EQ(tiny[i].knots, 3);  // at least two intervals
    EXPECT_EQ(same[i].knots, base[i].knots);
    EXPECT_EQ(half[i].kind, base[i].kind);
    EXPECT_EQ(half[i].p0, base[i].p0);
  }
  EXPECT_THROW(asperity::scale_knot_density(base, 0.0), asperity::Error);
  EXPECT_THROW(asperity::scale_knot_density(base, -1.0), asperity::Error);
  EXPECT_THROW(asperity::scale_knot_density(base, std::nan("")), asperity::Error);
  EXPECT_THROW(asperity::scale_knot_density(base, 1e9), asperity::Error);
}
}  // namespace
