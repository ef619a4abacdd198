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

#include "asperity/record_fields.hpp"
#include "asperity/topography/height_map.hpp"

namespace asperity::topography {

// Each record's fields, defined once (record_fields.hpp): its members, report.json's keys (the
// column) and the Python attributes with their meanings.
#define ASPERITY_HEIGHT_STATISTICS_FIELDS(X)                                      \
  X(std::size_t, valid_points, "valid_points", "the heights that are not missing") \
  X(std::size_t, missing_points, "missing_points", "the missing heights")          \
  X(double, mean, nullptr, "the mean height [m]")                                  \
  X(double, rms, "Sq_m", "Sq, the rms height about the mean [m]")                  \
  X(double, mean_absolute, "Sa_m", "Sa, the mean absolute height about the mean [m]") \
  X(double, skewness, "Ssk", "Ssk, the heights' skewness")                         \
  X(double, kurtosis, "Sku", "Sku, the heights' kurtosis (3 for a Gaussian)")      \
  X(double, min, "min_m", "the lowest height [m]")                                 \
  X(double, max, "max_m", "the highest height [m]")

struct HeightStatistics {
  ASPERITY_HEIGHT_STATISTICS_FIELDS(ASPERITY_RECORD_MEMBER_INIT)
};

HeightStatistics height_statistics(const HeightMap& map);

// Nayak-McCool's isotropy is not assumed beyond this ratio of principal slope variances.
inline constexpr double max_isotropic_anisotropy = 1.5;

// In report.json's order (spectral_moments); the principal directions of the slope tensor: the
// angle of the steepest from x, the principal slope variances (steepest first) and the curvature
// variances along them
#define ASPERITY_SPECTRAL_MOMENTS_FIELDS(X)                                                                  \
  X(double, m0, "m0_m2", "the height variance [m^2]")                                                       \
  X(double, m2, "m2", "the equivalent isotropic slope variance (geometric mean, McCool 1986)")              \
  X(double, m4, "m4_per_m2", "the equivalent isotropic curvature variance [1/m^2]")                         \
  X(double, alpha, "alpha", "Nayak's bandwidth m0 m4 / m2^2")                                               \
  X(double, m2x, "m2x", "the slope variance along x")                                                       \
  X(double, m2y, "m2y", "the slope variance along y")                                                       \
  X(double, m11, "m11", "<(dh/dx)(dh/dy)>")                                                                 \
  X(double, m4x, "m4x_per_m2", "the curvature variance along x [1/m^2]")                                    \
  X(double, m4y, "m4y_per_m2", "the curvature variance along y [1/m^2]")                                    \
  X(double, principal_angle, "principal_angle_rad", "the steepest principal direction's angle from x [rad]") \
  X(double[2], m2_principal, "m2_principal", "the principal slope variances, steepest first")               \
  X(double[2], m4_principal, "m4_principal_per_m2",                                                         \
    "the curvature variances along the principal directions [1/m^2]")                                       \
  X(double, anisotropy, "anisotropy", "m2_principal[0] / m2_principal[1]; Nayak-McCool assume 1 (isotropic)", 1) \
  X(std::size_t, slope_samples, nullptr, "the slope stencils summed")                                       \
  X(std::size_t, curvature_samples, nullptr, "the curvature stencils summed")

struct SpectralMoments {
  ASPERITY_SPECTRAL_MOMENTS_FIELDS(ASPERITY_RECORD_MEMBER_INIT)
};

// Heights about their mean; stencils that touch a missing point are skipped.
SpectralMoments spectral_moments(const HeightMap& map);

// The lags (in points) along x and along y at which the height autocorrelation first falls
// below `level` (e.g. 0.1: heights that far apart are nearly independent); capped at half the
// map. Used to thin a correlated map before fitting distributions to its heights.
#define ASPERITY_CORRELATION_LENGTHS_FIELDS(X)                                                  \
  X(std::size_t, x, "lag_x_points", "the lag along x [points]", 1)                               \
  X(std::size_t, y, "lag_y_points", "the lag along y [points]", 1)                               \
  X(double, level, "level", "the autocorrelation the lags are where it first falls below", 0.1)

struct CorrelationLengths {
  ASPERITY_CORRELATION_LENGTHS_FIELDS(ASPERITY_RECORD_MEMBER_INIT)
};
CorrelationLengths correlation_lengths(const HeightMap& map, double level = 0.1);

// The valid heights on a grid of one point every lengths.x by lengths.y points, then at most
// max_count of them, evenly spaced in that order (0: all): nearly independent values.
std::vector<double> thinned_heights(const HeightMap& map, const CorrelationLengths& lengths, std::size_t max_count);

}  // namespace asperity::topography

namespace asperity {
ASPERITY_DEFINE_RECORD(topography::HeightStatistics, ASPERITY_HEIGHT_STATISTICS_FIELDS)
ASPERITY_DEFINE_RECORD(topography::SpectralMoments, ASPERITY_SPECTRAL_MOMENTS_FIELDS)
ASPERITY_DEFINE_RECORD(topography::CorrelationLengths, ASPERITY_CORRELATION_LENGTHS_FIELDS)
}  // namespace asperity
