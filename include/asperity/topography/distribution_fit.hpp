// The three candidate distributions of (summit) heights and their estimation.
//
//   gaussian         N(location, scale^2)                         (ML: sample mean and rms)
//   weibull_tail     x = location + scale W, W ~ phi_a            (GW's side: the tail up)
//   weibull_bounded  x = location - scale W                       (mirrored: bounded above,
//                                                                  worn and polished surfaces)
// with phi_a(w) = a w^(a-1) exp(-w^a) the unit Weibull density of docs/model.md (shape a).
//
// Estimator for the three-parameter Weibull: maximum product of spacings (MPS; Cheng & Amin
// 1983, Ranneby 1984). Maximum likelihood is ill-posed here: for a shape below 1 the likelihood
// grows without bound as the location approaches the smallest observation (and for 1 < a < 2 it
// is irregular). MPS maximizes the mean log spacing
//   S = 1/(n+1) sum_{i=1}^{n+1} ln(F(x_(i)) - F(x_(i-1))),   F(x_(0)) = 0, F(x_(n+1)) = 1,
// which is bounded for every shape (each spacing is a probability <= 1), so the estimate
// exists with the location strictly beyond the extreme observation; it is consistent, and as
// efficient as ML where ML is regular. Tied observations (quantized instruments) would give a
// zero spacing; for them the spacing is replaced by f(x) delta, the probability of the
// quantization step delta (the smallest positive gap in the data) around x (Cheng & Amin's
// remedy). The maximum is found by NLopt's BOBYQA in (ln gap, ln scale, ln shape) on
// standardized data, from several starting shapes; the shape is kept in [shape_min, shape_max].
#pragma once
#include <string>
#include <cstddef>
#include <vector>

#include "asperity/record_fields.hpp"

namespace asperity::topography {

enum class HeightModel { gaussian = 0, weibull_tail = 1, weibull_bounded = 2 };
inline constexpr HeightModel all_height_models[] = {HeightModel::gaussian, HeightModel::weibull_tail,
                                                    HeightModel::weibull_bounded};

const char* to_string(HeightModel model);        // "gaussian", "weibull-tail", "weibull-bounded"
// The inverse of to_string (its one spelling table); false for any other name
bool parse_height_model(const std::string& name, HeightModel& model) noexcept;
const char* describe(HeightModel model);         // "Gaussian", "Weibull, tail up (GW side)", ...
int parameter_count(HeightModel model);          // 2 or 3

// The functions never throw: parameters that are no distribution (a location or scale not
// finite, a scale <= 0, a Weibull shape not finite and > 0) give NaN for quantile, mean and
// standard_deviation; a mean or standard deviation beyond the largest double is +-inf.
// Its parameters, defined once (record_fields.hpp): report.json's models[] start with them
#define ASPERITY_HEIGHT_DISTRIBUTION_FIELDS(X)                                          \
  X(HeightModel, model, "model", "the height model")                                   \
  X(double, location, "location_m", "the location [m] (the Gaussian: its mean)")        \
  X(double, scale, "scale_m", "the scale [m] (the Gaussian: its standard deviation)", 1) \
  X(double, shape, "shape", "the Weibull shape a (the Gaussian: unused)")

struct HeightDistribution {
  ASPERITY_HEIGHT_DISTRIBUTION_FIELDS(ASPERITY_RECORD_MEMBER_INIT)

  double log_pdf(double x) const noexcept;
  double log_cdf(double x) const noexcept;     // ln P(X <= x)
  double log_sf(double x) const noexcept;      // ln P(X > x)
  double cdf(double x) const noexcept;
  double quantile(double p) const noexcept;    // p in (0, 1); NaN outside
  double mean() const noexcept;
  double standard_deviation() const noexcept;
};

struct FitOptions {
  double shape_min = 0.05, shape_max = 100;
  const HeightDistribution* start = nullptr;  // a known nearby solution (bootstrap refits): start there only
};

#define ASPERITY_FIT_RESULT_FIELDS(X)                                                                \
  X(HeightDistribution, distribution, nullptr, "the fitted distribution")                           \
  X(double, objective, nullptr,                                                                     \
    "maximum product of spacings: the mean log spacing S; Gaussian: the mean log-likelihood")       \
  X(bool, shape_at_bound, "shape_at_bound", "the shape hit shape_min or shape_max")                \
  X(int, evaluations, nullptr, "the objective's evaluations")

struct FitResult {
  ASPERITY_FIT_RESULT_FIELDS(ASPERITY_RECORD_MEMBER_INIT)
};

// `sorted` ascending, at least 5 finite values not all equal. Throws asperity::Error otherwise.
FitResult fit_height_distribution(HeightModel model, const std::vector<double>& sorted, const FitOptions& options = {});

// The MPS objective S (mean log spacing) of a distribution on sorted data (ties as above).
double mean_log_spacing(const HeightDistribution& distribution, const std::vector<double>& sorted);
double log_likelihood(const HeightDistribution& distribution, const std::vector<double>& data);

}  // namespace asperity::topography

namespace asperity {
ASPERITY_DEFINE_RECORD(topography::HeightDistribution, ASPERITY_HEIGHT_DISTRIBUTION_FIELDS)
ASPERITY_DEFINE_RECORD(topography::FitResult, ASPERITY_FIT_RESULT_FIELDS)
}  // namespace asperity
