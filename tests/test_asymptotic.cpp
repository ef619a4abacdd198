// The series used beyond the table, against the 50-digit reference where they take over.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "asperity/asymptotic.hpp"
#include "reference.hpp"

namespace {
using namespace asperity;

double relative(double log_value, const test::Precise& log_reference) {
  return std::fabs(std::expm1(log_value - static_cast<double>(log_reference)));
}

// A relative error of X is an absolute error of ln X, so rounding ln X itself costs
// |ln X| eps: the bound is 1e-14 plus a few of those.
double bound(double log_value) { return 1e-14 + 4 * std::numeric_limits<double>::epsilon() * std::fabs(log_value); }

TEST(Asymptotic, WeibullFarTailFromWhereTheTableEnds) {
  for (double shape : {0.5, 1.0, 2.0, 7.0, 20.0})
    for (double order : {-0.5, 0.0, 0.5, 1.0, 1.5, 2.0, 2.5}) {
      const Series series = weibull_tail_series(shape, order);
      for (double t : {700.0, 760.0, 2000.0}) {
        const double s = std::pow(t, 1 / shape);
        const double value = weibull_tail_log(series, shape, order, s);
        EXPECT_LE(relative(value, test::reference_log(Distribution::weibull, Side::tail, shape, order, s)), bound(value))
            << shape << " " << order << " " << s;
      }
    }
}

TEST(Asymptotic, GaussianFarTail) {
  for (double order : {-0.5, 0.0, 0.5, 1.0, 1.5, 2.0, 2.5}) {
    const Series series = gaussian_tail_series(order);
    for (double s : {37.4, 39.0, 45.0, 100.0})
      EXPECT_LE(relative(gaussian_tail_log(series, order, s),
                         test::reference_log(Distribution::gaussian, Side::tail, 2, order, s)),
                bound(gaussian_tail_log(series, order, s)))
          << order << " " << s;
  }
}

TEST(Asymptotic, BoundedNearFirstContact) {
  for (double shape : {0.5, 1.0, 3.0, 20.0})
    for (double order : {0.0, 0.5, 1.0, 1.5, 2.0, 2.5}) {
      const Series series = bounded_contact_series(shape, order);
      for (double tau : {1e-3, 1e-6, 1e-30}) {
        const double s = -std::pow(tau, 1 / shape);
        if (s == 0) continue;
        const double value = bounded_contact_log(series, shape, order, s);
        EXPECT_LE(relative(value, test::reference_log(Distribution::weibull, Side::bounded, shape, order, s)),
                  bound(value))
            << shape << " " << order << " " << s;
      }
    }
}

TEST(Asymptotic, StiffnessLoadRatioGrowsLikeThreeHalvesPlusShapeOverDistance) {
  // docs/model.md: near first contact K_n ~ C d^(n+a), so (3/2) K_1/2 / K_3/2 -> (3/2 + a)/d.
  for (double shape : {1.0, 2.0, 5.0}) {
    const double d = 1e-6, s = -d;
    const double ratio = 1.5 * std::exp(bounded_contact_log(bounded_contact_series(shape, 0.5), shape, 0.5, s) -
                                        bounded_contact_log(bounded_contact_series(shape, 1.5), shape, 1.5, s));
    EXPECT_NEAR(ratio * d / (1.5 + shape), 1.0, 1e-5);
  }
}

}  // namespace
