#include "sample_verdict.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "asperity/error.hpp"
#include "asperity/number_text.hpp"

namespace asperity::topography::verdict {
namespace {

// The least d(estimate)/d(shape) (1 + the bias slope) with which a bias-corrected interval is given.
constexpr double min_sensitivity = 0.25;

std::string p_text(const ModelAssessment& m) { return p_value_text(m.anderson_darling_p, m.p_at_floor); }

}  // namespace

std::uint64_t splitmix64(std::uint64_t x) {
  x += 0x9E3779B97F4A7C15ull;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
  return x ^ (x >> 31);
}

double percentile(std::vector<double> values, double q) {
  if (values.empty()) return nan;
  std::sort(values.begin(), values.end());
  const double position = q * static_cast<double>(values.size() - 1);
  const std::size_t k = static_cast<std::size_t>(position);
  const double fraction = position - static_cast<double>(k);
  return k + 1 < values.size() ? values[k] * (1 - fraction) + values[k + 1] * fraction : values[k];
}

Refit refit(HeightModel model, const std::vector<double>& sorted, const HeightDistribution& start,
            const FitOptions& options) {
  Refit r;
  try {
    FitOptions warm = options;
    warm.start = &start;
    const FitResult fit = fit_height_distribution(model, sorted, warm);
    const FitStatistics statistics = fit_statistics(fit.distribution, sorted);
    r.a2 = statistics.anderson_darling;
    r.d = statistics.kolmogorov_smirnov;
    r.shape = fit.distribution.shape;
    r.location = fit.distribution.location;
    r.scale = fit.distribution.scale;
    r.at_bound = fit.shape_at_bound;
    r.ok = std::isfinite(r.a2);
  } catch (const Error&) {
  }
  return r;
}

ModelAssessment observed(HeightModel model, const std::vector<double>& sorted, const FitOptions& options) {
  ModelAssessment m;
  m.fit = fit_height_distribution(model, sorted, options);
  m.anderson_darling = anderson_darling(m.fit.distribution, sorted);
  m.kolmogorov_smirnov = kolmogorov_smirnov(m.fit.distribution, sorted);
  m.log_likelihood = log_likelihood(m.fit.distribution, sorted);
  m.aic = 2 * parameter_count(model) - 2 * m.log_likelihood;
  m.shape = m.location = m.scale = {nan, nan};
  m.anderson_darling_p = m.kolmogorov_smirnov_p = nan;
  return m;
}

void conclude(ModelAssessment& m, const std::vector<Refit>& refits, const AssessmentOptions& options,
              ShapeInterval interval, const std::vector<Refit>* stepped) {
  int exceed_a2 = 0, exceed_d = 0, ok = 0, at_bound = 0;
  std::vector<double> shapes, locations, scales;
  for (const Refit& r : refits) {
    if (!r.ok) {
      ++m.failed_refits;
      continue;
    }
    ++ok;
    exceed_a2 += r.a2 >= m.anderson_darling ? 1 : 0;
    exceed_d += r.d >= m.kolmogorov_smirnov ? 1 : 0;
    at_bound += r.at_bound ? 1 : 0;
    shapes.push_back(r.shape);
    locations.push_back(r.location);
    scales.push_back(r.scale);
  }
  m.bootstrap = static_cast<int>(refits.size());
  if (ok == 0) return;
  m.shape_interval = interval;  // what the outputs say of these intervals (interval_method)
  m.anderson_darling_p = static_cast<double>(1 + exceed_a2) / (ok + 1);
  m.kolmogorov_smirnov_p = static_cast<double>(1 + exceed_d) / (ok + 1);
  m.p_at_floor = exceed_a2 == 0;
  m.kolmogorov_smirnov_p_at_floor = exceed_d == 0;
  m.rejected = m.anderson_darling_p < options.significance;
  const double tail = 0.5 * (1 - options.confidence);
  const HeightModel model = m.fit.distribution.model;
  m.location = {percentile(locations, tail), percentile(locations, 1 - tail)};
  m.scale = {percentile(scales, tail), percentile(scales, 1 - tail)};
  if (model == HeightModel::gaussian) return;
  const double lo = percentile(shapes, tail), hi = percentile(shapes, 1 - tail);
  const double a = m.fit.distribution.shape;
  if (interval == ShapeInterval::percentile || interval == ShapeInterval::none) {
    m.shape_interval = ShapeInterval::percentile;
    m.shape = {lo, hi};
  } else if (interval == ShapeInterval::centred_on_estimate) {
    // the spread of the refits around their own centre, carried to the estimate (in ln shape)
    const double median = percentile(shapes, 0.5);
    m.shape = {a * median / hi, a * median / lo};
  } else {
    // The basic bootstrap interval in ln shape corrected for a bias that changes with the shape.
    // The surrogates are drawn at the estimate, so their refits' offset b0 = ln median - ln a_hat
    // is the estimator's own bias there (leveling moves a skewed marginal's shape). The basic
    // interval, ln a_hat - b0 - e (e the refits' centred quantiles), assumes that bias the same
    // at the true shape; it is not (at a = 1.5 it falls as the shape grows: the maps whose
    // estimate erred most up showed the least bias, and the basic interval held the truth in 86%
    // of maps). So the bias is also measured at ln a_hat - bias_step on the same surrogate fields
    // (common random numbers: the difference is nearly free of their noise), b linear in ln a
    // between, beta its slope, and ln a_hat = ln a + b(ln a) + e solved for ln a:
    //   ln a = ln a_hat - (b0 + e) / (1 + beta).
    const double b0 = std::log(percentile(shapes, 0.5) / a);
    std::vector<double> stepped_shapes;
    if (stepped)
      for (const Refit& r : *stepped)
        if (r.ok) stepped_shapes.push_back(r.shape);
    double beta = 0;
    if (stepped_shapes.size() * 2 >= shapes.size()) {
      const double a1 = a * std::exp(-bias_step);
      const double b1 = std::log(percentile(stepped_shapes, 0.5) / a1);
      beta = (b1 - b0) / -bias_step;
    }
    m.bias_slope = beta;
    if (!(1 + beta >= min_sensitivity)) {
      // the estimate hardly follows the shape: no interval is honest
      m.shape = {FitOptions{}.shape_min, FitOptions{}.shape_max};
    } else {
      const double e_lo = std::log(lo / a) - b0, e_hi = std::log(hi / a) - b0;
      m.shape = {a * std::exp(-(b0 + e_hi) / (1 + beta)), a * std::exp(-(b0 + e_lo) / (1 + beta))};
    }
  }
  const FitOptions bounds;
  const bool interval_at_bound = m.shape.lo <= bounds.shape_min * 1.01 || m.shape.hi >= bounds.shape_max / 1.01;
  const bool refits_at_bound = at_bound * 10 > ok;
  if (m.fit.shape_at_bound || interval_at_bound || refits_at_bound) {
    m.shape_identified = false;
    char text[200];
    std::snprintf(text, sizeof text,
                  "not identified: %s (the fit keeps the shape within [%g, %g])",
                  m.fit.shape_at_bound ? "the estimate is at a bound"
                  : interval_at_bound  ? "its interval reaches a bound"
                                       : "over a tenth of the ensemble's refits end at a bound",
                  bounds.shape_min, bounds.shape_max);
    m.identification = text;
  }
}

void judge(SampleAssessment& sample, NullSamples null_samples) {
  weigh_models(sample);
  const AssessmentOptions& options = sample.options;
  Verdict& v = sample.verdict;
  const ModelAssessment& gaussian = sample.model(HeightModel::gaussian);
  v.gaussian_rejected = gaussian.rejected;
  const auto lower_aic = [&](int best, int k) {
    return best < 0 || sample.models[static_cast<std::size_t>(k)].aic < sample.models[static_cast<std::size_t>(best)].aic;
  };
  int best = -1;
  for (int k = 0; k < 3; ++k) {
    const ModelAssessment& m = sample.models[static_cast<std::size_t>(k)];
    if (!m.rejected && m.shape_identified && lower_aic(best, k)) best = k;
  }
  v.best_rejected = best < 0;
  if (best < 0)
    for (int k = 0; k < 3; ++k)
      if (lower_aic(best, k)) best = k;
  v.best = static_cast<HeightModel>(best);
  const ModelAssessment& winner = sample.models[static_cast<std::size_t>(best)];
  v.aic_gain_over_gaussian = gaussian.aic - winner.aic;

  const std::string null_name =
      null_samples == NullSamples::bootstrap ? "bootstrap samples of the fitted law" : "surrogate surfaces of the map's spectrum";
  std::string text = sample.name + " (n = " + std::to_string(sample.n) + "): ";
  if (options.bootstrap <= 0) {
    v.text = text + "not tested (no " + null_name + ", so no p-values: nothing is said about Gaussianity); by AIC alone " +
             "the lowest is " + describe(v.best) + ".";
    return;
  }
  text += std::string(v.gaussian_rejected ? "not Gaussian" : "consistent with a Gaussian") + " (Anderson-Darling " +
          p_text(gaussian) + ", Kolmogorov-Smirnov " +
          p_value_text(gaussian.kolmogorov_smirnov_p, gaussian.kolmogorov_smirnov_p_at_floor) + ", against " +
          std::to_string(options.bootstrap) + " " + null_name + "). ";
  for (HeightModel model : {HeightModel::weibull_tail, HeightModel::weibull_bounded}) {
    const ModelAssessment& m = sample.model(model);
    const std::string shape = m.shape_identified ? "shape " + three_digits(m.fit.distribution.shape) + " [" +
                                                       three_digits(m.shape.lo) + ", " + three_digits(m.shape.hi) + "]"
                                                 : "shape " + m.identification;
    text += std::string(describe(model)) + ": " + shape + ", " + (m.rejected ? "rejected" : "not rejected") + " (" +
            p_text(m) + "). ";
  }
  if (v.best_rejected)
    text += "No model is both not rejected at the " + three_digits(100 * options.significance) +
            "% level and of an identified shape; the lowest AIC is " + describe(v.best) + ". ";
  else
    text += std::string("Best fit (the lowest AIC among the models not rejected, of an identified shape): ") + describe(v.best) + ". ";
  text += "Akaike weights: Gaussian " + three_digits(sample.models[0].akaike_weight) + ", tail up " +
          three_digits(sample.models[1].akaike_weight) + ", mirrored " + three_digits(sample.models[2].akaike_weight) + ".";
  v.text = text;
}

}  // namespace asperity::topography::verdict

namespace asperity::topography {

const char* to_string(ShapeInterval interval) {
  switch (interval) {
    case ShapeInterval::none: return "none";
    case ShapeInterval::percentile: return "percentile";
    case ShapeInterval::centred_on_estimate: return "centred-on-estimate";
    case ShapeInterval::bias_corrected: return "bias-corrected";
  }
  return "?";
}

// The words of each branch of verdict::conclude above: kept beside it, read by every output.
std::string interval_method(ShapeInterval interval) {
  const std::string refits = "location and scale: percentile intervals of the refits; shape: ";
  switch (interval) {
    case ShapeInterval::none: return "none: no refits (no ensemble), so no intervals";
    case ShapeInterval::percentile: return refits + "percentile interval of the refitted shapes (refits drawn at the estimate)";
    case ShapeInterval::centred_on_estimate:
      return refits + "the refitted shapes' spread about their median carried to the estimate, in ln shape "
                      "(a m / q_hi to a m / q_lo)";
    case ShapeInterval::bias_corrected: {
      char text[400];
      std::snprintf(text, sizeof text,
                    "the basic interval in ln shape corrected for a bias that changes with the shape: the bias "
                    "measured on the same surrogate fields at the estimate and at the estimate times e^-%g, its "
                    "slope beta, ln a = ln a_hat - (b0 + e) / (1 + beta); not identified where 1 + beta < %g",
                    verdict::bias_step, verdict::min_sensitivity);
      return refits + text;
    }
  }
  return "?";
}

}  // namespace asperity::topography
