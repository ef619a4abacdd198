// The hot path's own exp and log (detail/fast_math.hpp) against references in long double
// (64-bit significand, so the reference's own error is 2^-11 of a double ulp), over the whole
// range and at the special values; and the vectorized loop against the scalar call.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "asperity/detail/fast_math.hpp"

namespace {
using asperity::detail::fast_exp;
using asperity::detail::fast_exp_lanes;

// The two forms of exp (one call at a time, and the one written for vectorized loops)
struct ExpForm {
  const char* name;
  double (*exp)(double);
};
const ExpForm exp_forms[] = {{"fast_exp", [](double x) { return fast_exp(x); }},
                             {"fast_exp_lanes", [](double x) { return fast_exp_lanes(x); }}};
using asperity::detail::fast_log;

constexpr double inf = std::numeric_limits<double>::infinity();

// "1.6e-16", not std::to_string's "0.000000"
std::string scientific(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", value);
  return text;
}

double relative_error(double value, long double reference) {
  return static_cast<double>(std::fabs((static_cast<long double>(value) - reference) / reference));
}

TEST(FastMath, ExpWithinBoundOverTheNormalRange) {
  for (const ExpForm& form : exp_forms) {
    std::mt19937_64 rng(1);
    std::uniform_real_distribution<double> pick(-708.3, 709.7);
    double worst = 0;
    for (int i = 0; i < 2000000; ++i) {
      const double x = pick(rng);
      worst = std::fmax(worst, relative_error(form.exp(x), std::exp(static_cast<long double>(x))));
    }
    for (double x : {0.0, -0.0, 1e-300, -1e-300, 1.0, -1.0, 0.5 * std::log(2.0), 709.78, -708.39})
      worst = std::fmax(worst, relative_error(form.exp(x), std::exp(static_cast<long double>(x))));
    RecordProperty(std::string(form.name) + "_max_relative_error", scientific(worst));
    EXPECT_LT(worst, 2.5e-16) << form.name;  // measured 1.6e-16
  }
}

TEST(FastMath, ExpSpecialValuesAndSubnormals) {
  for (const ExpForm& form : exp_forms) {
    SCOPED_TRACE(form.name);
    const auto fast_exp = form.exp;
    EXPECT_EQ(fast_exp(0.0), 1.0);
    EXPECT_EQ(fast_exp(-inf), 0.0);
    EXPECT_EQ(fast_exp(inf), inf);
    EXPECT_EQ(fast_exp(710.0), inf);
    EXPECT_EQ(fast_exp(-746.0), 0.0);
    EXPECT_EQ(fast_exp(-1e308), 0.0);
    EXPECT_TRUE(std::isnan(fast_exp(std::nan(""))));
    EXPECT_EQ(fast_exp(-1100.0), 0.0);
    EXPECT_EQ(fast_exp(1100.0), inf);
    EXPECT_EQ(fast_exp(1e308), inf);
    EXPECT_EQ(fast_exp(709.79), inf);
    EXPECT_EQ(fast_exp(std::log(std::numeric_limits<double>::max())), std::exp(std::log(std::numeric_limits<double>::max())));
    EXPECT_EQ(fast_exp(-745.2), 0.0);
    EXPECT_EQ(fast_exp(-745.1), 4.9406564584124654e-324);  // the smallest subnormal
    // every binade beyond the range, where the reduction's k, and with it m, is garbage: the
    // test on m must still send these to 0 and inf (a few significands a binade, both signs)
    for (double magnitude = 746.0; magnitude < inf; magnitude *= 2)
      for (double significand : {1.0, 1.1, 1.5, 1.9999999999999998}) {
        const double x = magnitude * significand;
        if (x == inf) continue;
        EXPECT_EQ(fast_exp(-x), 0.0) << -x;
        EXPECT_EQ(fast_exp(x), inf) << x;
      }
    EXPECT_TRUE(std::isnan(fast_exp(-std::nan(""))));
    EXPECT_TRUE(std::isnan(fast_exp(std::nan("0x7ffff"))));
    // below the normal range the result is subnormal (built in the bits), within one subnormal
    // spacing (2^-1074) of the reference, and at most one above the smallest normal
    constexpr long double spacing = 4.9406564584124654e-324L;
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> pick(-745.2, -708.3);
    long double worst = 0;
    for (int i = 0; i < 200000; ++i) {
      const double x = pick(rng);
      worst = std::fmax(worst, std::fabs(static_cast<long double>(fast_exp(x)) - std::exp(static_cast<long double>(x))));
  }
  RecordProperty(std::string(form.name) + "_max_subnormal_error_spacings", scientific(static_cast<double>(worst / spacing)));
  EXPECT_LE(worst, spacing);  // measured 0.75
  // the normal range's lowest end: the rounding of the significand carries into the exponent
  double x = -708.3964185322641;  // ln of the smallest normal; 2000 doubles either side
  for (int i = 0; i < 2000; ++i) x = std::nextafter(x, 0.0);
  for (int i = 0; i < 4000; ++i, x = std::nextafter(x, -inf)) {
    const long double reference = std::exp(static_cast<long double>(x));
    EXPECT_LE(std::fabs(static_cast<long double>(fast_exp(x)) - reference), spacing) << x;
  }
  EXPECT_GE(fast_exp(-708.3964185322641), std::numeric_limits<double>::min());
  }
}

// fast_exp2 (the contact kernels' exp in the baseline build: the records hold log2 X) against a
// long double exp2: the same bound as fast_exp where normal, one subnormal spacing below, and
// the special values; every exactly representable power of two exactly.
TEST(FastMath, Exp2WithinBoundEverywhere) {
  using asperity::detail::fast_exp2;
  std::mt19937_64 rng(4);
  std::uniform_real_distribution<double> pick(-1022.0, 1023.99);
  double worst = 0;
  for (int i = 0; i < 2000000; ++i) {
    const double t = pick(rng);
    worst = std::fmax(worst, relative_error(fast_exp2(t), std::exp2(static_cast<long double>(t))));
  }
  for (double t : {0.0, -0.0, 1e-300, -1e-300, 0.5, -0.5, 1.0 / 256, -1.0 / 256, 1023.999, -1021.999})
    worst = std::fmax(worst, relative_error(fast_exp2(t), std::exp2(static_cast<long double>(t))));
  RecordProperty("fast_exp2_max_relative_error", scientific(worst));
  EXPECT_LT(worst, 2.5e-16);
  for (int k = -1074; k <= 1023; ++k) EXPECT_EQ(fast_exp2(k), std::ldexp(1.0, k)) << k;
  constexpr long double spacing = 4.9406564584124654e-324L;
  std::uniform_real_distribution<double> below(-1075.5, -1022.0);
  long double worst_below = 0;
  for (int i = 0; i < 200000; ++i) {
    const double t = below(rng);
    worst_below = std::fmax(worst_below, std::fabs(static_cast<long double>(fast_exp2(t)) - std::exp2(static_cast<long double>(t))));
  }
  RecordProperty("fast_exp2_max_subnormal_error_spacings", scientific(static_cast<double>(worst_below / spacing)));
  EXPECT_LE(worst_below, spacing);
  EXPECT_EQ(fast_exp2(-inf), 0.0);
  EXPECT_EQ(fast_exp2(inf), inf);
  EXPECT_EQ(fast_exp2(1024.0), inf);
  EXPECT_EQ(fast_exp2(-1076.0), 0.0);
  EXPECT_EQ(fast_exp2(-1075.5), 0.0);
  EXPECT_EQ(fast_exp2(-1074.5), 4.9406564584124654e-324);
  EXPECT_TRUE(std::isnan(fast_exp2(std::nan(""))));
  for (double magnitude = 1076.0; magnitude < inf; magnitude *= 2)
    for (double significand : {1.0, 1.1, 1.5, 1.9999999999999998}) {
      const double t = magnitude * significand;
      if (t == inf) continue;
      EXPECT_EQ(fast_exp2(-t), 0.0) << -t;
      EXPECT_EQ(fast_exp2(t), inf) << t;
    }
}

TEST(FastMath, LogWithinBoundOverAllPositiveDoubles) {
  std::mt19937_64 rng(2);
  std::uniform_real_distribution<double> exponent(-1074.0, 1023.9);
  std::uniform_real_distribution<double> near_one(0.5, 2.0);
  double worst = 0;
  for (int i = 0; i < 2000000; ++i) {
    const double x = std::exp2(exponent(rng));
    if (x == 0) continue;
    worst = std::fmax(worst, relative_error(fast_log(x), std::log(static_cast<long double>(x))));
    const double y = near_one(rng);
    if (y != 1.0) worst = std::fmax(worst, relative_error(fast_log(y), std::log(static_cast<long double>(y))));
  }
  RecordProperty("max_relative_error", scientific(worst));
  EXPECT_LT(worst, 2.5e-16);  // measured 1.5e-16
}

TEST(FastMath, LogSpecialValues) {
  EXPECT_EQ(fast_log(1.0), 0.0);
  EXPECT_EQ(fast_log(0.0), -inf);
  EXPECT_EQ(fast_log(-0.0), -inf);
  EXPECT_EQ(fast_log(inf), inf);
  EXPECT_TRUE(std::isnan(fast_log(-1.0)));
  EXPECT_TRUE(std::isnan(fast_log(-inf)));
  EXPECT_TRUE(std::isnan(fast_log(std::nan(""))));
  EXPECT_NEAR(fast_log(4.9406564584124654e-324), -744.44007192138126, 1e-13);
  EXPECT_NEAR(fast_log(std::numeric_limits<double>::max()), 709.78271289338397, 1e-13);
}

// The same function in a loop (which the compiler may vectorize) and one call at a time; and
// exp's two forms, bit for bit (densely where the result leaves the normal range).
TEST(FastMath, LoopAgreesWithSingleCalls) {
  std::vector<double> inputs;
  for (double x = -800; x < 800; x += 0.731) inputs.push_back(x);
  for (double x = -746.5; x < -707; x += 0.0137) inputs.push_back(x);
  for (double x = 709; x < 711; x += 0.0137) inputs.push_back(x);
  // fast_exp's exact multiplication by 2^m (x in [-708, 709]) against the lanes' integer
  // addition: across the normal range, and the doubles on both sides of its two edges
  for (double x = -708; x <= 709; x += 0.0731) inputs.push_back(x);
  for (double edge : {-708.0, 709.0}) {
    double below = edge, above = edge;
    for (int k = 0; k < 2000; ++k) {
      inputs.push_back(below = std::nextafter(below, -inf));
      inputs.push_back(above = std::nextafter(above, inf));
    }
    inputs.push_back(edge);
  }
  for (double x : {1e300, -1e300, 1e15, -1e15, 5e-324, -0.0}) inputs.push_back(x);
  inputs.push_back(std::nan(""));
  inputs.push_back(inf);
  inputs.push_back(-inf);
  std::vector<double> exps(inputs.size()), logs(inputs.size());
  for (std::size_t i = 0; i < inputs.size(); ++i) exps[i] = fast_exp_lanes(inputs[i]);
  for (std::size_t i = 0; i < inputs.size(); ++i) logs[i] = fast_log(std::fabs(inputs[i]));
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    volatile double x = inputs[i];  // a call the compiler cannot fold into the loop above
    const double e = fast_exp(x), l = fast_log(std::fabs(x));
    EXPECT_TRUE(e == exps[i] || (std::isnan(e) && std::isnan(exps[i]))) << inputs[i];
    EXPECT_TRUE(l == logs[i] || (std::isnan(l) && std::isnan(logs[i]))) << inputs[i];
  }
}

}  // namespace
