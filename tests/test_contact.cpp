// Physical quantities (docs/model.md section 3) and the separation conventions (section 6).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

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
  const Surface surface{1000, 2e-4, 3e-6, 1e11};
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
    ASSERT_TRUE(contact_at(curve, Surface{}, s, state));
    EXPECT_NEAR(state.stiffness_ratio, 1.0, 1e-11) << s;  // finite even where the load underflows
  }
}

TEST(Contact, BoundedSideOutOfContactIsZero) {
  const Curve curve = table().curve(Distribution::weibull, Side::bounded, 3.0);
  ContactState state;
  ASSERT_TRUE(contact_at(curve, Surface{}, 0.5, state));
  EXPECT_EQ(state.load, 0.0);
  EXPECT_EQ(state.area, 0.0);
  EXPECT_TRUE(std::isnan(state.stiffness_ratio));
}

TEST(Contact, NonPhysicalInputIsRejectedByValue) {
  const Curve curve = table().curve(Distribution::weibull, Side::tail, 2.0);
  ContactState state;
  EXPECT_FALSE(contact_at(curve, Surface{-1, 1, 1, 1}, 1.0, state));
  EXPECT_TRUE(std::isnan(state.load));
  EXPECT_FALSE(contact_at(curve, Surface{1, 0, 1, 1}, 1.0, state));
  EXPECT_FALSE(contact_at(curve, Surface{1, 1, NAN, 1}, 1.0, state));
  EXPECT_FALSE(contact_at(curve, Surface{1, 1, 1, INFINITY}, 1.0, state));
  EXPECT_FALSE(contact_at(curve, Surface{}, NAN, state));
  EXPECT_FALSE(contact_at(curve, Surface{}, -INFINITY, state));
  // the checks read the bits: every edge of "finite and > 0", in each field
  const double largest = std::numeric_limits<double>::max(), tiny = std::numeric_limits<double>::denorm_min();
  const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
  double Surface::*const fields[] = {&Surface::summit_count, &Surface::summit_radius, &Surface::height_scale,
                                     &Surface::contact_modulus};
  for (int field = 0; field < 4; ++field) {
    for (double bad : {0.0, -0.0, -tiny, -largest, inf, -inf, nan, -nan}) {
      Surface surface;
      surface.*fields[field] = bad;
      EXPECT_FALSE(contact_at(curve, surface, 1.0, state)) << "field " << field << " = " << bad;
      EXPECT_TRUE(std::isnan(state.count) && std::isnan(state.stiffness_ratio));
    }
    for (double good : {tiny, std::numeric_limits<double>::min(), 1.0, largest}) {
      Surface surface;
      surface.*fields[field] = good;
      EXPECT_TRUE(contact_at(curve, surface, 1.0, state)) << "field " << field << " = " << good;
    }
  }
  EXPECT_FALSE(contact_at(curve, Surface{}, inf, state));
  EXPECT_FALSE(contact_at(curve, Surface{}, -nan, state));
  EXPECT_TRUE(contact_at(curve, Surface{}, -largest, state));
  EXPECT_TRUE(contact_at(curve, Surface{}, largest, state));
  EXPECT_TRUE(contact_at(curve, Surface{}, -0.0, state));
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
