// The hot handle: all orders at once agree with one order at a time, bit for bit, in every
// region (segments, beyond the table, out of contact, bad input).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
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

// contact_orders: the four orders 0, 1/2, 1, 3/2 as log_value and value give them, on the
// grid, off it (the all-touching segment, the series, |s| < 2^-70), for bad input, and NaN for
// an order a curve does not hold; with the contact records (one 4-lane vector: fused
// multiply-adds where the instruction set has them) and without (the same bits as log_value).
TEST(Curve, ContactOrdersAreLogValueAndValueOfTheFourOrders) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unit(-1, 1);
  CurveOptions without_records;
  without_records.contact_records = false;
  struct Case {
    Curve curve;
    bool same_bits;  // no contact records: the scalar quintic itself
  };
  const Case cases[] = {{table().curve(Distribution::weibull, Side::tail, 2.0), false},
                        {table().curve(Distribution::weibull, Side::bounded, 0.5), false},
                        {table().curve(Distribution::gaussian, Side::tail, 0), false},
                        {table().curve(Distribution::weibull, Side::tail, 20.0), false},
                        {table().curve(Distribution::weibull, Side::tail, 1.3, order_bit(0) | order_bit(3)), true},
                        {table().curve(Distribution::weibull, Side::tail, 2.0, Curve::all_orders, without_records), true}};
  const double special[] = {NAN, 0.0, -1e-300, 1e300, -1e6, INFINITY};
  double worst = 0;
  for (const Case& c : cases)
    for (int i = 0; i < 3000; ++i) {
      const double separation = i < 6 ? special[i] : std::sinh(14 * unit(rng));
      double logs[4], values[4];
      c.curve.contact_orders(separation, logs, values);
      for (int k = 0; k < 4; ++k) {
        const double log_value = c.curve.log_value(k, separation);
        double log_difference = 0;
        if (c.same_bits || !std::isfinite(log_value)) {
          EXPECT_TRUE(same_bits(logs[k], log_value)) << separation << " order " << k;
        } else {
          // the quintic's rounding, with and without fused multiply-adds: a few ulp of its terms;
          // with the records, log2 X's coefficients and ln 2 log2 X rounded too
          log_difference = std::fabs(logs[k] - log_value) / (1 + std::fabs(log_value));
          worst = std::fmax(worst, log_difference);
          EXPECT_LE(log_difference, 1e-15) << separation << " order " << k;
        }
        // the values by an exp within 2.3e-16 (with the records: 2 to log2 X, fast_math.hpp's
        // fast_exp2, 1.1e-16, or on x86 exp_x86.hpp's exp4 in base 2, 1.9e-16; without them
        // fast_exp); value() may itself be built with fused multiply-adds (Curve::value):
        // 1e-15 (1 + |ln X|) each; below DBL_MIN each value is rounded to the subnormal
        // spacing, which is no longer relative: one spacing more for the two roundings
        const double expected = c.curve.value(k, separation);
        if (std::isnan(expected) || std::isinf(expected) || expected == 0)
          EXPECT_TRUE(same_bits(values[k], expected)) << separation << " order " << k;
        else
          EXPECT_LE(std::fabs(values[k] - expected), (4e-16 + 2e-15 * (1 + std::fabs(log_value))) * expected +
                                                         std::numeric_limits<double>::denorm_min())
              << separation << " order " << k << " ln X = " << log_value;
      }
    }
  RecordProperty("contact_records_largest_log_difference", std::to_string(worst));
  std::printf("contact records: largest |difference| / (1 + |ln X|) from log_value %.2g\n", worst);
}

// value() is exp(log_value()), through the scalar kernel built for this CPU where it has one
// (fused multiply-adds: ln X to the rounding of the quintic) and inline otherwise; off the grid
// the same code as log_value's.
TEST(Curve, ValueIsTheExpOfLogValue) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> unit(-1, 1);
  const Curve curves[] = {table().curve(Distribution::weibull, Side::tail, 0.5),
                          table().curve(Distribution::weibull, Side::tail, 20.0),
                          table().curve(Distribution::weibull, Side::bounded, 2.0),
                          table().curve(Distribution::gaussian, Side::tail, 0)};
  const double special[] = {NAN, 0.0, -0.0, 1e-300, -1e-300, 1e300, -1e6, INFINITY, -INFINITY};
  double worst = 0;
  for (const Curve& curve : curves)
    for (int i = 0; i < 20000; ++i) {
      const double separation = i < 9 ? special[i] : std::sinh(14 * unit(rng));
      for (int k = 0; k < order_count; ++k) {
        const double log_value = curve.log_value(k, separation), value = curve.value(k, separation);
        if (!std::isfinite(log_value) || log_value < -708 || log_value > 709) {
          // NaN, no contact, and where X leaves the normal range: compare in the log (a subnormal
          // has fewer significant bits)
          if (std::isnan(log_value)) EXPECT_TRUE(std::isnan(value)) << separation;
          else if (std::isinf(log_value)) EXPECT_EQ(value, std::exp(log_value)) << separation;
          else EXPECT_NEAR(value, std::exp(log_value), 5e-324 + 1e-12 * std::exp(log_value)) << separation;
          continue;
        }
        const double difference = std::fabs(value / std::exp(log_value) - 1) / (1 + std::fabs(log_value));
        worst = std::fmax(worst, difference);
        EXPECT_LE(difference, 2e-15) << separation << " order " << k;
      }
    }
  std::printf("value against exp(log_value): largest |ratio - 1| / (1 + |ln X|) %.2g\n", worst);
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

// A Curve holds its lookup's pointers itself (curve_data.hpp's CurveLookup, into the data it
// shares): a copy must answer from its own after the original is gone (on the grid, off it,
// and through every path), and a moved-from Curve must answer as a default one, never through
// pointers that the Curve it moved to may outlive.
TEST(Curve, CopiesAndMovesKeepTheirLookupWithTheirData) {
  const double on_grid = 0.7, off_grid = 1e-30, separations[] = {on_grid, off_grid, -2.0};
  double expected[3], expected_log[3], expected_orders[4], expected_orders_log[4];
  Curve copy, moved_to;
  {
    Curve original = table().curve(Distribution::weibull, Side::tail, 2.0);
    for (int i = 0; i < 3; ++i) {
      expected[i] = original.value(3, separations[i]);
      expected_log[i] = original.log_value(3, separations[i]);
    }
    original.contact_orders(on_grid, expected_orders_log, expected_orders);
    copy = original;
    Curve other = original;
    moved_to = std::move(other);
    // the moved-from handle holds no order: every query answers NaN (or false) without data
    EXPECT_EQ(other.order_mask(), 0u);
    EXPECT_TRUE(std::isnan(other.value(3, on_grid)));
    EXPECT_TRUE(std::isnan(other.log_value(3, on_grid)));
    double logs[4], values[4], state[5];
    other.contact_orders(on_grid, logs, values);
    for (int k = 0; k < 4; ++k) EXPECT_TRUE(std::isnan(logs[k]) && std::isnan(values[k]));
    EXPECT_FALSE(other.contact_products(on_grid, 1, 1, 1, 1, state));
    double batch[2];
    other.value_batch(3, separations, batch, 2);
    EXPECT_TRUE(std::isnan(batch[0]) && std::isnan(batch[1]));
    Curve assigned = original;
    assigned = std::move(moved_to);  // move assignment, then back
    moved_to = std::move(assigned);
    EXPECT_TRUE(std::isnan(assigned.value(3, on_grid)));
    EXPECT_EQ(moved_to.value(3, on_grid), expected[0]);
  }
  for (const Curve* curve : {&copy, &moved_to}) {
    for (int i = 0; i < 3; ++i) {
      EXPECT_EQ(curve->value(3, separations[i]), expected[i]) << separations[i];
      EXPECT_EQ(curve->log_value(3, separations[i]), expected_log[i]) << separations[i];
    }
    double logs[4], values[4], state[5];
    curve->contact_orders(on_grid, logs, values);
    for (int k = 0; k < 4; ++k) EXPECT_EQ(values[k], expected_orders[k]);
    EXPECT_TRUE(curve->contact_products(on_grid, 1, 1, 1, 1, state));
    EXPECT_EQ(state[2], expected_orders[3]);  // the load's lane: X_3/2
    double batch[3];
    curve->value_batch(3, separations, batch, 3);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(batch[i], expected[i], 1e-13 * expected[i]) << separations[i];
  }
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

// Knots whose pieces do not meet (a crafted table): the lookup grid stops refining where its
// error stalls and says what it reached, or refuses the curve, in bounded work either way.
TEST(Curve, PiecesThatDoNotMeetAreServedHonestlyOrRefused) {
  const CurveSet* set = table().find(Distribution::gaussian, Side::tail);
  std::vector<double> knots(set->curve_stride());
  for (std::size_t i = 0; i < knots.size(); ++i) knots[i] = 0.125 * static_cast<double>(i % 9) - 0.5;
  try {
    Curve(Distribution::gaussian, Side::tail, 2, set->layout, knots.data());
    ADD_FAILURE() << "a curve with jumps of ~1 in ln X met a 1e-13 grid";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("not smooth"), std::string::npos) << error.what();
  }
  CurveOptions coarse;
  coarse.grid_tolerance = 1e-2;
  const Curve served(Distribution::gaussian, Side::tail, 2, set->layout, knots.data(), Curve::all_orders, coarse);
  EXPECT_GT(served.grid_error(), 1e-2);  // it did not meet what was asked, and says so
  EXPECT_LT(served.grid_intervals(), 20000u);
}

// A table's pieces meet to its own error, not to the grid's 1e-13: knots perturbed by 1e-9
// stall the grid near there. What the grid reports as its error bounds what it adds to the
// table's own curve (the table's layout alone: a grid range outside the table), at random
// separations and toward s = 0; and the perturbed curve stays within ~1e-9 of the clean one.
TEST(Curve, AGridThatStallsAtTheTablesErrorReportsIt) {
  const CurveSet* set = table().find(Distribution::weibull, Side::tail);
  std::size_t index = 0;
  while (set->shapes[index] != 2.0) ++index;
  const double* clean = &set->knots[index * set->curve_stride()];
  std::vector<double> noisy(clean, clean + set->curve_stride());
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> noise(-1e-9, 1e-9);
  for (std::size_t i = 0; i < noisy.size(); i += 3) noisy[i] += noise(rng);  // the values only
  const Curve reference(Distribution::weibull, Side::tail, 2.0, set->layout, clean);
  const Curve perturbed(Distribution::weibull, Side::tail, 2.0, set->layout, noisy.data());
  CurveOptions no_grid;
  no_grid.grid_min_separation = 1e299;
  no_grid.grid_max_separation = 1e300;
  const Curve table_layout(Distribution::weibull, Side::tail, 2.0, set->layout, noisy.data(), Curve::all_orders, no_grid);
  EXPECT_EQ(table_layout.grid_intervals(), 0u);
  EXPECT_LE(reference.grid_error(), 1.1e-13);
  EXPECT_GT(perturbed.grid_error(), 1e-13);
  EXPECT_LT(perturbed.grid_error(), 1e-8);
  EXPECT_LT(perturbed.grid_intervals(), 1u << 17);
  std::uniform_real_distribution<double> unit(-1, 1);
  for (int i = 0; i < 20000; ++i) {
    const double s = i < 200 ? std::ldexp(i % 2 ? -1.0 : 1.0, -i / 2) : std::sinh(4 * unit(rng));
    if (!(s >= table_layout.table_min_separation() && s <= table_layout.table_max_separation())) continue;
    for (int k = 0; k < order_count; ++k) {
      const double served = perturbed.log_value(k, s), own = table_layout.log_value(k, s);
      if (own < -230) continue;  // below 1e-100 the grid is allowed 100 times more
      // (next to s = 0 the grid meets the exact X_n(0) instead of the table's own value there)
      if (std::fabs(s) > 1e-6) {
        ASSERT_LE(std::fabs(served - own), perturbed.grid_error() + 4e-16 * std::fabs(own)) << s << " order " << k;
      }
      ASSERT_NEAR(served, reference.log_value(k, s), 1e-8) << s << " order " << k;
    }
  }
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

// Table::curve with the grid's options given: the same curve as made from the knots with them,
// at a grid shape and between grid shapes.
TEST(Curve, TableCurveWithOptions) {
  CurveOptions options;
  options.grid_min_separation = -1.5;
  options.grid_max_separation = -0.5;
  options.grid_tolerance = 1e-9;
  const CurveSet* set = table().find(Distribution::weibull, Side::bounded);
  std::size_t index = 0;
  while (set->shapes[index] != 2.0) ++index;
  const Curve from_knots(Distribution::weibull, Side::bounded, 2.0, set->layout,
                         &set->knots[index * set->curve_stride()], Curve::all_orders, options);
  const Curve from_table = table().curve(Distribution::weibull, Side::bounded, 2.0, Curve::all_orders, options);
  EXPECT_EQ(from_table.grid_intervals(), from_knots.grid_intervals());
  for (double s : {-3.0, -1.0, -0.3})
    for (int k = 0; k < order_count; ++k) EXPECT_TRUE(same_bits(from_table.log_value(k, s), from_knots.log_value(k, s)));

  CurveOptions coarse;
  coarse.grid_tolerance = 1e-7;
  const Curve between = table().curve(Distribution::weibull, Side::tail, 1.73, Curve::all_orders, coarse);
  const Curve fine = table().curve(Distribution::weibull, Side::tail, 1.73);
  EXPECT_LT(between.grid_intervals(), fine.grid_intervals());
  EXPECT_LE(between.grid_error(), 1e-7);
  for (double s = -3; s <= 6; s += 0.0625)
    for (int k = 0; k < order_count; ++k) EXPECT_NEAR(between.log_value(k, s), fine.log_value(k, s), 2e-7) << s;
  CurveOptions empty;
  empty.grid_min_separation = 1;
  empty.grid_max_separation = 0;
  EXPECT_THROW(table().curve(Distribution::gaussian, Side::tail, 2.0, Curve::all_orders, empty), Error);
}

}  // namespace

// Every shape the table serves gives a curve. Tail shapes 15.22-15.36 were refused ("not smooth
// near s = 0.03125"): there ln X_0 = -s^a is subnormal, the lookup grid matched it exactly, and
// its relative check divided 0 by an allowance that had underflowed to 0.
TEST(Curve, EveryServedShapeBuildsWhereLnX0IsSubnormal) {
  for (double shape = 15.2; shape <= 15.4; shape += 0.005) {
    const Curve curve = table().curve(Distribution::weibull, Side::tail, shape);
    EXPECT_EQ(curve.value(0, 0.04), 1.0) << shape;
    EXPECT_TRUE(std::isfinite(curve.log_value(3, 0.04))) << shape;
  }
}

namespace {

// Separations where a curve's pieces meet or end: each segment's ends and middle (from the
// grid curve's table range), s near 0 on both sides, the all-touching segment, the series
std::vector<double> separations_across(const Curve& curve) {
  std::vector<double> points = {-1e4, -300, -20, -3.01, -3, -2.99, -1, -0.1, -1e-3, -1e-9, -1e-21, -1e-300, 0,
                                1e-300, 1e-21, 1e-9, 1e-3, 0.1, 0.5, 1, 1.5, 2, 3, 5, 10, 40};
  const double lo = curve.table_min_separation(), hi = curve.table_max_separation();
  for (double end : {lo, hi})
    for (double factor : {1 - 1e-12, 1.0, 1 + 1e-12, 0.999, 1.001, 2.0}) points.push_back(end * factor);
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> unit(0, 1);
  for (int i = 0; i < 200; ++i) points.push_back(lo + (hi - lo) * unit(rng));
  return points;
}

}  // namespace

// Table::direct_curve answers from the table's nodes without a grid: what curve()'s grid is fitted
// to, so within that grid's error of curve() everywhere, and curve()'s own answers outside the
// grid (the series, s = 0, the bounded side at s >= 0, NaN); a node's own knots at a node.
TEST(Curve, DirectCurveAnswersAsTheGridCurve) {
  struct Case {
    Distribution distribution;
    Side side;
    double shape;
  };
  const Case cases[] = {{Distribution::weibull, Side::tail, 0.7},      {Distribution::weibull, Side::tail, 1.73},
                        {Distribution::weibull, Side::tail, 2.0},      {Distribution::weibull, Side::tail, 15.3},
                        {Distribution::weibull, Side::tail, 0.5},      {Distribution::weibull, Side::tail, 19.9},
                        {Distribution::weibull, Side::bounded, 0.7},   {Distribution::weibull, Side::bounded, 3.0},
                        {Distribution::weibull, Side::bounded, 19.316}, {Distribution::weibull, Side::bounded, 18.7},
                        {Distribution::gaussian, Side::tail, 0}};
  double worst = 0;
  for (const Case& c : cases) {
    const Curve grid = table().curve(c.distribution, c.side, c.shape);
    const Curve direct = table().direct_curve(c.distribution, c.side, c.shape);
    EXPECT_EQ(direct.grid_intervals(), 0u);
    EXPECT_EQ(direct.shape(), grid.shape());
    EXPECT_EQ(direct.table_max_separation(), grid.table_max_separation());
    for (double s : separations_across(grid)) {
      double from_grid[order_count], from_direct[order_count];
      grid.log_values(s, from_grid);
      direct.log_values(s, from_direct);
      for (int k = 0; k < order_count; ++k) {
        const double a = from_grid[k], b = from_direct[k];
        if (std::isnan(a) || std::isinf(a)) {
          EXPECT_TRUE(same_bits(a, b)) << c.shape << " order " << k << " s " << s;
          continue;
        }
        const double difference = std::fabs(a - b) / (1 + std::fabs(a));
        worst = std::max(worst, difference);
        EXPECT_LE(difference, 2e-13) << to_string(c.side) << " shape " << c.shape << " order " << k << " s " << s
                                     << ": grid " << a << " direct " << b;
        EXPECT_TRUE(same_bits(direct.log_value(k, s), b));
        EXPECT_EQ(direct.value(k, s), std::exp(b));
      }
    }
  }
  std::printf("direct against grid curves: worst |ln X difference| / (1 + |ln X|) %.2e\n", worst);
  // the batch and contact paths answer as the scalar one (no grid: every query off it)
  const Curve direct = table().direct_curve(Distribution::weibull, Side::tail, 1.73);
  const double separations[] = {-2.0, 0.0, 0.4, 1.3, 9.0};
  double batch[5], logs[4], values[4];
  direct.log_value_batch(2, separations, batch, 5);
  for (int i = 0; i < 5; ++i) EXPECT_TRUE(same_bits(batch[i], direct.log_value(2, separations[i])));
  direct.contact_orders(1.3, logs, values);
  for (int k = 0; k < 4; ++k) EXPECT_TRUE(same_bits(logs[k], direct.log_value(k, 1.3)));
  double state[5];
  EXPECT_FALSE(direct.contact_products(1.3, 1, 1, 1, 1, state));  // no grid: the caller's slow path
}

TEST(Curve, DirectCurveOutlivesItsTableAndRefusesAsCurveDoes) {
  Curve kept;
  double expected;
  {
    const Table local = Table::open(ASPERITY_TEST_TABLE);
    kept = local.direct_curve(Distribution::weibull, Side::bounded, 2.345);
    expected = kept.log_value(3, -0.7);
  }
  EXPECT_EQ(kept.log_value(3, -0.7), expected);
  EXPECT_TRUE(std::isnan(kept.log_value(3, std::nan(""))));
  EXPECT_EQ(kept.log_value(3, 0.5), -INFINITY);  // the bounded side out of contact
  EXPECT_THROW(table().direct_curve(Distribution::weibull, Side::tail, 0.2), Error);
  EXPECT_THROW(table().direct_curve(Distribution::weibull, Side::tail, std::nan("")), Error);
  EXPECT_THROW(table().direct_curve(Distribution::gaussian, Side::bounded, 2), Error);
  // orders not asked for answer NaN, as curve()'s
  const Curve two = table().direct_curve(Distribution::weibull, Side::tail, 2.5, order_bit(2) | order_bit(3));
  EXPECT_TRUE(std::isnan(two.log_value(0, 0.5)));
  EXPECT_FALSE(std::isnan(two.log_value(3, 0.5)));
}
