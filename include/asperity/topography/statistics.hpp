// Height statistics and the spectral moments of a height map, over its valid points.
//
// Spectral moments are computed in real space from finite differences, one consistent scheme:
// Nayak (1971) defines m0, m2, m4 as the variances of a profile's height, slope and curvature,
// and on a sampled surface every derivative is a difference whose transfer function is a power
// of one discrete wavenumber k = 2 sin(q dx / 2) / dx: the slope by forward differences,
//   (h[i+1] - h[i]) / dx                       (transfer |k|),
// the curvature by second differences,
//   (h[i+1] - 2 h[i] + h[i-1]) / dx^2          (transfer k^2, the square of the slope's).
// So m2 = sum k^2 C(q) and m4 = sum k^4 C(q) over the same spectrum, as Nayak's theory needs.
// (Central differences for the slope, transfer sin(q dx)/dx, see nothing at the Nyquist
// wavelength where second differences see the most: mixing the two inflated alpha from 19 to 89
// on a real map.) The mixed derivatives use the forward mixed difference, and give the slope
// tensor [[m2x, m11], [m11, m2y]] (its principal directions and the anisotropy ratio) and the
// curvature variance along any direction.
//
// Nayak and McCool's results are for isotropic surfaces. Here m2 and m4 are McCool's (1986)
// equivalent isotropic moments, the geometric means of the principal slope variances and of the
// curvature variances along the principal directions; `anisotropy` is the ratio of the principal
// slope variances, and above max_isotropic_anisotropy the Gaussian from the moments is said not
// to hold (the report says so).
//
// The moments depend on the sampling interval (a finer sampling sees shorter wavelengths: m2,
// m4 and Nayak's alpha = m0 m4 / m2^2 grow as dx shrinks on a self-affine surface); they are the
// moments at the file's sampling interval, stated with it, and the report gives them at 2 dx and
// 4 dx too.
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

// Nayak-McCool's isotropy is not assumed beyond this ratio of principal slope variances.
inline constexpr double max_isotropic_anisotropy = 1.5;

struct SpectralMoments {
  double m0 = 0;             // [m^2]
  double m2x = 0, m2y = 0;   // slope variances along x and y (dimensionless)
  double m11 = 0;            // <(dh/dx)(dh/dy)>
  double m4x = 0, m4y = 0;   // curvature variances along x and y [1/m^2]
  // principal directions of the slope tensor: the angle of the steepest from x [rad], the
  // principal slope variances (steepest first) and the curvature variances along them
  double principal_angle = 0;
  double m2_principal[2] = {0, 0};
  double m4_principal[2] = {0, 0};
  double anisotropy = 1;     // m2_principal[0] / m2_principal[1]
  double m2 = 0, m4 = 0;     // the equivalent isotropic moments (geometric means, McCool 1986)
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
