#include "asperity/topography/distribution_fit.hpp"

#include <algorithm>
#include <boost/math/policies/policy.hpp>
#include <boost/math/special_functions/erf.hpp>
#include <boost/math/special_functions/gamma.hpp>
#include <cmath>
#include <iterator>
#include <limits>

#include "asperity/error.hpp"
#include "spacing_fit.hpp"

namespace asperity::topography {
namespace {
constexpr double inf = std::numeric_limits<double>::infinity();
constexpr double nan = std::numeric_limits<double>::quiet_NaN();
constexpr double log_sqrt_2pi = 0.91893853320467274178;

// Boost.Math reports a domain error, a pole or an overflow by exception unless told otherwise;
// the distribution's functions are noexcept and answer by value (NaN, +-inf) instead.
namespace policies = boost::math::policies;
using NoThrow =
    policies::policy<policies::domain_error<policies::ignore_error>, policies::pole_error<policies::ignore_error>,
                     policies::overflow_error<policies::ignore_error>, policies::evaluation_error<policies::ignore_error>,
                     policies::rounding_error<policies::ignore_error>>;

// ln Phi(z), accurate far into the lower tail
double log_normal_cdf(double z) noexcept {
  if (z > -30) return std::log(0.5 * boost::math::erfc(-z / std::sqrt(2.0), NoThrow()));
  // Mills ratio: Phi(z) ~ phi(z)/|z| (1 - 1/z^2 + 3/z^4)
  const double z2 = z * z;
  return -0.5 * z2 - log_sqrt_2pi - std::log(-z) + std::log1p(-1 / z2 + 3 / (z2 * z2));
}

// the Weibull variable t = w^a of an observation, w = (x - location)/scale (tail) or
// (location - x)/scale (bounded); 0 beyond the bound
double weibull_t(const HeightDistribution& d, double x) {
  const double w = (d.model == HeightModel::weibull_tail ? x - d.location : d.location - x) / d.scale;
  return w > 0 ? std::pow(w, d.shape) : 0;
}

// parameters of a distribution at all: a finite location, a finite positive scale, and for the
// Weibulls a finite positive shape
bool has_valid_parameters(const HeightDistribution& d) noexcept {
  const bool location_and_scale = std::isfinite(d.location) && std::isfinite(d.scale) && d.scale > 0;
  return d.model == HeightModel::gaussian ? location_and_scale
                                          : location_and_scale && std::isfinite(d.shape) && d.shape > 0;
}

// scale Gamma(x), x >= 1, finite wherever the product is (Gamma alone overflows beyond x ~ 171.6)
double scaled_gamma(double scale, double x) noexcept {
  const double gamma = boost::math::tgamma(x, NoThrow());
  if (std::isfinite(gamma)) return scale * gamma;
  return std::exp(std::log(scale) + boost::math::lgamma(x, NoThrow()));
}
}  // namespace

// The models' names, once, in HeightModel's order
constexpr const char* height_model_names[] = {"gaussian", "weibull-tail", "weibull-bounded"};

const char* to_string(HeightModel model) {
  const auto k = static_cast<std::size_t>(model);
  return k < std::size(height_model_names) ? height_model_names[k] : "?";
}

bool parse_height_model(const std::string& name, HeightModel& model) noexcept {
  for (HeightModel candidate : all_height_models)
    if (name == to_string(candidate)) {
      model = candidate;
      return true;
    }
  return false;
}

const char* describe(HeightModel model) {
  switch (model) {
    case HeightModel::gaussian: return "Gaussian";
    case HeightModel::weibull_tail: return "Weibull, tail up (GW side)";
    case HeightModel::weibull_bounded: return "Weibull mirrored, bounded above (worn side)";
  }
  return "?";
}

int parameter_count(HeightModel model) { return model == HeightModel::gaussian ? 2 : 3; }

double HeightDistribution::log_pdf(double x) const noexcept {
  if (model == HeightModel::gaussian) {
    const double z = (x - location) / scale;
    return -0.5 * z * z - log_sqrt_2pi - std::log(scale);
  }
  const double w = (model == HeightModel::weibull_tail ? x - location : location - x) / scale;
  if (!(w > 0)) return shape < 1 && w == 0 ? inf : -inf;
  return std::log(shape / scale) + (shape - 1) * std::log(w) - std::pow(w, shape);
}

double HeightDistribution::log_cdf(double x) const noexcept {
  if (model == HeightModel::gaussian) return log_normal_cdf((x - location) / scale);
  const double t = weibull_t(*this, x);
  if (model == HeightModel::weibull_tail) return t > 0 ? std::log(-std::expm1(-t)) : -inf;
  return (x >= location) ? 0 : -t;
}

double HeightDistribution::log_sf(double x) const noexcept {
  if (model == HeightModel::gaussian) return log_normal_cdf(-(x - location) / scale);
  const double t = weibull_t(*this, x);
  if (model == HeightModel::weibull_tail) return -t;
  return (x >= location || t == 0) ? -inf : std::log(-std::expm1(-t));
}

double HeightDistribution::cdf(double x) const noexcept { return std::exp(log_cdf(x)); }

double HeightDistribution::quantile(double p) const noexcept {
  if (!(p > 0 && p < 1) || !has_valid_parameters(*this)) return nan;
  if (model == HeightModel::gaussian)
    return location - scale * std::sqrt(2.0) * boost::math::erfc_inv(2 * p, NoThrow());
  if (model == HeightModel::weibull_tail) return location + scale * std::pow(-std::log1p(-p), 1 / shape);
  return location - scale * std::pow(-std::log(p), 1 / shape);  // P(X <= x) = exp(-t)
}

// Gamma(1 + 1/a) overflows for a shape a below ~0.0059, Gamma(1 + 2/a) below ~0.0117: the mean
// and the standard deviation then come from the logs, +inf only where they are beyond the
// largest double.
double HeightDistribution::mean() const noexcept {
  if (!has_valid_parameters(*this)) return nan;
  if (model == HeightModel::gaussian) return location;
  const double m = scaled_gamma(scale, 1 + 1 / shape);
  return model == HeightModel::weibull_tail ? location + m : location - m;
}

double HeightDistribution::standard_deviation() const noexcept {
  if (!has_valid_parameters(*this)) return nan;
  if (model == HeightModel::gaussian) return scale;
  const double g1 = boost::math::tgamma(1 + 1 / shape, NoThrow()), g2 = boost::math::tgamma(1 + 2 / shape, NoThrow());
  if (std::isfinite(g2) && std::isfinite(g1 * g1)) return scale * std::sqrt(std::max(0.0, g2 - g1 * g1));
  // sqrt(G2 - G1^2) = sqrt(G2) sqrt(1 - G1^2/G2), G1^2 <= G2 (log-convexity)
  const double l1 = boost::math::lgamma(1 + 1 / shape, NoThrow()), l2 = boost::math::lgamma(1 + 2 / shape, NoThrow());
  if (!std::isfinite(l2)) return inf;
  return std::exp(std::log(scale) + 0.5 * l2) * std::sqrt(-std::expm1(2 * l1 - l2));
}

namespace {

// The mean log spacing of a tail-up Weibull (location < y_1) on sorted data y; `delta` is the
// quantization step used for ties.
double weibull_spacing_objective(double location, double scale, double shape, const std::vector<double>& y,
                                 double log_delta) {
  const std::size_t n = y.size();
  double sum = 0, t_previous = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const double w = (y[k] - location) / scale;
    if (!(w > 0)) return -inf;
    const double t = std::pow(w, shape);
    if (t > t_previous) {
      // ln(exp(-t_prev) - exp(-t)) = -t_prev + ln(-expm1(-(t - t_prev)))
      sum += -t_previous + std::log(-std::expm1(-(t - t_previous)));
    } else {
      // a tie: f(y) delta
      sum += std::log(shape / scale) + (shape - 1) * std::log(w) - t + log_delta;
    }
    t_previous = t;
  }
  sum += -t_previous;  // the last spacing, 1 - F(y_n)
  return sum / static_cast<double>(n + 1);
}

double smallest_gap(const std::vector<double>& sorted) {
  double gap = inf;
  for (std::size_t k = 1; k < sorted.size(); ++k)
    if (sorted[k] > sorted[k - 1]) gap = std::min(gap, sorted[k] - sorted[k - 1]);
  return gap;
}

}  // namespace

double mean_log_spacing(const HeightDistribution& d, const std::vector<double>& sorted) {
  const double log_delta = std::log(smallest_gap(sorted));
  if (d.model == HeightModel::weibull_tail)
    return weibull_spacing_objective(d.location, d.scale, d.shape, sorted, log_delta);
  if (d.model == HeightModel::weibull_bounded) {
    std::vector<double> mirrored(sorted.rbegin(), sorted.rend());
    for (double& v : mirrored) v = -v;
    return weibull_spacing_objective(-d.location, d.scale, d.shape, mirrored, log_delta);
  }
  double sum = 0, previous = -inf;
  for (double x : sorted) {
    const double c = d.log_cdf(x);
    sum += x > previous ? c + std::log(-std::expm1(std::min(-1e-300, (previous == -inf ? -inf : d.log_cdf(previous)) - c)))
                        : d.log_pdf(x) + log_delta;
    previous = x;
  }
  return (sum + d.log_sf(sorted.back())) / static_cast<double>(sorted.size() + 1);
}

double log_likelihood(const HeightDistribution& distribution, const std::vector<double>& data) {
  double sum = 0;
  for (double x : data) sum += distribution.log_pdf(x);
  return sum;
}

FitResult fit_height_distribution(HeightModel model, const std::vector<double>& sorted, const FitOptions& options) {
  const std::size_t n = sorted.size();
  if (n < 5) throw Error("fit: fewer than 5 values");
  long double sum = 0;
  for (std::size_t k = 0; k < n; ++k) {
    if (!std::isfinite(sorted[k])) throw Error("fit: a value is not finite");
    if (k > 0 && sorted[k] < sorted[k - 1]) throw Error("fit: values not sorted");
    sum += sorted[k];
  }
  if (!(sorted.back() > sorted.front())) throw Error("fit: every value is the same");
  const double mean = static_cast<double>(sum / n);
  long double squares = 0;
  for (double x : sorted) squares += (x - mean) * (x - mean);
  const double sd = std::sqrt(static_cast<double>(squares / n));

  FitResult result;
  result.distribution.model = model;
  if (model == HeightModel::gaussian) {
    result.distribution.location = mean;
    result.distribution.scale = sd;
    result.distribution.shape = std::numeric_limits<double>::quiet_NaN();
    result.objective = log_likelihood(result.distribution, sorted) / static_cast<double>(n);
    return result;
  }

  // standardized data: y = (x - x_1)/sd (tail) or (x_n - x)/sd (bounded), ascending, y_1 = 0
  const bool bounded = model == HeightModel::weibull_bounded;
  const double origin = bounded ? sorted.back() : sorted.front();
  std::vector<double> y(n);
  for (std::size_t k = 0; k < n; ++k) y[k] = bounded ? (origin - sorted[n - 1 - k]) / sd : (sorted[k] - origin) / sd;
  const detail::SpacingProblem problem{&y, std::log(smallest_gap(y)), {}};
  const double lower[3] = {std::log(1e-12), std::log(1e-4), std::log(options.shape_min)};
  const double upper[3] = {std::log(1e3), std::log(1e4), std::log(options.shape_max)};

  std::vector<std::vector<double>> starts;
  if (options.start) {
    const HeightDistribution& s = *options.start;
    const double location = bounded ? (origin - s.location) / sd : (s.location - origin) / sd;  // < 0 when valid
    starts.push_back({std::log(std::max(-location, 1e-9)), std::log(s.scale / sd),
                      std::log(std::clamp(s.shape, options.shape_min, options.shape_max))});
  } else {
    // moment-matched starts (unit variance, data mean) at several shapes; the location at
    // least a little below the smallest value
    const double y_mean = (bounded ? origin - mean : mean - origin) / sd;
    for (double shape : {0.6, 1.0, 1.6, 2.5, 4.0, 8.0}) {
      if (shape < options.shape_min || shape > options.shape_max) continue;
      const double g1 = boost::math::tgamma(1 + 1 / shape), g2 = boost::math::tgamma(1 + 2 / shape);
      const double scale = 1 / std::sqrt(g2 - g1 * g1);
      const double gap = std::max(scale * g1 - y_mean, 0.05);
      starts.push_back({std::log(gap), std::log(scale), std::log(shape)});
    }
  }
  // a refit from a known nearby solution needs less precision than a reported estimate: the
  // ensemble's spread is far wider than 1e-6
  const detail::SpacingMaximum found =
      detail::maximize_spacing(problem, starts, lower, upper, options.start ? 1e-7 : 1e-10);
  const double best = found.objective;
  const std::vector<double> best_point(found.p, found.p + 3);
  if (best_point.empty() || !(best > -1e300)) throw Error("fit: the spacing objective has no finite maximum");
  const double gap = std::exp(best_point[0]);
  result.distribution.scale = std::exp(best_point[1]) * sd;
  result.distribution.shape = std::exp(best_point[2]);
  result.distribution.location = bounded ? origin + gap * sd : origin - gap * sd;
  result.objective = best;
  result.evaluations = found.evaluations;
  result.shape_at_bound = best_point[2] <= std::log(options.shape_min) + 1e-6 ||
                          best_point[2] >= std::log(options.shape_max) - 1e-6;
  return result;
}

}  // namespace asperity::topography
