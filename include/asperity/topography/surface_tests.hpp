// Is this surface Gaussian, and which Weibull? Tests that carry the surface's correlation
// (docs/surfaces.md, section 4).
//
// Each height model M (Gaussian, Weibull tail up, Weibull mirrored) is a null hypothesis about
// the whole surface: "a Gaussian random field with the measured map's spectrum, whose heights
// have M's marginal (fitted to the map's heights)". Its null distributions come from B
// surrogate surfaces of that kind (surrogates.hpp): on each, the same statistics are computed
// exactly as on the measurement, so whatever correlation the surface carries (neighbouring
// summits share the long wavelengths) is in the null distribution too.
//
// Two samples, each with its own tests:
//   heights          a fixed random set of the map's valid points (AnalysisOptions::
//                    max_height_sample), the same positions on every surrogate: the marginal;
//   summit heights   every summit (up to max_fit_sample), found on each surrogate as on the
//                    map: what the GW integrals integrate. A summit height threshold (min_drop,
//                    in metres) is applied on the Gaussian surrogate mu + sigma g for every model.
// For each sample and model: the fit (ML for the Gaussian, MPS for the Weibulls), its
// Anderson-Darling A^2 and Kolmogorov-Smirnov D, and p = (1 + #{T_b >= T}) / (B + 1) with T_b
// the statistic of the model refitted on surrogate b; for the Weibulls the shape's interval
// from the refitted shapes: for the heights the basic bootstrap interval in ln a corrected for
// a bias that changes with the shape: the surrogates are drawn at the fitted shape, so the
// refits' offset b0 = ln median - ln a_hat is the estimator's own bias there (leveling's
// included); the same fields mapped to shape a_hat e^-0.1 and refitted give the bias there too
// (common random numbers), hence its slope beta in ln a, and
// ln a = ln a_hat - (b0 + e) / (1 + beta) over the refits' centred quantiles e (beta = 0: the
// basic interval a_hat^2 / q_hi ... a_hat^2 / q_lo); for the summit heights centred on the estimate, a_hat m / q_hi ... a_hat m / q_lo
// with m the refits' median (the surrogates' summit shape is that of the fitted marginal, not the
// summits' estimate). A shape whose interval reaches the fit's
// bounds, or with more than a tenth of its refits at a bound, is not identified.
//
// Cost: per surrogate one FFT of the padded map, the summits, and six warm-started refits (the
// heights' two Weibulls twice): O(N log N) a surrogate.
#pragma once
#include <cstddef>
#include <functional>
#include <vector>

#include "asperity/topography/goodness_of_fit.hpp"
#include "asperity/topography/height_map.hpp"
#include "asperity/topography/statistics.hpp"
#include "asperity/topography/summits.hpp"

namespace asperity::topography {

// Called as surrogates complete (done of total), under a lock, from the worker threads.
using EnsembleProgress = std::function<void(std::size_t done, std::size_t total)>;

struct SurfaceTests {
  SampleAssessment heights;         // the marginal, on a fixed random sample of positions
  SampleAssessment summit_heights;  // what the asperity model integrates
  std::size_t surrogates = 0;       // B
  std::size_t padded_nx = 0, padded_ny = 0;  // the surrogates' grid before cutting
  std::vector<std::size_t> height_positions;  // the points of the heights sample
};

struct SurfaceTestOptions {
  AssessmentOptions assessment;    // bootstrap = B surrogates; seed; threads; confidence; significance
  SummitOptions summits;           // how summits are found (as on the map)
  std::size_t height_sample = 4000;
  std::size_t max_summits = 20000;  // summit heights tested per surface (a random subsample beyond)
  bool test_heights = true;         // false: the heights' fits only (the Weibull surrogates' marginals)
  bool leveled = true;              // the map was leveled: so is every surrogate surface
  // Called on a worker thread for each surrogate with its summits (on the Gaussian surrogate,
  // mu + sigma g): what else the ensemble should measure. Must only touch its own b's slot.
  std::function<void(std::size_t b, const Summits& summits)> on_surrogate;
};

// `map`: as analysed (leveled); `summit_heights`: the map's summit heights as fitted. Throws
// asperity::Error for fewer than 5 summits or heights, or options out of range.
SurfaceTests test_surface(const HeightMap& map, const std::vector<double>& summit_heights,
                          const CorrelationLengths& lengths, const SurfaceTestOptions& options,
                          const EnsembleProgress& progress = {});

// The surrogate surface of model M from normal scores g: mu + sigma g for the Gaussian (the
// statistics do not depend on mu and sigma), F^-1(Phi(g)) for a Weibull marginal F.
double surrogate_height(const HeightDistribution& marginal, double g) noexcept;

}  // namespace asperity::topography
