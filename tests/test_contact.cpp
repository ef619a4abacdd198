// Physical quantities (docs/model.md section 3) and the separation conventions (section 6).
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

#include "asperity/contact.hpp"
#include "asperity/table.hpp"

namespace {
using namespace asperity;

const Table& table() {
  static const Table instance = Table::open(ASPERITY_TEST_TABLE);
  return instance;
}

TEST(Contact, QuantitiesFollowTheModelFormulas) {
  const Curve curve = table().curve(Distribution::weibull, Side::tail, 2.0);
  const SurfaceScales surface{1000, 2e-4, 3e-6, 1e11};
  const double s = 1.3;
  ContactState state;
  ASSERT_TRUE(contact_at(curve, surface, s, state));
  EXPECT_DOUBLE_EQ(state.count, 1000 * curve.value(0, s));
  EXPECT_NEAR(state.area / (M_PI * 1000 * 2e-4 * 3e-6 * curve.value(2, s)), 1, 1e-15);
  EXPECT_NEAR(state.load / (4.0 / 3.0 * 1000 * 1e11 * std::sqrt(2e-4) * std::pow(3e-6, 1.5) * curve.value(3, s)), 1, 1e-14);
  EXPECT_NEAR(state.stiffness / (2 * 1000 * 1e11 * std::sqrt(2e-4 * 3e-6) * curve.value(1, s)), 1, 1e-14);
  // K = -dP/d(separation): check against a central difference of the load in physical units.
  const double h = 1e-4;
  ContactState plus, minus;
  contact_at(curve, surface, s + h, plus);
  contact_at(curve, surface, s - h, minus);
  const double slope = -(plus.load - minus.load) / (2 * h * surface.height_scale);
  EXPECT_NEAR(slope / state.stiffness, 1, 1e-6);
  EXPECT_NEAR(state.stiffness_ratio, 1.5 * curve.value(1, s) / curve.value(3, s), 1e-13);
}

TEST(Contact, ExponentialHeightsHaveUnitStiffnessLoadRatio) {
  const Curve curve = table().curve(Distribution::weibull, Side::tail, 1.0);
  for (double s : {0.0, 1.0, 10.0, 300.0, 2000.0}) {
    ContactState state;
    ASSERT_TRUE(contact_at(curve, SurfaceScales{}, s, state));
    EXPECT_NEAR(state.stiffness_ratio, 1.0, 1e-11) << s;  // finite even where the load underflows
  }
}

TEST(Contact, BoundedSideOutOfContactIsZero) {
  const Curve curve = table().curve(Distribution::weibull, Side::bounded, 3.0);
  ContactState state;
  ASSERT_TRUE(contact_at(curve, SurfaceScales{}, 0.5, state));
  EXPECT_EQ(state.load, 0.0);
  EXPECT_EQ(state.area, 0.0);
  EXPECT_TRUE(std::isnan(state.stiffness_ratio));
}

TEST(Contact, NonPhysicalInputIsRejectedByValue) {
  const Curve curve = table().curve(Distribution::weibull, Side::tail, 2.0);
  ContactState state;
  EXPECT_FALSE(contact_at(curve, SurfaceScales{-1, 1, 1, 1}, 1.0, state));
  EXPECT_TRUE(std::isnan(state.load));
  EXPECT_FALSE(contact_at(curve, SurfaceScales{1, 0, 1, 1}, 1.0, state));
  EXPECT_FALSE(contact_at(curve, SurfaceScales{1, 1, NAN, 1}, 1.0, state));
  EXPECT_FALSE(contact_at(curve, SurfaceScales{1, 1, 1, INFINITY}, 1.0, state));
  EXPECT_FALSE(contact_at(curve, SurfaceScales{}, NAN, state));
  EXPECT_FALSE(contact_at(curve, SurfaceScales{}, -INFINITY, state));
  // the checks read the bits: every edge of "finite and > 0", in each field
  const double largest = std::numeric_limits<double>::max(), tiny = std::numeric_limits<double>::denorm_min();
  const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
  double SurfaceScales::*const fields[] = {&SurfaceScales::summit_count, &SurfaceScales::summit_radius, &SurfaceScales::height_scale,
                                     &SurfaceScales::contact_modulus};
  for (int field = 0; field < 4; ++field) {
    for (double bad : {0.0, -0.0, -tiny, -largest, inf, -inf, nan, -nan}) {
      SurfaceScales surface;
      surface.*fields[field] = bad;
      EXPECT_FALSE(contact_at(curve, surface, 1.0, state)) << "field " << field << " = " << bad;
      EXPECT_TRUE(std::isnan(state.count) && std::isnan(state.stiffness_ratio));
    }
    for (double good : {tiny, std::numeric_limits<double>::min(), 1.0, largest}) {
      SurfaceScales surface;
      surface.*fields[field] = good;
      EXPECT_TRUE(contact_at(curve, surface, 1.0, state)) << "field " << field << " = " << good;
    }
  }
  EXPECT_FALSE(contact_at(curve, SurfaceScales{}, inf, state));
  EXPECT_FALSE(contact_at(curve, SurfaceScales{}, -nan, state));
  EXPECT_TRUE(contact_at(curve, SurfaceScales{}, -largest, state));
  EXPECT_TRUE(contact_at(curve, SurfaceScales{}, largest, state));
  EXPECT_TRUE(contact_at(curve, SurfaceScales{}, -0.0, state));
}

// contact_at's kernel (the products where the exps are, Curve::contact_products) against
// contact_orders' values and the model from the same curve's logs in long double: every kind,
// the whole range and off it, densely where an order's exp leaves the surely-normal range
// (log2 X = -1021) and underflows (-1075), where the kernel's products and ratio change method.
TEST(Contact, KernelAgreesWithTheLogsEverywhere) {
  struct Kind {
    Distribution distribution;
    Side side;
    double shape;
  };
  const Kind kinds[] = {{Distribution::gaussian, Side::tail, 0},     {Distribution::weibull, Side::tail, 0.5},
                        {Distribution::weibull, Side::tail, 2.0},    {Distribution::weibull, Side::tail, 20.0},
                        {Distribution::weibull, Side::bounded, 0.5}, {Distribution::weibull, Side::bounded, 2.0},
                        {Distribution::weibull, Side::bounded, 20.0},
                        // shapes between the grid's nodes (blended curves; 0.5 and 20 are its ends)
                        {Distribution::weibull, Side::tail, 1.73},   {Distribution::weibull, Side::bounded, 0.77},
                        {Distribution::weibull, Side::tail, 13.3},   {Distribution::weibull, Side::bounded, 19.1}};
  const SurfaceScales surfaces[] = {{1e4, 1e-4, 1e-6, 1e11}, {1, 1, 1, 1}, {1e-300, 1e-5, 1e-5, 1e-3}};
  const double denorm = std::numeric_limits<double>::denorm_min();
  long checked = 0;
  for (const Kind& kind : kinds) {
    const Curve curve = table().curve(kind.distribution, kind.side, kind.shape);
    const double lo = curve.table_min_separation(), hi = curve.table_max_separation();
    std::vector<double> separations;
    for (int i = 0; i <= 4000; ++i) separations.push_back(lo - 0.5 + (hi - lo + 1.0) * i / 4000);
    // s -> 0 from both sides, where the grid's binades get small, and across its end at 2^-70
    for (int e = 1; e <= 80; ++e)
      for (double sign : {-1.0, 1.0}) {
        separations.push_back(sign * std::ldexp(1.0, -e));
        separations.push_back(sign * std::nextafter(std::ldexp(1.0, -e), 1.0));
        separations.push_back(sign * 3 * std::ldexp(1.0, -e - 2));
      }
    separations.push_back(0.0);
    separations.push_back(-0.0);
    // where ln X of each order crosses the kernels' edges (bisection on log_value), and around
    // them: the surely-normal range's lower end in base 2 (log2 X = -1021) and in base e (-708),
    // DBL_MIN (log2 X = -1022), the smallest subnormal (-1074) and half of it (-1075)
    const double ln2 = std::log(2.0);
    for (int order = 0; order < 4; ++order)
      for (double level : {-1021 * ln2, -708.0, -1022 * ln2, -1074 * ln2, -1075 * ln2}) {
        double a = lo, b = hi;
        if (!(curve.log_value(order, a) > level && curve.log_value(order, b) < level)) continue;
        for (int step = 0; step < 200 && b - a > 0; ++step) {
          const double middle = 0.5 * (a + b);
          if (middle <= a || middle >= b) break;
          (curve.log_value(order, middle) > level ? a : b) = middle;
        }
        for (int i = -300; i <= 300; ++i) separations.push_back(a + i * 1e-4);
      }
    for (const SurfaceScales& surface : surfaces) {
      const ContactScales scales = contact_scales(surface);
      const double factors[4] = {scales.count, scales.stiffness, scales.area, scales.load};  // order 0, 1/2, 1, 3/2
      for (double s : separations) {
        ContactState state, from_scales;
        ASSERT_TRUE(contact_at(curve, surface, s, state)) << s;
        ASSERT_TRUE(contact_at_scales(curve, scales, s, from_scales)) << s;
        ASSERT_EQ(std::memcmp(&state, &from_scales, sizeof state), 0) << s;  // the same arithmetic
        double logs[4], values[4];
        curve.contact_orders(s, logs, values);
        const double got[4] = {state.count, state.stiffness, state.area, state.load};
        // ln X: ln 2 log2 X, ln 2 in double (3.4e-17 relative) and the product rounded (half an
        // ulp: kernels.hpp's contact_logs_of)
        double log_rounding[4];
        for (int k = 0; k < 4; ++k) {
          const double magnitude = std::isfinite(logs[k]) ? std::fabs(logs[k]) : 0.0;  // X = 0: no rounding
          log_rounding[k] = 0.5 * (std::nextafter(magnitude, INFINITY) - magnitude) + 3.4e-17 * magnitude;
        }
        for (int k = 0; k < 4; ++k) {
          // contact_orders' exps, times the factor: the kernel rounds m f and scales by 2^k,
          // which is f X rounded once wherever X and the product are normal doubles
          const double smallest_normal = std::numeric_limits<double>::min();
          if (values[k] >= smallest_normal && std::fabs(got[k]) >= smallest_normal && std::isfinite(got[k])) {
            ASSERT_EQ(got[k], factors[k] * values[k]) << "order " << k << " s = " << s;
          }
          // and the model from the logs: the exp within 2.3e-16 where normal, 0.75 of the
          // subnormal spacing below; the product's rounding; the log's
          const long double expected = static_cast<long double>(factors[k]) * std::exp(static_cast<long double>(logs[k]));
          const long double bound = (4.5e-16L + log_rounding[k]) * std::fabs(expected) + (factors[k] + 1.0L) * denorm;
          ASSERT_LE(std::fabs(got[k] - expected), bound) << "order " << k << " s = " << s << " ln X = " << logs[k];
        }
        if (logs[3] == -std::numeric_limits<double>::infinity()) {
          EXPECT_TRUE(std::isnan(state.stiffness_ratio)) << s;
        } else if (values[1] >= std::numeric_limits<double>::min() && values[3] >= std::numeric_limits<double>::min()) {
          // both values normal: their ratio, 1.5 (m_1/2 / m_3/2) 2^(k_1/2 - k_3/2): two roundings
          const long double expected = 1.5L * values[1] / values[3];
          ASSERT_LE(std::fabs(state.stiffness_ratio - expected), 2.3e-16L * expected) << "s = " << s;
        } else {
          const long double difference = static_cast<long double>(logs[1]) - logs[3];
          const long double expected = 1.5L * std::exp(difference);
          // (the kernel's ratio is exact to a few roundings from log2 X; the logs are rounded)
          const long double bound =
              (8e-16L + 1.2e-16L * std::fabs(difference) + log_rounding[1] + log_rounding[3]) * expected;
          ASSERT_LE(std::fabs(state.stiffness_ratio - expected), bound) << "s = " << s << " logs " << logs[1] << " " << logs[3];
        }
        ++checked;
      }
    }
  }
  EXPECT_GT(checked, 80000);
}

// Without contact records (CurveOptions::contact_records off) contact_at takes contact_orders
// and the logs: the same quantities within the kernels' bounds
TEST(Contact, WithoutContactRecordsTheSameQuantities) {
  CurveOptions options;
  options.contact_records = false;
  const Curve plain = table().curve(Distribution::weibull, Side::tail, 2.0, Curve::all_orders, options);
  const Curve with_records = table().curve(Distribution::weibull, Side::tail, 2.0);
  const SurfaceScales surface{1e4, 1e-4, 1e-6, 1e11};
  for (int i = 0; i <= 2000; ++i) {
    const double s = -3.5 + 31.5 * i / 2000;
    ContactState a, b;
    ASSERT_TRUE(contact_at(plain, surface, s, a));
    ASSERT_TRUE(contact_at(with_records, surface, s, b));
    // each quantity with the log of its order (0, 1, 3/2, 1/2; the ratio: 1/2 and 3/2)
    double logs[order_count];
    plain.log_values(s, logs);
    const double abs_logs[5] = {std::fabs(logs[0]), std::fabs(logs[2]), std::fabs(logs[3]), std::fabs(logs[1]),
                                std::fabs(logs[1]) + std::fabs(logs[3])};
    const double pairs[][2] = {{a.count, b.count}, {a.area, b.area}, {a.load, b.load}, {a.stiffness, b.stiffness},
                               {a.stiffness_ratio, b.stiffness_ratio}};
    for (int k = 0; k < 5; ++k) {
      const auto& pair = pairs[k];
      if (std::isnan(pair[1])) {
        EXPECT_TRUE(std::isnan(pair[0])) << s;
        continue;
      }
      // the records' logs within 4.3e-16 (1 + |ln X|) of log_value's (measured in test_curve:
      // they are log2 X, a quintic rounded apart), the exps within 2.3e-16 and the products
      // rounded, each; the ratio has two of each; 1e-300 absolute for the quantities that are
      // themselves below DBL_MIN (their spacing is absolute there)
      const double terms = k == 4 ? 2 : 1;
      const double relative = terms * (5e-16 + 4.6e-16) + 5e-16 * abs_logs[k];
      EXPECT_LE(std::fabs(pair[0] - pair[1]), relative * std::fabs(pair[1]) + 1e-300)
          << s << " quantity " << k << " |ln X| " << abs_logs[k];
    }
  }
}

TEST(Contact, ScalesOutsideTheirRangeAreRejectedByValue) {
  const Curve curve = table().curve(Distribution::weibull, Side::tail, 2.0);
  ContactState state;
  const double largest = std::numeric_limits<double>::max(), tiny = std::numeric_limits<double>::denorm_min();
  const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
  double ContactScales::*const fields[] = {&ContactScales::count, &ContactScales::area, &ContactScales::load,
                                           &ContactScales::stiffness};
  for (int field = 0; field < 4; ++field) {
    for (double bad : {0.0, -0.0, -tiny, -1.0, -largest, inf, -inf, nan, -nan})
      for (double s : {-1.0, 1.0, 40.0}) {  // on the grid, and beyond it
        ContactScales scales = contact_scales(SurfaceScales{});
        scales.*fields[field] = bad;
        EXPECT_FALSE(contact_at_scales(curve, scales, s, state)) << "field " << field << " = " << bad;
        EXPECT_TRUE(std::isnan(state.count) && std::isnan(state.load) && std::isnan(state.stiffness_ratio));
      }
    for (double good : {tiny, std::numeric_limits<double>::min(), 1.0, largest}) {
      ContactScales scales = contact_scales(SurfaceScales{});
      scales.*fields[field] = good;
      EXPECT_TRUE(contact_at_scales(curve, scales, 1.0, state)) << "field " << field << " = " << good;
    }
  }
  const ContactScales unit = contact_scales(SurfaceScales{});
  EXPECT_FALSE(contact_at_scales(curve, unit, nan, state));
  EXPECT_FALSE(contact_at_scales(curve, unit, -inf, state));
  EXPECT_TRUE(contact_at_scales(curve, unit, largest, state));
  // a physical surface whose factors overflow is answered (inf), as before the kernel
  EXPECT_TRUE(contact_at(curve, SurfaceScales{largest, 1, 1, largest}, 1.0, state));
  EXPECT_TRUE(std::isinf(state.load));
  // a default Curve holds no order: NaN quantities
  EXPECT_TRUE(contact_at(Curve{}, SurfaceScales{}, 1.0, state));
  EXPECT_TRUE(std::isnan(state.count) && std::isnan(state.stiffness_ratio));
}

TEST(Contact, SeparationConventionsRoundTrip) {
  for (double shape : {0.5, 2.0, 20.0})
    for (Side side : {Side::tail, Side::bounded}) {
      const Curve curve = table().curve(Distribution::weibull, side, shape);
      for (double s : {-2.0, -0.3, 0.0, 1.5})
        EXPECT_NEAR(origin_from_standardized(curve, standardized_from_origin(curve, s)), s, 1e-13);
    }
  const Curve tail = table().curve(Distribution::weibull, Side::tail, 2.0);
  EXPECT_NEAR(standardized_from_origin(tail, weibull_mean(2.0)), 0.0, 1e-15);  // the mean summit
  const Curve bounded = table().curve(Distribution::weibull, Side::bounded, 2.0);
  EXPECT_NEAR(standardized_from_origin(bounded, -weibull_mean(2.0)), 0.0, 1e-15);
  const Curve gaussian = table().curve(Distribution::gaussian, Side::tail, 0);
  EXPECT_EQ(standardized_from_origin(gaussian, 1.25), 1.25);
}

}  // namespace
