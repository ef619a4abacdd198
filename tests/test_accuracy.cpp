// Accuracy of the shipped default table against independent references: 50-digit
// double-exponential quadrature of the defining integrals (reference.hpp) and closed forms.
// Bounds (issue #2): 1e-12 where X >= 1e-100 on grid shapes, 1e-10 down to 1e-300 and beyond
// the table, 1e-9 between grid shapes. The measured maxima are printed for docs/accuracy.md.
#include <gtest/gtest.h>

#include <boost/math/special_functions/erf.hpp>
#include <boost/math/special_functions/gamma.hpp>
#include <cmath>
#include <map>
#include <random>

#include "accuracy_harness.hpp"
#include "asperity/table.hpp"

namespace {
using namespace asperity;
using test::Precise;
using test::Probe;

const Table& table() {
  static const Table instance = Table::open(ASPERITY_TEST_TABLE);
  return instance;
}

// Separations that visit every segment of a tail curve and the asymptotic region beyond it,
// plus the named hard points: s just above and below 0, s < 0, the far tail.
std::vector<double> tail_separations(const Curve& curve, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> unit(0, 1);
  std::vector<double> points = {-1e4, -50, -3.5, -3, -1, -0.1, -1e-3, -1e-9, -1e-15, 0, 1e-15, 1e-9, 1e-3, 0.1};
  for (int i = 0; i < 4; ++i) points.push_back(-3 - 300 * std::pow(unit(rng), 3));   // all touching
  for (int i = 0; i < 4; ++i) points.push_back(-std::exp(std::log(0.1) + unit(rng) * std::log(30.0)));
  for (int i = 0; i < 4; ++i) points.push_back((unit(rng) - 0.5) * 0.2 * std::pow(unit(rng), 4));  // near 0
  const bool gaussian = curve.distribution() == Distribution::gaussian;
  const double shape = curve.shape();
  auto from_exponent = [&](double t) { return gaussian ? std::sqrt(2 * t) : std::pow(t, 1 / shape); };
  for (int i = 0; i < 8; ++i) points.push_back(from_exponent(std::exp(std::log(1e-3) + unit(rng) * std::log(2e5))));
  for (double t : {230.0, 400.0, 600.0, 690.0, 700.0, 759.0}) points.push_back(from_exponent(t));
  // Beyond the table; the problem's own condition number there is about a t (docs/model.md), so
  // the bound 1e-10 holds out to t ~ 1e5 and the error grows like a t eps past it.
  for (double t : {761.0, 800.0, 1500.0, 5000.0, 5e4}) points.push_back(from_exponent(t));
  if (gaussian) points.insert(points.end(), {-10, -9.5, -20, -2, 0.5, 1, 1.5, 5, 10, 20});
  return points;
}

std::vector<double> bounded_separations(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> unit(0, 1);
  std::vector<double> points = {-1e-12, -1e-6, -1e-3, -0.05, -0.5, -1, -2, -5, -9.99, -10, -10.01, -12, -100, -1e4};
  for (int i = 0; i < 16; ++i) points.push_back(-std::exp(std::log(1e-9) + unit(rng) * std::log(2e10)));
  return points;
}

std::vector<Probe> probes_for(const Curve& curve, const std::vector<double>& separations, const std::string& label) {
  std::vector<Probe> probes;
  for (double separation : separations)
    for (int twice_order = 0; twice_order < order_count; ++twice_order)
      probes.push_back({&curve, twice_order, separation, 0, label});
  return probes;
}

struct Worst {
  double error = 0;
  std::string where;
};

void check(std::vector<Probe>& probes, bool grid_shape, std::map<std::string, Worst>& report) {
  test::evaluate(probes);
  for (const Probe& probe : probes) {
    const double tolerance =
        grid_shape ? test::grid_tolerance(*probe.curve, probe.reference, probe.separation) : 1e-9;
    const std::string band = !grid_shape ? "between grid shapes"
                             : probe.separation > probe.curve->table_max_separation() ? "beyond the table"
                             : probe.reference >= std::log(1e-100) ? "X >= 1e-100"
                                                                   : "1e-300 <= X < 1e-100";
    Worst& worst = report[band];
    char where[200];
    std::snprintf(where, sizeof where, "%s shape %.4g order %g s %.6g", probe.label.c_str(), probe.curve->shape(),
                  order_of(probe.twice_order), probe.separation);
    if (probe.error > worst.error) worst = {probe.error, where};
    if (probe.reference < std::log(1e-300) && probe.reference > -std::numeric_limits<double>::infinity())
      continue;  // below the stated range (still checked to be finite and ordered below)
    EXPECT_LE(probe.error, tolerance) << where << " value " << probe.value << " reference " << probe.reference;
  }
}

void print(const std::map<std::string, Worst>& report, const char* title) {
  std::printf("\nMeasured maximum relative error, %s:\n", title);
  for (const auto& [band, worst] : report) std::printf("  %-22s %.2e  (%s)\n", band.c_str(), worst.error, worst.where.c_str());
}

TEST(Accuracy, GridShapesBothSidesAndGaussian) {
  std::mt19937_64 rng(2026);
  std::map<std::string, Worst> report;
  std::vector<Curve> curves;
  const std::vector<double> shapes = {0.5, 1, 2, 3, 5, 20};  // grid nodes of the default table
  curves.reserve(2 * shapes.size() + 1);
  for (double shape : shapes) curves.push_back(table().curve(Distribution::weibull, Side::tail, shape));
  for (double shape : shapes) curves.push_back(table().curve(Distribution::weibull, Side::bounded, shape));
  curves.push_back(table().curve(Distribution::gaussian, Side::tail, 0));
  std::vector<Probe> probes;
  for (const Curve& curve : curves) {
    const auto separations = curve.side() == Side::bounded ? bounded_separations(rng) : tail_separations(curve, rng);
    const std::string label = std::string(to_string(curve.distribution())) + " " + to_string(curve.side());
    const auto more = probes_for(curve, separations, label);
    probes.insert(probes.end(), more.begin(), more.end());
  }
  check(probes, true, report);
  print(report, "grid shapes 0.5, 1, 2, 3, 5, 20 and the Gaussian");
}

TEST(Accuracy, BetweenGridShapes) {
  std::mt19937_64 rng(11);
  std::map<std::string, Worst> report;
  const CurveSet* set = table().find(Distribution::weibull, Side::tail);
  ASSERT_NE(set, nullptr);
  // Midpoints (in the grid variable) of grid intervals across the served range: the worst place.
  std::vector<double> shapes;
  for (std::size_t i = 0; i + 1 < set->shapes.size(); i += 11) {
    if (set->shapes[i] < set->shape_min || set->shapes[i + 1] > set->shape_max) continue;
    shapes.push_back(std::sqrt(set->shapes[i] * set->shapes[i + 1]));
  }
  shapes.push_back(1.73);
  std::vector<Curve> curves;
  curves.reserve(2 * shapes.size());
  for (double shape : shapes) {
    curves.push_back(table().curve(Distribution::weibull, Side::tail, shape));
    curves.push_back(table().curve(Distribution::weibull, Side::bounded, shape));
  }
  std::vector<Probe> probes;
  for (const Curve& curve : curves) {
    auto separations = curve.side() == Side::bounded ? bounded_separations(rng) : tail_separations(curve, rng);
    separations.resize(separations.size() / 2);  // a lighter sweep per shape, more shapes
    const auto more = probes_for(curve, separations, std::string("weibull ") + to_string(curve.side()));
    probes.insert(probes.end(), more.begin(), more.end());
  }
  check(probes, false, report);
  print(report, "shapes between grid nodes");
}

// Closed forms of docs/model.md section 5, evaluated in 50 digits.
TEST(Accuracy, ClosedForms) {
  using boost::multiprecision::exp;
  using boost::multiprecision::log;
  using boost::multiprecision::pow;
  double worst = 0;
  auto expect = [&](double got_log, const Precise& exact, const char* what, double shape, double s) {
    const double error = std::fabs(std::expm1(got_log - static_cast<double>(log(exact))));
    worst = std::max(worst, error);
    EXPECT_LE(error, 1e-12) << what << " shape " << shape << " s " << s;
  };
  for (double shape : {0.5, 1.0, 2.0, 3.0, 5.0, 20.0}) {
    const Curve tail = table().curve(Distribution::weibull, Side::tail, shape);
    const Curve bounded = table().curve(Distribution::weibull, Side::bounded, shape);
    const Precise a = shape;
    // Weibull moments at s = 0: J_n(0) = Gamma(1 + n/a).
    for (int k = 0; k < order_count; ++k)
      expect(tail.log_value(k, 0.0), boost::math::tgamma(1 + Precise(order_of(k)) / a), "moment", shape, 0);
    for (double s : {1e-9, 0.01, 0.3, 0.9, 1.1, 1.7, 2.5}) {
      const Precise t = pow(Precise(s), a);
      if (t > 200) continue;  // keep to X >= 1e-100 here
      expect(tail.log_value(0, s), exp(-t), "J_0", shape, s);
      expect(tail.log_value(2, s), boost::math::tgamma(1 / a, t) / a, "J_1", shape, s);
    }
    for (double d : {1e-6, 0.01, 0.2, 0.9, 1.5, 4.0, 9.0}) {
      const Precise tau = pow(Precise(d), a);
      if (tau < 1e-20) continue;  // d - gamma(1/a, tau)/a cancels ~|log10 tau| of the 50 digits
      expect(bounded.log_value(0, -d), -boost::multiprecision::expm1(-tau), "K_0", shape, -d);
      expect(bounded.log_value(2, -d), Precise(d) - boost::math::tgamma_lower(1 / a, tau) / a, "K_1", shape, -d);
    }
  }
  // a = 1: J_n = Gamma(n+1) e^-s for s >= 0 (stiffness/load exactly 1); a = 2: J_1 = sqrt(pi)/2 erfc(s).
  const Curve exponential = table().curve(Distribution::weibull, Side::tail, 1.0);
  const Curve rayleigh = table().curve(Distribution::weibull, Side::tail, 2.0);
  for (double s : {0.0, 0.5, 3.0, 40.0, 200.0}) {
    for (int k = 0; k < order_count; ++k)
      expect(exponential.log_value(k, s), boost::math::tgamma(Precise(order_of(k)) + 1) * exp(-Precise(s)), "a=1", 1, s);
    EXPECT_NEAR(1.5 * std::exp(exponential.log_value(1, s) - exponential.log_value(3, s)), 1.0, 1e-12);
    if (s < 15)
      expect(rayleigh.log_value(2, s), boost::math::constants::root_pi<Precise>() / 2 * boost::math::erfc(Precise(s)),
             "a=2 J_1", 2, s);
  }
  // Gaussian: F_0 = erfc(s/sqrt 2)/2, F_1 = phi(s) - s F_0.
  const Curve gaussian = table().curve(Distribution::gaussian, Side::tail, 0);
  for (double s : {-8.0, -3.0, -0.5, 0.0, 0.7, 2.0, 5.0, 12.0, 20.0}) {
    const Precise f0 = boost::math::erfc(Precise(s) / boost::math::constants::root_two<Precise>()) / 2;
    const Precise phi = exp(-Precise(s) * s / 2) / boost::math::constants::root_two_pi<Precise>();
    expect(gaussian.log_value(0, s), f0, "F_0", 2, s);
    expect(gaussian.log_value(2, s), phi - s * f0, "F_1", 2, s);
  }
  std::printf("\nMeasured maximum relative error against closed forms: %.2e\n", worst);
}

// dX_n/ds = -n X_(n-1) between interpolated values (Richardson-extrapolated central differences).
TEST(Accuracy, DerivativeChainBetweenInterpolatedValues) {
  double worst = 0;
  auto check_curve = [&](const Curve& curve, const std::vector<double>& separations) {
    for (double s : separations)
      for (int k = 2; k < order_count; ++k) {
        const double n = order_of(k);
        auto log_x = [&](double x) { return curve.log_value(k, x); };
        const double h = 1e-3 * std::max(0.05, std::fabs(s));
        const double d1 = (log_x(s + h) - log_x(s - h)) / (2 * h);
        const double d2 = (log_x(s + h / 2) - log_x(s - h / 2)) / h;
        const double slope = (4 * d2 - d1) / 3;  // d ln X_n/ds
        const double chain = -n * std::exp(curve.log_value(k - 2, s) - curve.log_value(k, s));
        const double error = std::fabs(slope / chain - 1);
        worst = std::max(worst, error);
        EXPECT_LE(error, 1e-6) << to_string(curve.side()) << " shape " << curve.shape() << " order " << n << " s " << s;
      }
  };
  for (double shape : {0.5, 2.0, 20.0, 3.3}) {
    const Curve tail = table().curve(Distribution::weibull, Side::tail, shape);
    check_curve(tail, {-5, -1, -0.2, 0.3, 0.5 * std::pow(50.0, 1 / shape), std::pow(300.0, 1 / shape)});
    const Curve bounded = table().curve(Distribution::weibull, Side::bounded, shape);
    check_curve(bounded, {-0.3, -1, -1.5, -4, -9});
  }
  check_curve(table().curve(Distribution::gaussian, Side::tail, 0), {-5, -1, 0.3, 2, 8, 20});
  std::printf("\nMeasured maximum relative mismatch of dX_n/ds = -n X_(n-1): %.2e\n", worst);
}

TEST(Accuracy, ValuesStayFiniteAndOrderedInTheFarTail) {
  // Below 1e-300 the logs remain finite and keep falling; the values underflow to exactly 0 only.
  for (double shape : {0.5, 2.0, 20.0}) {
    const Curve curve = table().curve(Distribution::weibull, Side::tail, shape);
    double previous = INFINITY;
    for (double t = 1; t < 1e6; t *= 1.7) {
      const double s = std::pow(t, 1 / shape), log_value = curve.log_value(5, s);
      ASSERT_TRUE(std::isfinite(log_value)) << shape << " " << s;
      EXPECT_LT(log_value, previous);
      previous = log_value;
      EXPECT_GE(curve.value(5, s), 0.0);
    }
  }
}

}  // namespace
