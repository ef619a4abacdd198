// The batch path (Curve::value_batch / log_value_batch, asperity_eval_batch) for every
// instruction set this CPU has, against the scalar path on the same curve: random
// separations over every segment, the special values and the series beyond the table,
// block edges, aliasing and bad orders. (The scalar path's accuracy against 50-digit
// references is test_accuracy's.)
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "asperity/asperity.h"
#include "asperity/table.hpp"

namespace {
using namespace asperity;

const Table& table() {
  static const Table instance = Table::open(ASPERITY_TEST_TABLE);
  return instance;
}

std::vector<double> separations(const Curve& curve, std::size_t count) {
  std::mt19937_64 rng(11);
  const double lo = curve.table_min_separation(), hi = curve.table_max_separation();
  std::uniform_real_distribution<double> inside(lo, hi), unit(-1, 1);
  std::vector<double> values;
  for (std::size_t i = 0; i < count; ++i) {
    switch (i % 4) {
      case 0: values.push_back(inside(rng)); break;
      case 1: values.push_back(0.2 * unit(rng)); break;               // the graded segments at s = 0
      case 2: values.push_back(std::sinh(9 * unit(rng))); break;      // all-touching to beyond the table
      default: values.push_back(lo + (hi - lo) * std::fabs(unit(rng)) * 1e-3); break;
    }
  }
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  for (double special : {nan, inf, -inf, 0.0, -0.0, lo, hi, std::nextafter(hi, inf), 1e300, -1e300})
    values.insert(values.begin() + static_cast<long>(values.size() / 3), special);
  // the grid's inner end (|s| = 2^-70, each side: the positions pass tests s against each
  // side's signed range) and the smallest magnitudes, a few to a vector
  const double inner = std::ldexp(1.0, -70), denorm = std::numeric_limits<double>::denorm_min();
  for (double magnitude : {inner, std::nextafter(inner, 0.0), std::nextafter(inner, 1.0), denorm,
                           std::numeric_limits<double>::min(), std::ldexp(1.0, -69)})
    for (double sign : {1.0, -1.0}) values.insert(values.begin() + static_cast<long>(values.size() / 2), sign * magnitude);
  return values;
}

// ln X differs between the paths by rounding only: the libraries' exp/log against the inline
// ones, and fused multiply-adds. An error of a few ulp in t = s^a (up to 760) becomes that much
// absolute error in ln X, hence the bound's (1 + |ln X|).
bool agrees(double batch, double scalar) {
  if (std::isnan(scalar)) return std::isnan(batch);
  if (std::isinf(scalar)) return batch == scalar;
  return std::fabs(batch - scalar) <= 2e-14 * (1 + std::fabs(scalar));
}

std::vector<InstructionSet> available_sets() {
  std::vector<InstructionSet> sets;
  for (InstructionSet isa : {InstructionSet::generic, InstructionSet::avx2, InstructionSet::avx512})
    if (instruction_set_available(isa)) sets.push_back(isa);
  return sets;
}

TEST(Batch, EveryInstructionSetAgreesWithTheScalarPath) {
  struct Case {
    Distribution distribution;
    Side side;
    double shape;
  };
  const Case cases[] = {{Distribution::weibull, Side::tail, 0.5},    {Distribution::weibull, Side::tail, 2.0},
                        {Distribution::weibull, Side::tail, 20.0},   {Distribution::weibull, Side::tail, 0.77},
                        {Distribution::weibull, Side::bounded, 0.5}, {Distribution::weibull, Side::bounded, 1.3},
                        {Distribution::weibull, Side::bounded, 20.0}, {Distribution::gaussian, Side::tail, 0.0}};
  for (const Case& c : cases) {
    const Curve curve = table().curve(c.distribution, c.side, c.shape);
    const std::vector<double> inputs = separations(curve, 3001);  // not a multiple of the block
    for (InstructionSet isa : available_sets())
      for (int order = 0; order < order_count; ++order) {
        std::vector<double> logs(inputs.size()), values(inputs.size());
        curve.log_value_batch(order, inputs.data(), logs.data(), inputs.size(), isa);
        curve.value_batch(order, inputs.data(), values.data(), inputs.size(), isa);
        long failures = 0;
        for (std::size_t i = 0; i < inputs.size(); ++i) {
          const double scalar_log = curve.log_value(order, inputs[i]);
          const double scalar_value = curve.value(order, inputs[i]);
          const bool ok = agrees(logs[i], scalar_log) &&
                          (std::isnan(scalar_value)   ? std::isnan(values[i])
                           : !std::isfinite(scalar_log) || std::isinf(scalar_value) ? values[i] == scalar_value
                                                      : std::fabs(values[i] - scalar_value) <=
                                                          2e-14 * (1 + std::fabs(scalar_log)) * scalar_value + 1e-320);
          if (!ok && ++failures < 5)
            ADD_FAILURE() << to_string(isa) << " " << to_string(c.distribution) << " " << to_string(c.side) << " a="
                          << c.shape << " order " << order << " s=" << inputs[i] << ": batch " << logs[i] << " / "
                          << values[i] << ", scalar " << scalar_log << " / " << scalar_value;
        }
        EXPECT_EQ(failures, 0);
      }
  }
}

// A grid that covers nothing (CurveOptions' separations beside the table): no directory, no
// record; the batch path answers every query from the table's layout, as the scalar path does.
// And every block length from 1 to 19 (partial vectors), with the values at the edges of the
// grid's sign test: -0.0, NaN of either sign, the table's ends.
TEST(Batch, EmptyGridAndShortBlocksAgreeWithTheScalarPath) {
  CurveOptions beside;
  beside.grid_min_separation = 1e6;
  beside.grid_max_separation = 2e6;
  const Curve empty = table().curve(Distribution::weibull, Side::tail, 2.0, Curve::all_orders, beside);
  EXPECT_EQ(empty.grid_intervals(), 0u);
  const Curve full = table().curve(Distribution::weibull, Side::bounded, 1.3);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (const Curve* curve : {&empty, &full}) {
    const double lo = curve->table_min_separation(), hi = curve->table_max_separation();
    const double edges[] = {-0.0, 0.0, nan, -nan, lo, hi, std::nextafter(lo, -1e300), std::nextafter(hi, 1e300),
                            0.5, -0.5, 1e-300, -1e-300, 3.0, 1e6, 1.5e6};
    std::vector<double> inputs;
    for (int i = 0; i < 19; ++i) inputs.push_back(edges[i % 15] * (i < 15 ? 1.0 : 0.75));
    for (InstructionSet isa : available_sets())
      for (std::size_t length = 1; length <= inputs.size(); ++length) {
        std::vector<double> values(length), logs(length);
        curve->value_batch(3, inputs.data(), values.data(), length, isa);
        curve->log_value_batch(3, inputs.data(), logs.data(), length, isa);
        for (std::size_t i = 0; i < length; ++i) {
          EXPECT_TRUE(agrees(logs[i], curve->log_value(3, inputs[i])))
              << to_string(isa) << " length " << length << " s=" << inputs[i] << ": " << logs[i];
          const double scalar = curve->value(3, inputs[i]);
          EXPECT_TRUE(std::isnan(scalar) ? std::isnan(values[i])
                                         : std::fabs(values[i] - scalar) <= 1e-13 * scalar + 1e-320)
              << to_string(isa) << " length " << length << " s=" << inputs[i] << ": " << values[i] << " vs " << scalar;
        }
      }
  }
}

TEST(Batch, OutputMayAliasInputAndEmptyOrBadOrderAreHandled) {
  const Curve curve = table().curve(Distribution::weibull, Side::tail, 3.0);
  std::vector<double> inputs = separations(curve, 700);
  std::vector<double> expected(inputs.size());
  curve.value_batch(3, inputs.data(), expected.data(), inputs.size());
  std::vector<double> in_place = inputs;
  curve.value_batch(3, in_place.data(), in_place.data(), in_place.size());
  for (std::size_t i = 0; i < inputs.size(); ++i)
    EXPECT_TRUE(in_place[i] == expected[i] || (std::isnan(in_place[i]) && std::isnan(expected[i]))) << inputs[i];
  curve.value_batch(3, nullptr, nullptr, 0);  // nothing to do, nothing touched
  std::vector<double> out(inputs.size(), 1.0);
  curve.value_batch(6, inputs.data(), out.data(), out.size());
  curve.log_value_batch(-1, inputs.data(), out.data(), out.size());
  for (double value : out) EXPECT_TRUE(std::isnan(value));
  Curve empty;
  empty.value_batch(1, inputs.data(), out.data(), out.size());
  for (double value : out) EXPECT_TRUE(std::isnan(value));
}

TEST(Batch, CApiBatchMatchesTheCurveAndReportsStatus) {
  asperity_table* handle = asperity_table_open(ASPERITY_TEST_TABLE, nullptr, 0);
  ASSERT_NE(handle, nullptr);
  asperity_curve* c_curve = asperity_curve_open(handle, "weibull", "bounded", 1.3, nullptr, 0);
  ASSERT_NE(c_curve, nullptr);
  const Curve curve = table().curve(Distribution::weibull, Side::bounded, 1.3);
  std::vector<double> inputs = separations(curve, 1000);
  std::vector<double> out(inputs.size()), logs(inputs.size()), expected(inputs.size());
  EXPECT_EQ(asperity_eval_batch(c_curve, 3, inputs.data(), out.data(), inputs.size()), ASPERITY_BAD_SEPARATION);
  EXPECT_EQ(asperity_eval_log_batch(c_curve, 3, inputs.data(), logs.data(), inputs.size()), ASPERITY_BAD_SEPARATION);
  curve.value_batch(3, inputs.data(), expected.data(), inputs.size());
  for (std::size_t i = 0; i < inputs.size(); ++i)
    EXPECT_TRUE(out[i] == expected[i] || (std::isnan(out[i]) && std::isnan(expected[i])));
  std::vector<double> finite(inputs.begin(), inputs.begin() + 100);
  for (double& value : finite) value = std::isfinite(value) ? value : 0.5;
  EXPECT_EQ(asperity_eval_batch(c_curve, 2, finite.data(), out.data(), finite.size()), ASPERITY_OK);
  EXPECT_EQ(asperity_eval_batch(c_curve, 9, finite.data(), out.data(), finite.size()), ASPERITY_BAD_ORDER);
  EXPECT_EQ(asperity_eval_batch(nullptr, 2, finite.data(), out.data(), finite.size()), ASPERITY_BAD_HANDLE);
  EXPECT_EQ(asperity_eval_batch(c_curve, 2, nullptr, out.data(), finite.size()), ASPERITY_BAD_HANDLE);
  EXPECT_EQ(asperity_eval_batch(c_curve, 2, nullptr, nullptr, 0), ASPERITY_OK);
  asperity_curve_close(c_curve);
  asperity_table_close(handle);
}

TEST(Batch, InstructionSetsAreReported) {
  EXPECT_TRUE(instruction_set_available(InstructionSet::generic));
  EXPECT_TRUE(instruction_set_available(InstructionSet::automatic));
  const InstructionSet best = best_instruction_set();
  EXPECT_TRUE(instruction_set_available(best));
  EXPECT_NE(best, InstructionSet::automatic);
  RecordProperty("best_instruction_set", to_string(best));
  std::printf("batch path on this CPU: %s\n", to_string(best));
}

}  // namespace
