// Height statistics and the spectral moments of a height map, over its valid points.
//
// Spectral moments are computed in real space from finite differences, which is what the
// spectral moments of the sampled surface are (Nayak 1971: m0, m2, m4 are the variances of the
// height, the slope and the curvature of a profile):
//   m0 = <h^2>, m2 = <(dh/dx)^2> with dh/dx = (h[i+1] - h[i-1]) / (2 dx),
//   m4 = <(d2h/dx2)^2> with d2h/dx2 = (h[i+1] - 2 h[i] + h[i-1]) / dx^2,
// along x and along y (profiles in both directions), averaged: m2 = (m2x + m2y)/2, likewise m4.
// They depend on the sampling interval (a finer sampling sees shorter wavelengths: m2, m4 and
// Nayak's alpha = m0 m4 / m2^2 grow as dx shrinks on a self-affine surface); they are the
// moments at the file's sampling interval, stated with it.
#pragma once
#include <cstddef>
#include <vector>

#include "asperity/topography/height_map.hpp"

namespace asperity::topography {

struct HeightStatistics {
  std::size_t valid_points = 0, missing_points = 0;
  double mean = 0;      // [m]
  double rms = 0;       // Sq, about the mean [m]
  double mean_absolute = 0;  // Sa [m]
  double skewness = 0;  // Ssk
  double kurtosis = 0;  // Sku (3 for a Gaussian)
  double min = 0, max = 0;
};

HeightStatistics height_statistics(const HeightMap& map);

struct SpectralMoments {
  double m0 = 0;             // [m^2]
  double m2x = 0, m2y = 0;   // slope variances (dimensionless)
  double m4x = 0, m4y = 0;   // curvature variances [1/m^2]
  double m2 = 0, m4 = 0;     // averaged over the two directions
  double alpha = 0;          // Nayak's bandwidth m0 m4 / m2^2
  std::size_t slope_samples = 0, curvature_samples = 0;
};

// Heights about their mean; stencils that touch a missing point are skipped.
SpectralMoments spectral_moments(const HeightMap& map);

// The lags (in points) along x and along y at which the height autocorrelation first falls
// below `level` (e.g. 0.1: heights that far apart are nearly independent); capped at half the
// map. Used to thin a correlated map before fitting distributions to its heights.
struct CorrelationLengths {
  std::size_t x = 1, y = 1;
  double level = 0.1;
};
CorrelationLengths correlation_lengths(const HeightMap& map, double level = 0.1);

// The valid heights on a grid of one point every lengths.x by lengths.y points, then at most
// max_count of them, evenly spaced in that order (0: all): nearly independent values.
std::vector<double> thinned_heights(const HeightMap& map, const CorrelationLengths& lengths, std::size_t max_count);

}  // namespace asperity::topography
