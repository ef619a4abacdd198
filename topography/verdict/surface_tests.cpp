#include "asperity/topography/surface_tests.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <mutex>
#include <random>

#include "asperity/detail/parallel_for.hpp"
#include "asperity/error.hpp"
#include "asperity/topography/leveling.hpp"
#include "asperity/topography/surrogates.hpp"
#include "statistics/plane_fit.hpp"

namespace asperity::topography {
namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();
// The step in ln shape over which the heights' bias slope is measured, and the least
// d(estimate)/d(shape) (1 + the slope) with which an interval is given.
constexpr double bias_step = 0.1;
constexpr double min_sensitivity = 0.25;
FitOptions bounds_of_fit() { return FitOptions{}; }

std::uint64_t splitmix64(std::uint64_t x) {
  x += 0x9E3779B97F4A7C15ull;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
  return x ^ (x >> 31);
}

// ln Phi(z), accurate far into both tails
double log_normal_cdf(double z) {
  if (z > -30) return std::log(normal_cdf(z));
  const double z2 = z * z;
  return -0.5 * z2 - 0.91893853320467274178 - std::log(-z) + std::log1p(-1 / z2 + 3 / (z2 * z2));
}

// k of n indices, a reproducible random choice (partial Fisher-Yates), in ascending order
std::vector<std::size_t> choose(std::size_t n, std::size_t k, std::uint64_t seed) {
  std::vector<std::size_t> all(n);
  for (std::size_t i = 0; i < n; ++i) all[i] = i;
  if (k >= n) return all;
  std::mt19937_64 engine(seed);
  for (std::size_t i = 0; i < k; ++i) std::swap(all[i], all[i + static_cast<std::size_t>(engine() % (n - i))]);
  all.resize(k);
  std::sort(all.begin(), all.end());
  return all;
}

double percentile(std::vector<double> values, double q) {
  if (values.empty()) return nan;
  std::sort(values.begin(), values.end());
  const double position = q * static_cast<double>(values.size() - 1);
  const std::size_t k = static_cast<std::size_t>(position);
  const double fraction = position - static_cast<double>(k);
  return k + 1 < values.size() ? values[k] * (1 - fraction) + values[k + 1] * fraction : values[k];
}

// F^-1(Phi(g)) tabulated on a fine grid of g and interpolated linearly (within ~1e-7 of the
// scale; direct beyond the table): the Weibull surrogate of a whole surface.
class MarginalTable {
 public:
  explicit MarginalTable(const HeightDistribution& marginal) : marginal_(marginal) {
    values_.resize(points);
    for (std::size_t k = 0; k < points; ++k) values_[k] = surrogate_height(marginal, lo + step * static_cast<double>(k));
  }
  double at(double g) const noexcept {
    const double position = (g - lo) / step;
    if (!(position >= 0 && position < static_cast<double>(points - 1)))
      return std::isnan(g) ? g : surrogate_height(marginal_, g);
    const std::size_t i = static_cast<std::size_t>(position);
    const double f = position - static_cast<double>(i);
    return values_[i] + f * (values_[i + 1] - values_[i]);
  }

 private:
  static constexpr std::size_t points = 16385;
  static constexpr double lo = -8, step = 16.0 / (points - 1);
  HeightDistribution marginal_;
  std::vector<double> values_;
};

// One model refitted on one surrogate sample.
struct Refit {
  double a2 = nan, d = nan, shape = nan, location = nan, scale = nan;
  bool ok = false, at_bound = false;
};

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

// p-values, intervals and identification of one model from its refits.
void conclude(ModelAssessment& m, const std::vector<Refit>& refits, const AssessmentOptions& options,
              const std::vector<Refit>* stepped) {
  const bool centred_on_estimate = stepped == nullptr;
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
  if (centred_on_estimate) {
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
      m.shape = {bounds_of_fit().shape_min, bounds_of_fit().shape_max};
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

std::string p_text(const ModelAssessment& m) { return p_value_text(m.anderson_darling_p, m.p_at_floor); }

// The sample's own verdict, in words (the surface's verdict combines the two samples).
void judge(SampleAssessment& sample, const AssessmentOptions& options) {
  Verdict& v = sample.verdict;
  const ModelAssessment& gaussian = sample.model(HeightModel::gaussian);
  v.gaussian_rejected = gaussian.rejected;
  int best = -1;
  for (int k = 0; k < 3; ++k) {
    const ModelAssessment& m = sample.models[static_cast<std::size_t>(k)];
    if (m.rejected || !m.shape_identified) continue;
    if (best < 0 || m.aic < sample.models[static_cast<std::size_t>(best)].aic) best = k;
  }
  v.best_rejected = best < 0;
  if (best < 0) best = 0;
  v.best = static_cast<HeightModel>(best);
  v.aic_gain_over_gaussian = gaussian.aic - sample.models[static_cast<std::size_t>(best)].aic;
  std::string text = sample.name + " (n = " + std::to_string(sample.n) + "): ";
  if (options.bootstrap <= 0) {
    text += "not tested (no surrogates, so no p-values: nothing is said about Gaussianity).";
    v.text = text;
    return;
  }
  text += std::string(v.gaussian_rejected ? "not Gaussian" : "consistent with a Gaussian surface") +
          " (Anderson-Darling " + p_text(gaussian) + " against " + std::to_string(options.bootstrap) +
          " surrogate surfaces of the map's spectrum). ";
  for (HeightModel model : {HeightModel::weibull_tail, HeightModel::weibull_bounded}) {
    const ModelAssessment& m = sample.model(model);
    char shape[160];
    if (m.shape_identified)
      std::snprintf(shape, sizeof shape, "shape %.3g [%.3g, %.3g]", m.fit.distribution.shape, m.shape.lo, m.shape.hi);
    else
      std::snprintf(shape, sizeof shape, "shape %s", m.identification.c_str());
    text += std::string(describe(model)) + ": " + shape + ", " + (m.rejected ? "rejected" : "not rejected") + " (" +
            p_text(m) + "). ";
  }
  char weights[160];
  std::snprintf(weights, sizeof weights, "Akaike weights: Gaussian %.2g, tail up %.2g, mirrored %.2g.",
                sample.models[0].akaike_weight, sample.models[1].akaike_weight, sample.models[2].akaike_weight);
  text += weights;
  v.text = text;
}

}  // namespace

double surrogate_height(const HeightDistribution& marginal, double g) noexcept {
  switch (marginal.model) {
    case HeightModel::gaussian: return marginal.location + marginal.scale * g;
    case HeightModel::weibull_tail:  // W = (-ln(1 - Phi(g)))^(1/a) = (-ln Phi(-g))^(1/a)
      return marginal.location + marginal.scale * std::pow(-log_normal_cdf(-g), 1 / marginal.shape);
    case HeightModel::weibull_bounded:  // bounded above: x = location - scale (-ln Phi(g))^(1/a)
      return marginal.location - marginal.scale * std::pow(-log_normal_cdf(g), 1 / marginal.shape);
  }
  return nan;
}

SurfaceTests test_surface(const HeightMap& map, const std::vector<double>& summit_heights,
                          const CorrelationLengths& lengths, const SurfaceTestOptions& options,
                          const EnsembleProgress& progress) {
  const AssessmentOptions& a = options.assessment;
  if (!(a.confidence > 0 && a.confidence < 1)) throw Error("assessment: confidence must be in (0, 1)");
  if (!(a.significance > 0 && a.significance < 1)) throw Error("assessment: significance must be in (0, 1)");
  check_bootstrap_size(a.bootstrap, a.significance);
  SurfaceTests tests;
  tests.surrogates = static_cast<std::size_t>(a.bootstrap);

  // the samples: a fixed random set of valid positions, and the summit heights
  std::vector<std::size_t> valid;
  for (std::size_t k = 0; k < map.heights.size(); ++k)
    if (!std::isnan(map.heights[k])) valid.push_back(k);
  for (std::size_t k : choose(valid.size(), options.height_sample, splitmix64(a.seed ^ 0x4e16475ull)))
    tests.height_positions.push_back(valid[k]);
  std::vector<double> heights;
  for (std::size_t k : tests.height_positions) heights.push_back(map.heights[k]);
  std::sort(heights.begin(), heights.end());
  std::vector<double> summits = summit_heights;
  std::sort(summits.begin(), summits.end());
  if (heights.size() < 5 || summits.size() < 5) throw Error(map.source + ": too few heights or summits to test");

  SampleAssessment& H = tests.heights;
  SampleAssessment& S = tests.summit_heights;
  H.name = "heights (a random sample of " + std::to_string(heights.size()) + " points)";
  S.name = "summit heights";
  H.n = heights.size();
  S.n = summits.size();
  H.options = S.options = a;
  for (HeightModel model : all_height_models) {
    H.models.push_back(observed(model, heights, a.fit));
    S.models.push_back(observed(model, summits, a.fit));
  }

  if (a.bootstrap > 0) {
    const SurrogateFields fields(map, lengths, options.leveled, a.threads);
    tests.padded_nx = fields.padded_nx();
    tests.padded_ny = fields.padded_ny();
    const std::size_t B = static_cast<std::size_t>(a.bootstrap);
    // each Weibull marginal as a table in g: a surface's worth of transforms at a few ns each
    std::vector<MarginalTable> tables;
    for (int m = 0; m < 3; ++m) tables.emplace_back(H.models[static_cast<std::size_t>(m)].fit.distribution);
    // The heights' Weibull intervals correct the estimator's bias for its change with the shape:
    // the same surrogate fields (common random numbers) also mapped to the marginal of shape
    // a_hat e^-bias_step and refitted, so the bias is known at two shapes (see conclude).
    std::vector<HeightDistribution> stepped(3);
    for (int m = 1; m < 3; ++m) {
      stepped[static_cast<std::size_t>(m)] = H.models[static_cast<std::size_t>(m)].fit.distribution;
      stepped[static_cast<std::size_t>(m)].shape *= std::exp(-bias_step);
      tables.emplace_back(stepped[static_cast<std::size_t>(m)]);  // tables[2 + m]
    }
    // refits[b][sample * 3 + model]; [6 + model]: the heights at the stepped shape
    std::vector<std::array<Refit, 9>> refits(B);
    std::mutex progress_mutex;
    std::size_t done = 0;
    asperity::detail::parallel_for(B, a.threads, [&](std::size_t b) {
      std::vector<double> g;
      fields.generate(a.seed, b, g);
      HeightMap surface;
      surface.nx = map.nx;
      surface.ny = map.ny;
      surface.dx = map.dx;
      surface.dy = map.dy;
      surface.source = "surrogate";
      // the Gaussian surface (its scale, so that a height threshold in metres means the same),
      // leveled as the map was: its summits are every model's (a monotone map keeps them; the
      // leveling of the others moves them by far less than a point)
      const HeightDistribution& gaussian_marginal = H.models[0].fit.distribution;
      surface.heights.resize(g.size());
      for (std::size_t k = 0; k < g.size(); ++k) surface.heights[k] = surrogate_height(gaussian_marginal, g[k]);
      if (options.leveled) subtract_plane(surface, fit_plane(surface));
      const Summits found = find_summits(surface, options.summits);
      if (options.on_surrogate) options.on_surrogate(b, found);
      std::vector<std::size_t> summit_points;
      for (std::size_t k : choose(found.list.size(), options.max_summits, splitmix64(a.seed ^ (0x5u + b * 7919u))))
        summit_points.push_back(found.list[k].j * map.nx + found.list[k].i);
      std::vector<double> x_heights(tests.height_positions.size()), x_summits(summit_points.size());
      // A Weibull model's surface, F^-1(Phi(g)), leveled as the map was (leveling a skewed surface
      // changes its marginal: left out, the heights' shape intervals missed the truth in half the
      // maps): its plane fitted over every point, the surface itself evaluated only at the samples.
      const auto sample = [&](const auto& height, const Plane& plane, const std::vector<std::size_t>& points,
                              std::vector<double>& out) {
        for (std::size_t k = 0; k < out.size(); ++k)
          out[k] = height(points[k]) - plane_height(plane, map, points[k] % map.nx, points[k] / map.nx);
        std::sort(out.begin(), out.end());
      };
      const auto leveled_plane = [&](const auto& height) {
        return options.leveled ? detail::fit_plane_of(map, "surrogate", height) : Plane{};
      };
      const auto gaussian_height = [&](std::size_t k) { return surface.heights[k]; };  // leveled already
      for (int m = 0; m < 3; ++m) {
        const HeightModel model = all_height_models[m];
        const HeightDistribution& marginal = H.models[static_cast<std::size_t>(m)].fit.distribution;
        const MarginalTable& table = tables[static_cast<std::size_t>(m)];
        const auto weibull_height = [&](std::size_t k) { return table.at(g[k]); };
        if (model == HeightModel::gaussian) {
          sample(gaussian_height, Plane{}, tests.height_positions, x_heights);
          sample(gaussian_height, Plane{}, summit_points, x_summits);
        } else {
          const Plane plane = leveled_plane(weibull_height);
          sample(weibull_height, plane, tests.height_positions, x_heights);
          sample(weibull_height, plane, summit_points, x_summits);
        }
        if (options.test_heights) refits[b][static_cast<std::size_t>(m)] = refit(model, x_heights, marginal, a.fit);
        if (x_summits.size() >= 5)
          refits[b][static_cast<std::size_t>(3 + m)] =
              refit(model, x_summits, S.models[static_cast<std::size_t>(m)].fit.distribution, a.fit);
        if (options.test_heights && model != HeightModel::gaussian) {  // the same field at the stepped shape
          const MarginalTable& stepped_table = tables[static_cast<std::size_t>(2 + m)];
          const auto stepped_height = [&](std::size_t k) { return stepped_table.at(g[k]); };
          sample(stepped_height, leveled_plane(stepped_height), tests.height_positions, x_heights);
          refits[b][static_cast<std::size_t>(6 + m)] = refit(model, x_heights, stepped[static_cast<std::size_t>(m)], a.fit);
        }
      }
      if (progress) {
        std::lock_guard<std::mutex> lock(progress_mutex);
        progress(++done, B);
      }
    });
    for (int m = 0; m < 3; ++m) {
      std::vector<Refit> of_heights, of_summits, of_stepped;
      for (const auto& r : refits) {
        of_heights.push_back(r[static_cast<std::size_t>(m)]);
        of_summits.push_back(r[static_cast<std::size_t>(3 + m)]);
        if (m > 0) of_stepped.push_back(r[static_cast<std::size_t>(6 + m)]);
      }
      if (options.test_heights) conclude(H.models[static_cast<std::size_t>(m)], of_heights, a, &of_stepped);
      conclude(S.models[static_cast<std::size_t>(m)], of_summits, a, nullptr);
    }
  }
  for (SampleAssessment* sample : {&H, &S}) {
    weigh_models(*sample);
    judge(*sample, a);
  }
  return tests;
}

}  // namespace asperity::topography
