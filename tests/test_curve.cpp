// The hot handle: all orders at once agree with one order at a time, bit for bit, in every
// region (segments, beyond the table, out of contact, bad input).
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>

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

}  // namespace
