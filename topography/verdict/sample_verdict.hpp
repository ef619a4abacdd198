// The one path from a sample's null refits to its verdict, shared by the two ways the null
// samples are drawn: an i.i.d. parametric bootstrap (assess_sample, goodness_of_fit.hpp) and
// surrogate surfaces of the map's spectrum (test_surface, surface_tests.hpp). Each model is
// fitted on the sample (observed), refitted on each null sample (refit), its p-values, intervals
// and shape identification concluded from the refits (conclude), and the sample judged (judge:
// the Akaike weights, the best model and the verdict's words). Only the null samples differ.
#pragma once
#include <cstdint>
#include <limits>
#include <vector>

#include "asperity/topography/goodness_of_fit.hpp"

namespace asperity::topography::verdict {

inline constexpr double nan = std::numeric_limits<double>::quiet_NaN();
// The step in ln shape over which the heights' bias slope is measured: the surrogate fields are
// refitted at a_hat and at a_hat e^-bias_step (ShapeInterval::bias_corrected).
inline constexpr double bias_step = 0.1;

std::uint64_t splitmix64(std::uint64_t x);
// linear interpolation between order statistics; NaN for none
double percentile(std::vector<double> values, double q);

// One model refitted on one null sample.
struct Refit {
  double a2 = nan, d = nan, shape = nan, location = nan, scale = nan;
  bool ok = false, at_bound = false;
};
// The model refitted on `sorted`, started from `start` (the fit on the measured sample); not ok
// where the fit refuses the sample.
Refit refit(HeightModel model, const std::vector<double>& sorted, const HeightDistribution& start,
            const FitOptions& options);

// The model fitted on the measured sample: its statistics and AIC; p-values and intervals NaN
// until concluded.
ModelAssessment observed(HeightModel model, const std::vector<double>& sorted, const FitOptions& options);

// How a Weibull's shape interval is made from the refitted shapes (goodness_of_fit.hpp: the
// enum, and interval_method, its words in every output, defined beside conclude).
using topography::ShapeInterval;

// p-values, intervals and identification of one model from its refits, the intervals made as
// `interval` says (recorded in m.shape_interval). `stepped`: the refits of the same null fields at
// the shape a_hat e^-bias_step (bias_corrected only).
void conclude(ModelAssessment& m, const std::vector<Refit>& refits, const AssessmentOptions& options,
              ShapeInterval interval, const std::vector<Refit>* stepped = nullptr);

// Where a sample's null samples came from, for the verdict's words.
enum class NullSamples { bootstrap, surrogate_surfaces };

// The Akaike weights, the best model (the lowest AIC among the models neither rejected nor of an
// unidentified shape; when there is none, the lowest AIC of all, best_rejected) and the verdict in
// words, the same for both kinds of null samples.
void judge(SampleAssessment& sample, NullSamples null_samples);

}  // namespace asperity::topography::verdict
