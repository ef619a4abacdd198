// The interpolation kernel reproduces every polynomial of degree <= 5 exactly, and its
// slope is the polynomial's derivative.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "asperity/detail/quintic_hermite.hpp"

namespace {

TEST(QuinticHermite, ReproducesQuinticsExactly) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> coefficient(-3, 3);
  for (int trial = 0; trial < 200; ++trial) {
    double c[6];
    for (double& value : c) value = coefficient(rng);
    const double x0 = coefficient(rng), h = 0.01 + std::fabs(coefficient(rng));
    auto p = [&](double x) { return c[0] + x * (c[1] + x * (c[2] + x * (c[3] + x * (c[4] + x * c[5])))); };
    auto dp = [&](double x) { return c[1] + x * (2 * c[2] + x * (3 * c[3] + x * (4 * c[4] + x * 5 * c[5]))); };
    auto d2p = [&](double x) { return 2 * c[2] + x * (6 * c[3] + x * (12 * c[4] + x * 20 * c[5])); };
    const double left[3] = {p(x0), dp(x0) * h, d2p(x0) * h * h};
    const double right[3] = {p(x0 + h), dp(x0 + h) * h, d2p(x0 + h) * h * h};
    for (double t = 0; t <= 1.0; t += 0.0625) {
      // rounding of the polynomial's own terms bounds what any evaluation can match
      const double x = std::fabs(x0) + h;
      const double scale = std::fabs(c[0]) + x * (std::fabs(c[1]) + x * (std::fabs(c[2]) + x * (std::fabs(c[3]) +
                           x * (std::fabs(c[4]) + x * std::fabs(c[5])))));
      EXPECT_NEAR(asperity::detail::quintic_hermite(left, right, t), p(x0 + t * h), 1e-13 * scale);
      EXPECT_NEAR(asperity::detail::quintic_hermite_slope(left, right, t) / h, dp(x0 + t * h), 1e-13 * scale * 30 / h);
    }
  }
}

TEST(QuinticHermite, MatchesEndData) {
  const double left[3] = {1.5, -0.25, 0.125}, right[3] = {-2.0, 0.75, -0.5};
  EXPECT_DOUBLE_EQ(asperity::detail::quintic_hermite(left, right, 0.0), 1.5);
  EXPECT_DOUBLE_EQ(asperity::detail::quintic_hermite(left, right, 1.0), -2.0);
  EXPECT_DOUBLE_EQ(asperity::detail::quintic_hermite_slope(left, right, 0.0), -0.25);
  EXPECT_NEAR(asperity::detail::quintic_hermite_slope(left, right, 1.0), 0.75, 1e-15);
}

}  // namespace
