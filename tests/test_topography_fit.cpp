// Distribution fits: the Gaussian, the three-parameter Weibull by maximum product of spacings
// (both sides, shapes below 1 included), goodness of fit by parametric bootstrap, the verdict.
#include <gtest/gtest.h>

#include <algorithm>
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <string>

#include "asperity/error.hpp"
#include "asperity/topography/distribution_fit.hpp"
#include "asperity/topography/goodness_of_fit.hpp"
#include "verdict/spacing_fit.hpp"
#include "verdict/vector_math.hpp"

namespace t = asperity::topography;

namespace {
std::vector<double> sorted_sample(const t::HeightDistribution& d, std::size_t n, std::uint64_t seed) {
  std::vector<double> x = t::draw_sample(d, n, seed);
  std::sort(x.begin(), x.end());
  return x;
}
t::HeightDistribution weibull(t::HeightModel model, double location, double scale, double shape) {
  t::HeightDistribution d;
  d.model = model;
  d.location = location;
  d.scale = scale;
  d.shape = shape;
  return d;
}
}  // namespace

TEST(TopographyFit, DistributionFunctionsAgree) {
  for (t::HeightModel model : t::all_height_models) {
    t::HeightDistribution d = weibull(model, 0.3, 2.0, 1.7);
    if (model == t::HeightModel::gaussian) d.shape = 0;
    for (double p : {1e-6, 0.01, 0.3, 0.5, 0.9, 0.999999}) {
      const double x = d.quantile(p);
      EXPECT_NEAR(d.cdf(x), p, 1e-12 * std::max(1.0, 1 / p)) << t::to_string(model);
      EXPECT_NEAR(std::exp(d.log_sf(x)), 1 - p, 1e-9) << t::to_string(model);
    }
    // the density integrates the distribution function (midpoint rule across a small step)
    const double x = d.quantile(0.4), h = 1e-5 * d.standard_deviation();
    EXPECT_NEAR((d.cdf(x + h) - d.cdf(x - h)) / (2 * h), std::exp(d.log_pdf(x)), 1e-6) << t::to_string(model);
  }
}

// The functions are noexcept and answer by value: NaN outside the quantile's (0, 1) and for
// parameters that are no distribution (Boost.Math threw through noexcept there: the process
// ended), +-inf where a moment is beyond the largest double.
TEST(TopographyFit, DistributionFunctionsAnswerBadArgumentsByValue) {
  const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
  for (t::HeightModel model : t::all_height_models) {
    const t::HeightDistribution d = weibull(model, 0.3, 2.0, 1.7);
    for (double p : {0.0, 1.0, -0.5, 1.5, -inf, inf, nan}) EXPECT_TRUE(std::isnan(d.quantile(p))) << p;
    EXPECT_TRUE(std::isfinite(d.quantile(std::numeric_limits<double>::denorm_min())));
    EXPECT_TRUE(std::isfinite(d.quantile(std::nextafter(1.0, 0.0))));
    for (double scale : {0.0, -1.0, inf, nan}) {
      const t::HeightDistribution bad = weibull(model, 0.3, scale, 1.7);
      EXPECT_TRUE(std::isnan(bad.quantile(0.5)) && std::isnan(bad.mean()) && std::isnan(bad.standard_deviation()))
          << t::to_string(model) << " scale " << scale;
    }
    for (double location : {inf, -inf, nan}) {
      const t::HeightDistribution bad = weibull(model, location, 2.0, 1.7);
      EXPECT_TRUE(std::isnan(bad.quantile(0.5)) && std::isnan(bad.mean()) && std::isnan(bad.standard_deviation()));
    }
    if (model == t::HeightModel::gaussian) continue;
    for (double shape : {0.0, -0.5, -1.0, -2.0, inf, nan}) {
      const t::HeightDistribution bad = weibull(model, 0.3, 2.0, shape);
      EXPECT_TRUE(std::isnan(bad.quantile(0.5)) && std::isnan(bad.mean()) && std::isnan(bad.standard_deviation()))
          << t::to_string(model) << " shape " << shape;
    }
    // shape 1e-3: Gamma(1001) ~ 4e2564 and Gamma(2001): both moments beyond any double
    const t::HeightDistribution extreme = weibull(model, 0.3, 2.0, 1e-3);
    EXPECT_EQ(extreme.mean(), model == t::HeightModel::weibull_tail ? inf : -inf);
    EXPECT_EQ(extreme.standard_deviation(), inf);
    EXPECT_EQ(weibull(model, 0.3, 2.0, std::numeric_limits<double>::denorm_min()).standard_deviation(), inf);
  }
}

// Where Gamma(1 + 1/a) or Gamma(1 + 2/a) overflows but the moment does not (a = 2^-8, scale
// 1e-300): the mean 256! 1e-300 and the standard deviation sqrt(512! - 256!^2) 1e-300, against
// the factorials in 50 digits.
TEST(TopographyFit, MomentsWhereGammaOverflows) {
  using boost::multiprecision::cpp_bin_float_50;
  cpp_bin_float_50 f256 = 1, f512 = 1;
  for (int k = 2; k <= 512; ++k) {
    f512 *= k;
    if (k <= 256) f256 *= k;
  }
  const cpp_bin_float_50 scale("1e-300");
  const double mean = static_cast<double>(f256 * scale);
  const double sd = static_cast<double>(sqrt(f512 - f256 * f256) * scale);
  const t::HeightDistribution d = weibull(t::HeightModel::weibull_tail, 0, 1e-300, 0x1p-8);
  EXPECT_NEAR(d.mean() / mean - 1, 0, 1e-12);
  EXPECT_NEAR(d.standard_deviation() / sd - 1, 0, 1e-12);
  const t::HeightDistribution mirrored = weibull(t::HeightModel::weibull_bounded, 0, 1e-300, 0x1p-8);
  EXPECT_NEAR(mirrored.mean() / -mean - 1, 0, 1e-12);
}

// The bootstrap's size is bounded (as --bootstrap is): 2^31 - 1 refits would run for days.
TEST(TopographyFit, BootstrapSizeIsBounded) {
  const std::vector<double> values = sorted_sample(weibull(t::HeightModel::weibull_tail, 0, 1, 1.5), 50, 1);
  for (int bootstrap : {-1, t::max_bootstrap + 1, 2147483647}) {
    t::AssessmentOptions options;
    options.bootstrap = bootstrap;
    try {
      t::assess_sample("sample", values, options);
      ADD_FAILURE() << "bootstrap " << bootstrap << " accepted";
    } catch (const asperity::Error& error) {
      EXPECT_NE(std::string(error.what()).find("bootstrap must be from 0 to 100000"), std::string::npos) << error.what();
    }
  }
}

// The three-parameter Weibull by MPS recovers the shape, below 1 as well, on both sides.
TEST(TopographyFit, MaximumProductOfSpacingsRecoversShapes) {
  for (t::HeightModel model : {t::HeightModel::weibull_tail, t::HeightModel::weibull_bounded})
    for (double shape : {0.5, 0.8, 1.0, 1.5, 3.0, 6.0}) {
      const t::HeightDistribution truth = weibull(model, -2.0, 1.5, shape);
      const std::vector<double> x = sorted_sample(truth, 2000, 7 + static_cast<std::uint64_t>(10 * shape));
      const t::FitResult fit = t::fit_height_distribution(model, x);
      EXPECT_NEAR(fit.distribution.shape, shape, 0.12 * shape) << t::to_string(model) << " a = " << shape;
      EXPECT_NEAR(fit.distribution.scale, 1.5, 0.15 * 1.5) << t::to_string(model) << " a = " << shape;
      // the location stays strictly beyond the extreme observation: the estimate exists
      if (model == t::HeightModel::weibull_tail) EXPECT_LT(fit.distribution.location, x.front());
      else EXPECT_GT(fit.distribution.location, x.back());
      EXPECT_FALSE(fit.shape_at_bound);
      EXPECT_TRUE(std::isfinite(fit.objective));
    }
}

// Where maximum likelihood degenerates (a < 1: ln L -> +inf as the location reaches the
// smallest value) the spacing objective stays bounded and peaks at a finite gap.
TEST(TopographyFit, SpacingObjectiveBoundedWhereLikelihoodIsNot) {
  const t::HeightDistribution truth = weibull(t::HeightModel::weibull_tail, 0.0, 1.0, 0.6);
  const std::vector<double> x = sorted_sample(truth, 500, 11);
  double previous_likelihood = -1e300;
  for (double gap : {1e-2, 1e-4, 1e-6, 1e-8, 1e-10}) {
    const t::HeightDistribution near = weibull(t::HeightModel::weibull_tail, x.front() - gap, 1.0, 0.6);
    const double likelihood = t::log_likelihood(near, x);
    EXPECT_GT(likelihood, previous_likelihood);  // grows without bound
    previous_likelihood = likelihood;
    EXPECT_LT(t::mean_log_spacing(near, x), 0.0);  // every spacing is a probability
  }
  const t::FitResult fit = t::fit_height_distribution(t::HeightModel::weibull_tail, x);
  EXPECT_GT(x.front() - fit.distribution.location, 1e-8);
  EXPECT_NEAR(fit.distribution.shape, 0.6, 0.1);
}

// Quantized data (ties) do not break the estimator.
TEST(TopographyFit, TiesFromQuantizedData) {
  const t::HeightDistribution truth = weibull(t::HeightModel::weibull_bounded, 1.0, 1.0, 2.0);
  std::vector<double> x = sorted_sample(truth, 1000, 5);
  for (double& v : x) v = std::round(v * 100) / 100;  // 0.01 steps: many ties
  const t::FitResult fit = t::fit_height_distribution(t::HeightModel::weibull_bounded, x);
  EXPECT_NEAR(fit.distribution.shape, 2.0, 0.25);
  EXPECT_GT(fit.distribution.location, x.back());
}

TEST(TopographyFit, BadSamplesRefused) {
  EXPECT_THROW(t::fit_height_distribution(t::HeightModel::weibull_tail, {1, 2, 3}), asperity::Error);
  EXPECT_THROW(t::fit_height_distribution(t::HeightModel::gaussian, {1, 1, 1, 1, 1, 1}), asperity::Error);
  EXPECT_THROW(t::fit_height_distribution(t::HeightModel::gaussian, {1, 2, 3, 4, NAN}), asperity::Error);
  EXPECT_THROW(t::fit_height_distribution(t::HeightModel::gaussian, {5, 4, 3, 2, 1}), asperity::Error);
}

// The bootstrap interval of the shape holds the true shape (shapes below 1 included, both
// sides), and the right model is not rejected.
TEST(TopographyFit, BootstrapIntervalHoldsTheShape) {
  int covered = 0, cases = 0;
  for (t::HeightModel model : {t::HeightModel::weibull_tail, t::HeightModel::weibull_bounded})
    for (double shape : {0.6, 0.9, 1.5, 4.0}) {
      const t::HeightDistribution truth = weibull(model, 1.0, 0.5, shape);
      const std::vector<double> x = sorted_sample(truth, 400, 100 + static_cast<std::uint64_t>(shape * 10) + 7 * static_cast<int>(model));
      t::AssessmentOptions options;
      options.bootstrap = 99;
      const t::SampleAssessment a = t::assess_sample("weibull", x, options);
      const t::ModelAssessment& m = a.model(model);
      ++cases;
      covered += (m.shape.lo <= shape && shape <= m.shape.hi) ? 1 : 0;
      EXPECT_LT(m.shape.lo, m.fit.distribution.shape);
      EXPECT_GT(m.shape.hi, m.fit.distribution.shape);
      EXPECT_FALSE(m.rejected) << t::to_string(model) << " a = " << shape << " p = " << m.anderson_darling_p;
      EXPECT_EQ(m.failed_refits, 0);
      std::printf("%s a=%.2f fit %.3f [%.3f, %.3f] AD p %.3f  gaussian p %.3f best %s\n", t::to_string(model), shape,
                  m.fit.distribution.shape, m.shape.lo, m.shape.hi, m.anderson_darling_p,
                  a.model(t::HeightModel::gaussian).anderson_darling_p, t::to_string(a.verdict.best));
    }
  // 95% intervals: all 8 in, or at most one out by chance (P(>= 2 out) = 5.7% if exact)
  EXPECT_GE(covered, cases - 1);
}

// The size of the bootstrap Anderson-Darling test of the Gaussian at 5%, measured on Gaussian
// data, and its power against Weibull a = 1.5 data (n = 100 each). With 400 data sets the
// rejection rate's standard error at 5% is 1.1%: the bound is 3 standard errors.
// ASPERITY_TEST_SUBSAMPLE=k (CI's sanitizer pass) uses 400/k sets, the bound widened to match.
TEST(TopographyFit, AndersonDarlingSizeAndPower) {
  int subsample = 1;
  if (const char* text = std::getenv("ASPERITY_TEST_SUBSAMPLE")) subsample = std::max(1, std::atoi(text));
  t::HeightDistribution gaussian;
  gaussian.location = 3;
  gaussian.scale = 2;
  const t::HeightDistribution weibull15 = weibull(t::HeightModel::weibull_tail, 0, 1, 1.5);
  const int sets = std::max(80, 400 / subsample), bootstrap = 99;
  int rejected_gaussian = 0, rejected_weibull = 0;
  for (int k = 0; k < sets; ++k) {
    const std::vector<double> g = sorted_sample(gaussian, 100, 1000 + k);
    rejected_gaussian += t::bootstrap_test(t::HeightModel::gaussian, g, bootstrap, k, 1).anderson_darling_p <= 0.05;
    const std::vector<double> w = sorted_sample(weibull15, 100, 5000 + k);
    rejected_weibull += t::bootstrap_test(t::HeightModel::gaussian, w, bootstrap, k, 1).anderson_darling_p <= 0.05;
  }
  const double size = static_cast<double>(rejected_gaussian) / sets, power = static_cast<double>(rejected_weibull) / sets;
  std::printf("Anderson-Darling (Gaussian null, n = 100, B = %d, %d sets): size %.3f at 5%%, power %.3f on Weibull a = 1.5\n",
              bootstrap, sets, size, power);
  EXPECT_NEAR(size, 0.05, 3 * std::sqrt(0.05 * 0.95 / sets));
  EXPECT_GT(power, 0.5);
}

// The spacing objective's gradient, which the L-BFGS fit relies on, against central differences
// (ties included), and the fit against a derivative-free search of the same objective.
TEST(TopographyFit, SpacingGradientIsExact) {
  for (double shape : {0.6, 1.5, 4.0, 12.0}) {
    t::HeightDistribution d{t::HeightModel::weibull_tail, -1, 2, shape};
    std::vector<double> x = t::draw_sample(d, 300, 11);
    std::sort(x.begin(), x.end());
    std::vector<double> y(x.size());
    for (std::size_t k = 0; k < x.size(); ++k) y[k] = x[k] - x[0];
    y[150] = y[149];  // a tie
    const t::detail::SpacingProblem problem{&y, std::log(1e-6), {}};
    for (double gap : {1e-3, 0.1, 1.0}) {
      const double p[3] = {std::log(gap), std::log(2.0), std::log(shape)};
      double gradient[3];
      t::detail::spacing_objective(problem, p, gradient);
      for (int k = 0; k < 3; ++k) {
        double plus[3] = {p[0], p[1], p[2]}, minus[3] = {p[0], p[1], p[2]};
        const double h = 1e-6;
        plus[k] += h;
        minus[k] -= h;
        const double numeric =
            (t::detail::spacing_objective(problem, plus, nullptr) - t::detail::spacing_objective(problem, minus, nullptr)) /
            (2 * h);
        EXPECT_NEAR(gradient[k], numeric, 1e-6 * std::max(1.0, std::fabs(numeric)))
            << "shape " << shape << " gap " << gap << " parameter " << k;
      }
    }
    // the maximum L-BFGS finds is no lower than a fine derivative-free scan around it finds
    const t::FitResult fit = t::fit_height_distribution(t::HeightModel::weibull_tail, x);
    double best = -std::numeric_limits<double>::infinity();
    for (int a = -20; a <= 20; ++a) {
      t::HeightDistribution near = fit.distribution;
      near.shape *= 1 + 0.002 * a;
      best = std::max(best, t::mean_log_spacing(near, x));
    }
    EXPECT_GE(fit.objective, best - 1e-12) << "shape " << shape;
  }
}

// ln, exp and expm1 a vector at a time (vector_math.hpp) within their documented ulp of the
// standard library's, over their ranges' ends and near 0 (expm1's cancellation), with array
// lengths that leave a partial vector.
TEST(TopographyFit, VectorMathWithinItsUlp) {
  const auto ulps = [](double got, double want) {
    if (got == want) return 0.0;
    const double spacing = std::nextafter(std::fabs(want), std::numeric_limits<double>::infinity()) - std::fabs(want);
    return std::fabs(got - want) / spacing;
  };
  std::vector<double> x, out;
  const auto check = [&](void (*f)(const double*, double*, std::size_t) noexcept, double (*reference)(double),
                         double bound, const char* name) {
    for (std::size_t n : {x.size(), x.size() - 1, std::size_t{3}, std::size_t{1}}) {
      out.assign(n, 0.0);
      f(x.data(), out.data(), n);
      double worst = 0;
      for (std::size_t k = 0; k < n; ++k) worst = std::max(worst, ulps(out[k], reference(x[k])));
      EXPECT_LE(worst, bound) << name << " over " << n << " arguments";
    }
  };
  x.clear();
  for (double e = -307; e <= 307; e += 0.37) x.push_back(std::pow(10.0, e));
  for (double v = 0.5; v < 2; v += 1e-3) x.push_back(v);  // around 1, where ln cancels
  check(t::detail::vector_log, [](double v) { return std::log(v); }, 4, "log");
  x.clear();
  for (double v = -700; v <= t::detail::vector_exp_max; v += 0.731) x.push_back(v);
  for (double v = -1; v <= 1; v += 1e-3) x.push_back(v);
  check(t::detail::vector_exp, [](double v) { return std::exp(v); }, 1, "exp");
  for (double e = -300; e <= -1; e += 0.53) {
    x.push_back(std::pow(10.0, e));
    x.push_back(-std::pow(10.0, e));
  }
  check(t::detail::vector_expm1, [](double v) { return std::expm1(v); }, 4, "expm1");
}

// The spacing objective in 50 digits (Boost.Multiprecision), the same formula on the same
// (double) data: the reference of the test below.
double precise_spacing_objective(const std::vector<double>& y, double log_delta, const double p[3]) {
  using Real = boost::multiprecision::cpp_bin_float_50;
  const Real gap = exp(Real(p[0])), shape = exp(Real(p[2])), log_scale = p[1];
  Real sum = 0, t_previous = 0;
  for (double v : y) {
    const Real log_w = log(Real(v) + gap) - log_scale;
    const Real t = exp(shape * log_w);
    const Real step = t - t_previous;
    if (step > 0)
      sum += -t_previous + log(-expm1(-step));
    else
      sum += Real(p[2]) - log_scale + (shape - 1) * log_w - t + log_delta;
    t_previous = t;
  }
  return static_cast<double>((sum - t_previous) / (y.size() + 1));
}

// The objective's formula with <cmath> a point at a time (as it was before its functions went a
// vector at a time).
double scalar_spacing_objective(const std::vector<double>& y, double log_delta, const double p[3]) {
  const double gap = std::exp(p[0]), shape = std::exp(p[2]), log_scale = p[1];
  double sum = 0, t_previous = 0;
  for (double v : y) {
    const double log_w = std::log(v + gap) - log_scale;
    const double t = std::exp(shape * log_w);
    const double step = t - t_previous;
    if (step > 0)
      sum += step < 700 ? -t + std::log(std::expm1(step)) : -t_previous + std::log1p(-std::exp(-step));
    else
      sum += p[2] - log_scale + (shape - 1) * log_w - t + log_delta;
    t_previous = t;
  }
  return (sum - t_previous) / static_cast<double>(y.size() + 1);
}

// The vectorized spacing objective against a 50-digit evaluation: within 16 times the error of
// the scalar evaluations (the same formula with <cmath>, and mean_log_spacing's), plus 1e-13
// (Highway's functions are within 1-4 ulp where glibc's are within 1; measured: at most 10 times).
// Differences of neighbouring t lose digits where the shape is small (every evaluation alike:
// up to 8e-8 at shape 0.3). Sharp and singular shapes, gaps from 1e-9 to 10, a tie.
TEST(TopographyFit, SpacingObjectiveMatchesScalarEvaluation) {
  for (double shape : {0.3, 0.6, 1.5, 4.0, 12.0, 50.0}) {
    t::HeightDistribution d{t::HeightModel::weibull_tail, -1, 2, shape};
    std::vector<double> y = t::draw_sample(d, 1001, 23);
    std::sort(y.begin(), y.end());
    const double first = y[0];
    for (double& v : y) v -= first;
    y[500] = y[499];  // a tie
    double smallest = std::numeric_limits<double>::infinity();
    for (std::size_t k = 1; k < y.size(); ++k)
      if (y[k] > y[k - 1]) smallest = std::min(smallest, y[k] - y[k - 1]);
    const t::detail::SpacingProblem problem{&y, std::log(smallest), {}};
    for (double gap : {1e-9, 1e-3, 0.1, 1.0, 10.0})
      for (double scale : {0.05, 1.0, 20.0}) {
        const double p[3] = {std::log(gap), std::log(scale), std::log(shape)};
        const double vectorized = t::detail::spacing_objective(problem, p, nullptr);
        const double precise = precise_spacing_objective(y, std::log(smallest), p);
        const t::HeightDistribution at{t::HeightModel::weibull_tail, -gap, scale, shape};
        const double scalar = t::mean_log_spacing(at, y);
        const double scalar_error = std::max(std::fabs(scalar - precise),
                                             std::fabs(scalar_spacing_objective(y, std::log(smallest), p) - precise));
        const double error = std::fabs(vectorized - precise);
        EXPECT_LE(error, 16 * scalar_error + 1e-13 * std::max(1.0, std::fabs(precise)))
            << "shape " << shape << " gap " << gap << " scale " << scale;
      }
  }
}
