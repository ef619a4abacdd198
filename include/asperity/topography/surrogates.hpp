// Synthetic surfaces that share a measured map's spectrum: the surfaces of the null hypotheses
// (docs/surfaces.md, section 4). Summit heights of a real surface are correlated (neighbouring
// summits share the long wavelengths): a test that draws independent values cannot see that. Its
// null distribution comes instead from whole synthetic surfaces of the measured map's own
// spectrum, with summits found on each exactly as on the measurement.
//
// The spectrum: of the map's heights transformed to normal scores (each height replaced by
// Phi^-1 of its mid-rank, so the spectrum is that of the Gaussian field behind any monotone
// marginal), estimated by Blackman and Tukey: the scores' autocovariance at every lag by FFT,
// divided by each lag's pairs (missing points left out), with the variance the analysis took
// from the map (its mean, and its plane when leveled) restored from the long lags' bias, under a
// flat-topped lag window (Tukey's: 1 to half the largest lag, a cosine taper to 0 at it) to six
// correlation lengths (at most three quarters of the map), laid on a grid the map plus that lag
// wide (so a surrogate is not periodic across the map) and transformed (surrogates.cpp says why
// each step). The constants below are what the code reads, and surrogate_method() the words every
// output gives for it, made from them.
// A surrogate is a Gaussian random field with that spectrum (complex normal Fourier
// coefficients, one inverse FFT), of unit variance in expectation, cut to the map's grid, and
// missing where the map is. Its mean and variance over the map fluctuate from surrogate to
// surrogate as the measured map's would (a Weibull marginal turns those fluctuations into ones
// of the shape, so they must not be standardized away).
//
// Under a hypothesis the surrogate becomes a surface through a monotone map of its normal scores
// (a Gaussian: mu + sigma g; a Weibull: F^-1(Phi(g))): the amplitude-adjusted surrogates of
// Theiler et al. (1992) and Schreiber & Schmitz (2000). A monotone map keeps every summit where it
// is, so the summits are found once per surrogate, on g.
//
// Cost: one FFT of the padded grid a surrogate, O(N log N); reproducible for every thread count
// (surrogate k of seed s is the same however the ensemble is split).
#pragma once
#include <complex>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "asperity/topography/height_map.hpp"
#include "asperity/topography/statistics.hpp"

namespace asperity::topography {

// The spectrum estimate's constants, read by SurrogateFields and by surrogate_method().
struct SurrogateSpectrum {
  // the largest lag along each axis: this many correlation lengths (CorrelationLengths) ...
  static constexpr std::size_t largest_lag_lengths = 6;
  // ... at most this fraction of the map's points along it (numerator / denominator)
  static constexpr std::size_t largest_lag_map_numerator = 3, largest_lag_map_denominator = 4;
  // Tukey's lag window is 1 up to this fraction of the largest lag
  static constexpr double window_flat = 0.5;
};

// The lag window at u = the lag's elliptical radius over the largest lag ((rx/Lx)^2 + (ry/Ly)^2)^1/2:
// Tukey's (a split cosine bell), 1 for u <= window_flat, (1 + cos(pi (u - flat) / (1 - flat))) / 2
// beyond, 0 from u = 1. What SurrogateFields multiplies the autocovariance by.
double surrogate_lag_window(double u) noexcept;

// The surrogates in words, made from the constants above and the window (report.json's
// ensemble.method, report.md).
std::string surrogate_method();

class SurrogateFields {
 public:
  // `map`: the heights as analysed, NaN missing; `lengths`: its correlation lengths (the largest
  // lag and the padding); `leveled`: the map's least-squares plane was subtracted (the variance
  // that took is restored, as the mean's always is). Throws asperity::Error for a map with fewer
  // than 3 x 3 points. `threads`: for the spectrum's autocorrelations (0: all cores).
  SurrogateFields(const HeightMap& map, const CorrelationLengths& lengths, bool leveled = true, int threads = 0);

  // Surrogate `index` of the ensemble `seed`: normal scores on the map's grid (x fastest), unit
  // variance in expectation, NaN where the map is missing. `field` is resized.
  void generate(std::uint64_t seed, std::size_t index, std::vector<double>& field) const;

  // The map's own normal scores (the transform the spectrum was taken of), NaN where missing.
  const std::vector<double>& normal_scores() const noexcept { return scores_; }
  std::size_t nx() const noexcept { return nx_; }
  std::size_t ny() const noexcept { return ny_; }
  std::size_t padded_nx() const noexcept { return px_; }
  std::size_t padded_ny() const noexcept { return py_; }

 private:
  std::size_t nx_ = 0, ny_ = 0, px_ = 0, py_ = 0;
  std::vector<double> amplitude_;  // py x (px/2 + 1), the coefficients' standard deviation
  std::vector<double> scores_;
  std::vector<char> valid_;
};

// The standard normal quantile Phi^-1(p) and distribution Phi(z) (Boost.Math).
double normal_quantile(double p);
double normal_cdf(double z);

}  // namespace asperity::topography
