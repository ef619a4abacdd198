#include "asperity/topography/goodness_of_fit.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include "asperity/detail/parallel_for.hpp"
#include "asperity/error.hpp"

namespace asperity::topography {
namespace {

std::uint64_t splitmix64(std::uint64_t x) {
  x += 0x9E3779B97F4A7C15ull;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
  return x ^ (x >> 31);
}

// a uniform in (0, 1) from 53 bits, never 0 or 1
double uniform(std::mt19937_64& engine) { return (static_cast<double>(engine() >> 11) + 0.5) * 0x1p-53; }

double percentile(std::vector<double> values, double q) {
  if (values.empty()) return std::numeric_limits<double>::quiet_NaN();
  std::sort(values.begin(), values.end());
  const double position = q * static_cast<double>(values.size() - 1);
  const std::size_t k = static_cast<std::size_t>(position);
  const double fraction = position - static_cast<double>(k);
  return k + 1 < values.size() ? values[k] * (1 - fraction) + values[k + 1] * fraction : values[k];
}

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

TestResult bootstrap_test(HeightModel model, const std::vector<double>& sorted, int bootstrap, std::uint64_t seed,
                          int threads, const FitOptions& fit_options) {
  TestResult result;
  result.fit = fit_height_distribution(model, sorted, fit_options);
  const HeightDistribution& fitted = result.fit.distribution;
  result.anderson_darling = anderson_darling(fitted, sorted);
  result.kolmogorov_smirnov = kolmogorov_smirnov(fitted, sorted);
  if (bootstrap <= 0) return result;

  struct Replicate {
    double a2 = 0, d = 0, location = 0, scale = 0, shape = 0;
    bool ok = false;
  };
  std::vector<Replicate> replicates(static_cast<std::size_t>(bootstrap));
  FitOptions refit_options = fit_options;
  refit_options.start = &fitted;
  detail::parallel_for(static_cast<std::size_t>(bootstrap), threads, [&](std::size_t index) {
    {
      const int b = static_cast<int>(index);
      const std::uint64_t replicate_seed =
          splitmix64(splitmix64(seed) ^ splitmix64(static_cast<std::uint64_t>(model) * 1000003u + static_cast<std::uint64_t>(b)));
      std::vector<double> sample = draw_sample(fitted, sorted.size(), replicate_seed);
      std::sort(sample.begin(), sample.end());
      Replicate& r = replicates[static_cast<std::size_t>(b)];
      try {
        const FitResult refit = fit_height_distribution(model, sample, refit_options);
        r.a2 = anderson_darling(refit.distribution, sample);
        r.d = kolmogorov_smirnov(refit.distribution, sample);
        r.location = refit.distribution.location;
        r.scale = refit.distribution.scale;
        r.shape = refit.distribution.shape;
        r.ok = true;
      } catch (const Error&) {
        r.ok = false;  // counted; a sample of identical values cannot happen from a continuous law
      }
    }
  });

  int exceed_a2 = 0, exceed_d = 0, ok = 0;
  for (const Replicate& r : replicates) {
    if (!r.ok) {
      ++result.failed_refits;
      continue;
    }
    ++ok;
    exceed_a2 += r.a2 >= result.anderson_darling ? 1 : 0;
    exceed_d += r.d >= result.kolmogorov_smirnov ? 1 : 0;
    result.refit_locations.push_back(r.location);
    result.refit_scales.push_back(r.scale);
    result.refit_shapes.push_back(r.shape);
  }
  result.anderson_darling_p = static_cast<double>(1 + exceed_a2) / (ok + 1);
  result.kolmogorov_smirnov_p = static_cast<double>(1 + exceed_d) / (ok + 1);
  result.anderson_darling_p_at_floor = ok > 0 && exceed_a2 == 0;
  result.kolmogorov_smirnov_p_at_floor = ok > 0 && exceed_d == 0;
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
  const double tail = 0.5 * (1 - options.confidence);
  for (HeightModel model : all_height_models) {
    const TestResult test = bootstrap_test(model, values, options.bootstrap, options.seed, options.threads, options.fit);
    ModelAssessment m;
    m.fit = test.fit;
    m.anderson_darling = test.anderson_darling;
    m.anderson_darling_p = test.anderson_darling_p;
    m.kolmogorov_smirnov = test.kolmogorov_smirnov;
    m.kolmogorov_smirnov_p = test.kolmogorov_smirnov_p;
    m.p_at_floor = options.bootstrap > 0 && test.anderson_darling_p_at_floor;
    m.kolmogorov_smirnov_p_at_floor = options.bootstrap > 0 && test.kolmogorov_smirnov_p_at_floor;
    m.log_likelihood = log_likelihood(test.fit.distribution, values);
    m.aic = 2 * parameter_count(model) - 2 * m.log_likelihood;
    m.bootstrap = options.bootstrap;
    m.failed_refits = test.failed_refits;
    m.location = {percentile(test.refit_locations, tail), percentile(test.refit_locations, 1 - tail)};
    m.scale = {percentile(test.refit_scales, tail), percentile(test.refit_scales, 1 - tail)};
    if (model != HeightModel::gaussian) m.shape = {percentile(test.refit_shapes, tail), percentile(test.refit_shapes, 1 - tail)};
    else m.shape = {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN()};
    m.rejected = options.bootstrap > 0 && m.anderson_darling_p < options.significance;
    assessment.models.push_back(m);
  }
  weigh_models(assessment);

  Verdict& v = assessment.verdict;
  const ModelAssessment& gaussian = assessment.model(HeightModel::gaussian);
  v.gaussian_rejected = gaussian.rejected;
  int best = -1;
  for (int k = 0; k < 3; ++k)
    if (!assessment.models[k].rejected && (best < 0 || assessment.models[k].aic < assessment.models[best].aic)) best = k;
  v.best_rejected = best < 0;
  if (best < 0)
    for (int k = 0; k < 3; ++k)
      if (best < 0 || assessment.models[k].aic < assessment.models[best].aic) best = k;
  v.best = static_cast<HeightModel>(best);
  const ModelAssessment& winner = assessment.models[best];
  v.aic_gain_over_gaussian = gaussian.aic - winner.aic;

  const int b = options.bootstrap;
  std::string text = name + " (n = " + std::to_string(values.size()) + "): ";
  if (b <= 0) {
    text += "not tested (no bootstrap samples, so no p-values: nothing is said about Gaussianity); by AIC alone "
            "the lowest is " + std::string(describe(v.best)) + ".";
  } else {
    text += v.gaussian_rejected ? "not Gaussian: Anderson-Darling rejects the Gaussian (" : "consistent with a Gaussian (Anderson-Darling ";
    text += p_value_text(gaussian.anderson_darling_p, gaussian.p_at_floor) + ", KS " +
            p_value_text(gaussian.kolmogorov_smirnov_p, gaussian.kolmogorov_smirnov_p_at_floor) + ", " +
            std::to_string(b) + " bootstrap samples). ";
    if (v.best_rejected) {
      text += "No model passes at the " + format("%.0f%%", 100 * options.significance) + " level; the least bad by AIC is " +
              describe(v.best);
    } else {
      text += std::string("Best fit (lowest AIC among the models not rejected): ") + describe(v.best);
    }
    if (v.best != HeightModel::gaussian)
      text += ", shape " + format("%.3g", winner.fit.distribution.shape) + " [" + format("%.3g", winner.shape.lo) + ", " +
              format("%.3g", winner.shape.hi) + "] (" + format("%.0f%%", 100 * options.confidence) + ")";
    text += " (Anderson-Darling " + p_value_text(winner.anderson_darling_p, winner.p_at_floor) + ")";
    if (v.best != HeightModel::gaussian) {
      text += "; its AIC is " + format("%.1f", v.aic_gain_over_gaussian) + " below the Gaussian's (Akaike weights " +
              format("%.3g", winner.akaike_weight) + " against " + format("%.3g", gaussian.akaike_weight) + ")";
    }
    text += ".";
  }
  v.text = text;
  return assessment;
}

}  // namespace asperity::topography
