#include "asperity/topography/goodness_of_fit.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include "asperity/detail/parallel_for.hpp"
#include "asperity/error.hpp"
#include "sample_verdict.hpp"

namespace asperity::topography {
namespace {

// a uniform in (0, 1) from 53 bits, never 0 or 1
double uniform(std::mt19937_64& engine) { return (static_cast<double>(engine() >> 11) + 0.5) * 0x1p-53; }

std::string format(const char* pattern, double a) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, pattern, a);
  return buffer;
}

}  // namespace

std::string p_value_text(double p, bool at_floor) {
  if (!std::isfinite(p)) return "not tested";
  return (at_floor ? "p <= " : "p = ") + format("%.3g", p);
}

int minimum_bootstrap(double significance) {
  // p = (1 + #exceeding) / (B + 1) >= 1 / (B + 1): below the significance only if B + 1 > 1 / significance
  return static_cast<int>(std::floor(1 / significance * (1 + 1e-12)));
}

void check_bootstrap_size(int bootstrap, double significance) {
  if (bootstrap < 0 || bootstrap > max_bootstrap)
    throw Error("assessment: bootstrap must be from 0 to " + std::to_string(max_bootstrap) + ", not " +
                std::to_string(bootstrap));
  if (bootstrap > 0 && bootstrap < minimum_bootstrap(significance))
    throw Error("a bootstrap of " + std::to_string(bootstrap) + " samples can never give p below " +
                format("%g", significance) + " (its smallest p-value is 1/(B + 1) = " +
                format("%.3g", 1.0 / (bootstrap + 1)) + "): use at least " +
                std::to_string(minimum_bootstrap(significance)) + " samples, or 0 for no test");
}

FitStatistics fit_statistics(const HeightDistribution& d, const std::vector<double>& sorted) {
  // each point's ln F, ln(1 - F) and F from one evaluation of the law (for a Weibull one power:
  // t = w^a gives ln(1 - F) = -t and ln F = ln(-expm1(-t)) on the tail side, and the reverse)
  const std::size_t n = sorted.size();
  const double nd = static_cast<double>(n);
  constexpr double floor = -745;  // a point far outside the fit adds a large but finite term
  double sum = 0, worst = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double x = sorted[i];
    double log_cdf, log_sf;
    if (d.model == HeightModel::gaussian) {
      log_cdf = d.log_cdf(x);
      log_sf = d.log_sf(x);
    } else {
      const double w = (d.model == HeightModel::weibull_tail ? x - d.location : d.location - x) / d.scale;
      const double t = w > 0 ? std::pow(w, d.shape) : 0;
      const double near = t > 0 ? std::log(-std::expm1(-t)) : -std::numeric_limits<double>::infinity();
      log_cdf = d.model == HeightModel::weibull_tail ? near : -t;
      log_sf = d.model == HeightModel::weibull_tail ? -t : near;
    }
    // point i is the i-th lowest (ln F) and the (n - 1 - i)-th highest (ln(1 - F))
    sum += static_cast<double>(2 * i + 1) * std::max(log_cdf, floor) +
           static_cast<double>(2 * (n - 1 - i) + 1) * std::max(log_sf, floor);
    const double f = std::exp(log_cdf);
    worst = std::max({worst, static_cast<double>(i + 1) / nd - f, f - static_cast<double>(i) / nd});
  }
  return {-nd - sum / nd, worst};
}

double anderson_darling(const HeightDistribution& d, const std::vector<double>& sorted) {
  return fit_statistics(d, sorted).anderson_darling;
}

double kolmogorov_smirnov(const HeightDistribution& d, const std::vector<double>& sorted) {
  return fit_statistics(d, sorted).kolmogorov_smirnov;
}

std::vector<double> draw_sample(const HeightDistribution& distribution, std::size_t n, std::uint64_t seed) {
  std::mt19937_64 engine(seed);
  std::vector<double> sample(n);
  for (double& x : sample) x = distribution.quantile(uniform(engine));
  return sample;
}

namespace {

// The model refitted on B samples of n drawn from its fit `fitted` (the i.i.d. parametric
// bootstrap), each from its own seed (seed, model, replicate): the same for every thread count.
std::vector<verdict::Refit> bootstrap_refits(HeightModel model, const HeightDistribution& fitted, std::size_t n,
                                             int bootstrap, std::uint64_t seed, int threads, const FitOptions& fit_options) {
  using verdict::splitmix64;
  std::vector<verdict::Refit> refits(static_cast<std::size_t>(std::max(bootstrap, 0)));
  detail::parallel_for(refits.size(), threads, [&](std::size_t b) {
    const std::uint64_t replicate_seed =
        splitmix64(splitmix64(seed) ^ splitmix64(static_cast<std::uint64_t>(model) * 1000003u + static_cast<std::uint64_t>(b)));
    std::vector<double> sample = draw_sample(fitted, n, replicate_seed);
    std::sort(sample.begin(), sample.end());
    refits[b] = verdict::refit(model, sample, fitted, fit_options);  // a failure is counted
  });
  return refits;
}

// The model fitted on `sorted`, bootstrapped and concluded (p-values, percentile intervals, the
// shape's identification): what both bootstrap_test and assess_sample report.
ModelAssessment bootstrapped(HeightModel model, const std::vector<double>& sorted, const AssessmentOptions& options,
                             std::vector<verdict::Refit>* refits_out = nullptr) {
  ModelAssessment m = verdict::observed(model, sorted, options.fit);
  const std::vector<verdict::Refit> refits =
      bootstrap_refits(model, m.fit.distribution, sorted.size(), options.bootstrap, options.seed, options.threads, options.fit);
  verdict::conclude(m, refits, options, verdict::ShapeInterval::percentile);
  if (refits_out) *refits_out = refits;
  return m;
}

}  // namespace

TestResult bootstrap_test(HeightModel model, const std::vector<double>& sorted, int bootstrap, std::uint64_t seed,
                          int threads, const FitOptions& fit_options) {
  AssessmentOptions options;
  options.bootstrap = bootstrap;
  options.seed = seed;
  options.threads = threads;
  options.fit = fit_options;
  std::vector<verdict::Refit> refits;
  const ModelAssessment m = bootstrapped(model, sorted, options, &refits);
  TestResult result;
  result.fit = m.fit;
  result.anderson_darling = m.anderson_darling;
  result.kolmogorov_smirnov = m.kolmogorov_smirnov;
  result.anderson_darling_p = m.anderson_darling_p;
  result.kolmogorov_smirnov_p = m.kolmogorov_smirnov_p;
  result.anderson_darling_p_at_floor = m.p_at_floor;
  result.kolmogorov_smirnov_p_at_floor = m.kolmogorov_smirnov_p_at_floor;
  result.failed_refits = m.failed_refits;
  for (const verdict::Refit& r : refits) {
    if (!r.ok) continue;
    result.refit_locations.push_back(r.location);
    result.refit_scales.push_back(r.scale);
    result.refit_shapes.push_back(r.shape);
  }
  return result;
}

void weigh_models(SampleAssessment& sample) {
  double best = std::numeric_limits<double>::infinity();
  for (const ModelAssessment& m : sample.models) best = std::min(best, m.aic);
  double sum = 0;
  for (ModelAssessment& m : sample.models) {
    m.delta_aic = m.aic - best;
    m.akaike_weight = std::exp(-0.5 * m.delta_aic);
    sum += m.akaike_weight;
  }
  for (ModelAssessment& m : sample.models) m.akaike_weight /= sum;
}

SampleAssessment assess_sample(const std::string& name, std::vector<double> values, const AssessmentOptions& options) {
  if (!(options.confidence > 0 && options.confidence < 1)) throw Error("assessment: confidence must be in (0, 1)");
  if (!(options.significance > 0 && options.significance < 1)) throw Error("assessment: significance must be in (0, 1)");
  check_bootstrap_size(options.bootstrap, options.significance);
  std::sort(values.begin(), values.end());
  SampleAssessment assessment;
  assessment.name = name;
  assessment.n = values.size();
  assessment.options = options;
  for (HeightModel model : all_height_models) assessment.models.push_back(bootstrapped(model, values, options));
  verdict::judge(assessment, verdict::NullSamples::bootstrap);
  return assessment;
}

}  // namespace asperity::topography
