// Goodness of fit, confidence intervals and a verdict, for the three height models on one sample.
//
//   Anderson-Darling A^2 = -n - (1/n) sum (2i-1) [ln F(x_(i)) + ln(1 - F(x_(n+1-i)))]
//   Kolmogorov-Smirnov D = max_i max(i/n - F(x_(i)), F(x_(i)) - (i-1)/n)
// The parameters are estimated from the same data, so the textbook null distributions (for a
// fully specified F) do not apply: the p-values come from a parametric bootstrap. B samples of
// size n are drawn from the fitted distribution, each is refitted with the same estimator, and
// its A^2 and D against its own refit are the null sample; p = (1 + #{A*^2 >= A^2}) / (B + 1).
// The refits give the confidence intervals too: percentile intervals of the refitted
// parameters (for the Weibull models the shape, which is what the contact curves depend on);
// a surface's samples make their shape intervals otherwise (ShapeInterval below, surface_tests.hpp).
// AIC = 2k - 2 ln L at the estimate (MPS for the Weibull models, ML for the Gaussian). With a
// shape below 1, ln L is finite at the MPS estimate but grows as the location nears the
// smallest value: the AIC of such a fit leans toward it; the verdict rests on the tests first.
//
// Random numbers: std::mt19937_64 (its output sequence is defined by the standard) seeded per
// replicate from (seed, model, replicate), uniforms from its bits and the quantile function,
// so results are the same on every platform and for every thread count.
//
// The samples are assumed independent; a map's heights and summit heights are not (neighbours
// share the long wavelengths): a map is tested against surrogate surfaces of its own spectrum
// instead (surface_tests.hpp). Both draw their null samples their own way and share the rest:
// the refits' p-values, intervals, the shape's identification, the Akaike weights and the verdict.
#pragma once
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "asperity/topography/distribution_fit.hpp"

namespace asperity::topography {

double anderson_darling(const HeightDistribution& distribution, const std::vector<double>& sorted);
double kolmogorov_smirnov(const HeightDistribution& distribution, const std::vector<double>& sorted);
// Both at once, from one evaluation of the law a point.
struct FitStatistics {
  double anderson_darling = 0, kolmogorov_smirnov = 0;
};
FitStatistics fit_statistics(const HeightDistribution& distribution, const std::vector<double>& sorted);

// Bootstrap samples: each is three refits; bounded (as `asperity surface --bootstrap` is), so that
// an option cannot make the assessment's time unbounded.
inline constexpr int max_bootstrap = 100000;

// B: bootstrap samples (assess_sample) or surrogate surfaces (the surface analysis), 0 to
// max_bootstrap; 0: no p-values and no intervals (no test: the verdict says so). Its fields defined
// once (record_fields.hpp): report.json's fits.* give B, the seed and the levels
#define ASPERITY_ASSESSMENT_OPTIONS_FIELDS(X)                                                              \
  X(int, bootstrap, "surrogates", "B, the bootstrap samples or surrogate surfaces (0: no test)", 99)      \
  X(std::uint64_t, seed, "seed", "the ensemble's seed (reproducible)", 1)                                 \
  X(int, threads, nullptr, "threads (0: the hardware's)")                                                 \
  X(double, confidence, "confidence", "the intervals' confidence", 0.95)                                  \
  X(double, significance, "significance", "the tests' significance, for the verdict", 0.05)              \
  X(FitOptions, fit, nullptr, "the Weibull shape's search range of the fits")

struct AssessmentOptions {
  ASPERITY_ASSESSMENT_OPTIONS_FIELDS(ASPERITY_RECORD_MEMBER_INIT)
};

#define ASPERITY_INTERVAL_FIELDS(X)          \
  X(double, lo, "lo", "the interval's lower end") \
  X(double, hi, "hi", "the interval's upper end")

struct Interval {
  ASPERITY_INTERVAL_FIELDS(ASPERITY_RECORD_MEMBER_INIT)
};

// How a Weibull's shape interval is made from the refitted shapes: the enum the interval's code
// switches on (verdict::conclude, sample_verdict.cpp) and every output's words for it
// (interval_method), so that a label cannot say another method than the one that ran.
enum class ShapeInterval {
  none,                 // no refits (no ensemble or bootstrap): no interval
  percentile,           // the refits' percentiles (assess_sample's i.i.d. bootstrap: drawn at the estimate)
  centred_on_estimate,  // the refits' spread about their median carried to the estimate (a surface's summit heights)
  bias_corrected,       // the basic interval in ln a corrected for a bias that changes with a (a surface's heights)
};
// "none", "percentile", "centred-on-estimate", "bias-corrected"
const char* to_string(ShapeInterval interval);
// The intervals of a sample whose Weibull shapes were made so, in words (report.json's
// fits.*.intervals, report.md): the location's and scale's percentiles and the shape's method.
std::string interval_method(ShapeInterval interval);

// location and scale: percentile intervals of the refits; shape (Weibull only): made as
// shape_interval says (percentile for assess_sample; a surface's samples: surface_tests.hpp), set
// by the code that made them (none until then). A p at its floor 1/(B' + 1) (B' the refits that
// succeeded; no refit reached the statistic) is a bound, "p <= 1/(B' + 1)", not a value. The shape
// is identified when its interval stays inside the fit's bounds and at most a tenth of the refits
// end at a bound. bias_slope: the heights' Weibull shape interval's d(bias of ln a_hat)/d(ln a),
// measured on the surrogates (surface_tests.hpp); NaN where not measured (the summit heights, the
// Gaussian, an i.i.d. bootstrap). The fields defined once (record_fields.hpp), in report.json's
// order after the fit's (its fits.*.models[]; the intervals there as [lo, hi]).
#define ASPERITY_MODEL_ASSESSMENT_FIELDS(X)                                                                   \
  X(FitResult, fit, nullptr, "the fit")                                                                      \
  X(bool, shape_identified, "shape_identified", "the data pin the shape down (its interval stays inside the fit's bounds)", true) \
  X(std::string, identification, "identification", "why not, when not")                                       \
  X(Interval, location, nullptr, "the location's interval [m]")                                              \
  X(Interval, scale, nullptr, "the scale's interval [m]")                                                    \
  X(Interval, shape, nullptr, "the shape's interval (Weibull only)")                                        \
  X(ShapeInterval, shape_interval, "interval_shape_method",                                                  \
    "how the intervals were made: 'percentile', 'centred-on-estimate', 'bias-corrected', or 'none' (no refits)") \
  X(double, bias_slope, "shape_bias_slope",                                                                  \
    "the heights' Weibull shape: d(bias of ln a)/d(ln a) on the surrogates, which its interval corrects for (NaN where not measured)", \
    std::numeric_limits<double>::quiet_NaN())                                                                \
  X(double, anderson_darling, "anderson_darling", "the Anderson-Darling statistic A^2")                     \
  X(double, anderson_darling_p, "anderson_darling_p", "its p-value, by parametric bootstrap")                \
  X(bool, p_at_floor, "anderson_darling_p_is_bound",                                                         \
    "the Anderson-Darling p-value is at its floor 1/(B + 1): a bound (p <= ...), not a value")              \
  X(double, kolmogorov_smirnov, "kolmogorov_smirnov", "the Kolmogorov-Smirnov statistic D")                 \
  X(double, kolmogorov_smirnov_p, "kolmogorov_smirnov_p", "its p-value, by parametric bootstrap")            \
  X(bool, kolmogorov_smirnov_p_at_floor, "kolmogorov_smirnov_p_is_bound",                                    \
    "the Kolmogorov-Smirnov p-value is at its floor 1/(B + 1): a bound, not a value")                       \
  X(double, log_likelihood, "log_likelihood", "ln L of the sample")                                         \
  X(double, aic, "aic", "Akaike's information criterion")                                                    \
  X(double, delta_aic, "delta_aic", "AIC minus the lowest AIC of the models")                               \
  X(double, akaike_weight, "akaike_weight", "the Akaike weight over all three models")                      \
  X(bool, rejected, "rejected", "the Anderson-Darling p-value is below the significance")                   \
  X(int, failed_refits, "failed_refits", "refits that failed")                                              \
  X(int, bootstrap, nullptr, "the bootstrap's size B")

struct ModelAssessment {
  ASPERITY_MODEL_ASSESSMENT_FIELDS(ASPERITY_RECORD_MEMBER_INIT)
};

#define ASPERITY_VERDICT_FIELDS(X)                                                                       \
  X(bool, gaussian_rejected, "gaussian_rejected", "the Gaussian is rejected")                           \
  X(HeightModel, best, "best", "the lowest AIC among the models neither rejected nor of an unidentified shape") \
  X(bool, best_rejected, "best_rejected", "every model was rejected: the best by AIC anyway")           \
  X(double, aic_gain_over_gaussian, "aic_gain_over_gaussian", "AIC(Gaussian) - AIC(best)")              \
  X(std::string, text, "text", "the verdict with its evidence, in words")

struct Verdict {
  ASPERITY_VERDICT_FIELDS(ASPERITY_RECORD_MEMBER_INIT)
};

// report.json's fits.summit_heights and fits.heights: these fields, the options' and the models'
#define ASPERITY_SAMPLE_ASSESSMENT_FIELDS(X)                                                          \
  X(std::string, name, "sample", "the sample: \"summit heights\", \"heights (thinned)\"")              \
  X(std::size_t, n, "n", "its size")                                                                 \
  X(std::vector<ModelAssessment>, models, nullptr, "in HeightModel order: gaussian, weibull_tail, weibull_bounded") \
  X(Verdict, verdict, "verdict", "which model the evidence favours")                                \
  X(AssessmentOptions, options, nullptr, "the bootstrap and the tests")

struct SampleAssessment {
  ASPERITY_SAMPLE_ASSESSMENT_FIELDS(ASPERITY_RECORD_MEMBER_INIT)
  const ModelAssessment& model(HeightModel m) const { return models[static_cast<int>(m)]; }
};

// The smallest bootstrap that can reject at `significance`: p >= 1/(B + 1), so B + 1 > 1/significance
// (20 samples at 5%). check_bootstrap_size throws asperity::Error for 0 < B below it (and B < 0).
int minimum_bootstrap(double significance);
void check_bootstrap_size(int bootstrap, double significance);

// A bootstrap p-value as every output writes it: "p = 0.0123", or "p <= 0.005" at its floor (a
// bound, not a value); "not tested" for NaN (no bootstrap).
std::string p_value_text(double p, bool at_floor);

// Fits the three models, bootstraps, and gives the verdict. `values` need not be sorted.
// asperity::Error for confidence or significance outside (0, 1), bootstrap outside
// [0, max_bootstrap], or values the fits refuse.
SampleAssessment assess_sample(const std::string& name, std::vector<double> values, const AssessmentOptions& options = {});
// Each model's AIC difference from the least and its Akaike weight, over every compared model
// (the rejected ones too: the weights are about the likelihoods, the tests about the fit); the
// one weighting both verdict paths use (assess_sample, surface_tests.hpp).
void weigh_models(SampleAssessment& sample);

// The parametric-bootstrap p-value of the Anderson-Darling (and KS) test of one model on one
// sample: exposed for the size and power measurements.
struct TestResult {
  FitResult fit;
  double anderson_darling = 0, anderson_darling_p = 0, kolmogorov_smirnov = 0, kolmogorov_smirnov_p = 0;
  bool anderson_darling_p_at_floor = false, kolmogorov_smirnov_p_at_floor = false;  // bounds (ModelAssessment)
  std::vector<double> refit_shapes, refit_locations, refit_scales;
  int failed_refits = 0;
};
TestResult bootstrap_test(HeightModel model, const std::vector<double>& sorted, int bootstrap, std::uint64_t seed,
                          int threads, const FitOptions& fit = {});

// Reproducible draws from a distribution (the same generator as the bootstrap).
std::vector<double> draw_sample(const HeightDistribution& distribution, std::size_t n, std::uint64_t seed);

}  // namespace asperity::topography

namespace asperity {
ASPERITY_DEFINE_RECORD(topography::Interval, ASPERITY_INTERVAL_FIELDS)
ASPERITY_DEFINE_RECORD(topography::ModelAssessment, ASPERITY_MODEL_ASSESSMENT_FIELDS)
ASPERITY_DEFINE_RECORD(topography::Verdict, ASPERITY_VERDICT_FIELDS)
ASPERITY_DEFINE_RECORD(topography::AssessmentOptions, ASPERITY_ASSESSMENT_OPTIONS_FIELDS)
ASPERITY_DEFINE_RECORD(topography::SampleAssessment, ASPERITY_SAMPLE_ASSESSMENT_FIELDS)
}  // namespace asperity
