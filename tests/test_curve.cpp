// The hot handle: all orders at once agree with one order at a time, bit for bit, in every
// region (segments, beyond the table, out of contact, bad input).
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>

#include "asperity/error.hpp"
#include "asperity/table.hpp"

namespace {
using namespace asperity;

const Table& table() {
  static const Table instance = Table::open(ASPERITY_TEST_TABLE);
  return instance;
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0 || (std::isnan(a) && std::isnan(b)); }

TEST(Curve, AllOrdersAtOnceMatchOneAtATime) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> unit(-1, 1);
  const Curve curves[] = {table().curve(Distribution::weibull, Side::tail, 0.5),
                          table().curve(Distribution::weibull, Side::tail, 7.3),
                          table().curve(Distribution::weibull, Side::bounded, 2.0),
                          table().curve(Distribution::gaussian, Side::tail, 0)};
  for (const Curve& curve : curves)
    for (int i = 0; i < 2000; ++i) {
      double separation = std::sinh(12 * unit(rng));  // every scale from 1e-5 to 1e5, both signs
      if (i == 0) separation = NAN;
      if (i == 1) separation = 0;
      if (i == 2) separation = -INFINITY;
      double all[order_count];
      curve.log_values(separation, all);
      for (int k = 0; k < order_count; ++k)
        EXPECT_TRUE(same_bits(all[k], curve.log_value(k, separation))) << separation << " order " << k;
    }
}

TEST(Curve, ReportsItsRangeAndMemory) {
  const Curve curve = table().curve(Distribution::weibull, Side::tail, 2.0);
  EXPECT_EQ(curve.table_min_separation(), -3.0);
  EXPECT_NEAR(std::pow(curve.table_max_separation(), 2.0), 760.0, 1e-9);
  EXPECT_GT(curve.memory_bytes(), 6u * 1000 * 3 * sizeof(double));
  const Curve bounded = table().curve(Distribution::weibull, Side::bounded, 2.0);
  EXPECT_LT(bounded.table_max_separation(), 0.0);
  EXPECT_EQ(bounded.value(0, 0.0), 0.0);
  EXPECT_EQ(bounded.log_value(0, 1e-300), -INFINITY);
}

TEST(Curve, CopiesShareTheirDataAndOutliveTheTable) {
  Curve copy;
  EXPECT_TRUE(std::isnan(copy.log_value(0, 1.0)));  // a default Curve holds no order
  double expected;
  {
    const Table local = Table::open(ASPERITY_TEST_TABLE);
    const Curve curve = local.curve(Distribution::weibull, Side::tail, 2.0);
    expected = curve.log_value(3, 0.7);
    copy = curve;
    EXPECT_EQ(copy.memory_bytes(), curve.memory_bytes());
  }
  EXPECT_EQ(copy.log_value(3, 0.7), expected);
  EXPECT_GT(copy.grid_intervals(), 0u);
  EXPECT_LE(copy.grid_error(), 2e-13);
}

TEST(Curve, RefusesALayoutItCannotInterpolate) {
  // a segment of one knot has no interval: refused, never read before its data
  const std::vector<SegmentSpec> layout = {{SegmentKind::reciprocal, 3, 0, 0}, {SegmentKind::linear, 1, -3.0, 1.0}};
  const std::vector<double> knots(static_cast<std::size_t>(order_count) * 4 * 3, 0.0);
  EXPECT_THROW(Curve(Distribution::gaussian, Side::tail, 2, layout, knots.data()), Error);
  const std::vector<SegmentSpec> empty;
  EXPECT_THROW(Curve(Distribution::gaussian, Side::tail, 2, empty, knots.data()), Error);
  CurveOptions backwards;
  backwards.grid_min_separation = 1;
  backwards.grid_max_separation = -1;
  const CurveSet* set = table().find(Distribution::gaussian, Side::tail);
  EXPECT_THROW(Curve(Distribution::gaussian, Side::tail, 2, set->layout, set->knots.data(), Curve::all_orders, backwards),
               Error);
}

// A grid over part of the range (a scene's): inside it the grid answers, outside the table's
// own layout; both agree with the full curve to the tables' error.
TEST(Curve, AGridOverPartOfTheRange) {
  const CurveSet* set = table().find(Distribution::weibull, Side::bounded);
  std::size_t index = 0;
  while (set->shapes[index] != 2.0) ++index;
  CurveOptions options;
  options.grid_min_separation = -1.5;
  options.grid_max_separation = -0.5;
  options.grid_tolerance = 1e-9;
  const Curve part(Distribution::weibull, Side::bounded, 2.0, set->layout, &set->knots[index * set->curve_stride()],
                   Curve::all_orders, options);
  const Curve whole = table().curve(Distribution::weibull, Side::bounded, 2.0);
  EXPECT_LT(part.grid_intervals(), whole.grid_intervals() / 4);
  for (double s : {-3.0, -1.4, -1.0, -0.6, -0.3, -0.01}) {
    for (int k = 0; k < order_count; ++k) {
      const double tolerance = (s >= -1.5 && s <= -0.5) ? 2e-9 : 2e-12;
      EXPECT_NEAR(part.log_value(k, s), whole.log_value(k, s), tolerance) << s << " order " << k;
    }
  }
}

}  // namespace
