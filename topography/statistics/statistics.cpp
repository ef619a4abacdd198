#include "asperity/topography/statistics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "asperity/error.hpp"
#include "fft.hpp"

namespace asperity::topography {

HeightStatistics height_statistics(const HeightMap& map) {
  HeightStatistics stats;
  long double sum = 0;
  stats.min = std::numeric_limits<double>::infinity();
  stats.max = -stats.min;
  for (double h : map.heights) {
    if (std::isnan(h)) {
      ++stats.missing_points;
      continue;
    }
    ++stats.valid_points;
    sum += h;
    stats.min = std::min(stats.min, h);
    stats.max = std::max(stats.max, h);
  }
  if (stats.valid_points == 0) throw Error(map.source + ": no valid point");
  const double n = static_cast<double>(stats.valid_points);
  stats.mean = static_cast<double>(sum / n);
  long double m1 = 0, m2 = 0, m3 = 0, m4 = 0;
  for (double h : map.heights) {
    if (std::isnan(h)) continue;
    const long double d = h - stats.mean;
    m1 += std::fabs(static_cast<double>(d));
    m2 += d * d;
    m3 += d * d * d;
    m4 += d * d * d * d;
  }
  stats.rms = std::sqrt(static_cast<double>(m2 / n));
  stats.mean_absolute = static_cast<double>(m1 / n);
  if (stats.rms > 0) {
    stats.skewness = static_cast<double>(m3 / n) / (stats.rms * stats.rms * stats.rms);
    stats.kurtosis = static_cast<double>(m4 / n) / (stats.rms * stats.rms * stats.rms * stats.rms);
  }
  return stats;
}

SpectralMoments spectral_moments(const HeightMap& map) {
  const HeightStatistics stats = height_statistics(map);
  SpectralMoments moments;
  moments.m0 = stats.rms * stats.rms;
  const std::size_t nx = map.nx, ny = map.ny;
  const double dx = map.dx, dy = map.dy;
  const auto h = [&](std::size_t i, std::size_t j) { return map.heights[j * nx + i]; };
  // slopes by forward differences (both at a point where h, its x and y neighbours are valid)
  long double sxx = 0, syy = 0, sxy = 0;
  std::size_t nx_slopes = 0, ny_slopes = 0, n_cross = 0;
  // curvatures: second differences along x, y; the forward mixed difference
  long double cxx = 0, cyy = 0, cxy = 0, cxx_yy = 0, cxx_xy = 0, cyy_xy = 0, common_xx = 0, common_yy = 0;
  std::size_t n_xx = 0, n_yy = 0, n_curvature = 0;
  for (std::size_t j = 0; j < ny; ++j)
    for (std::size_t i = 0; i < nx; ++i) {
      const double here = h(i, j);
      if (std::isnan(here)) continue;
      const double right = i + 1 < nx ? h(i + 1, j) : NAN, up = j + 1 < ny ? h(i, j + 1) : NAN;
      const double sx = (right - here) / dx, sy = (up - here) / dy;
      if (!std::isnan(sx)) {
        sxx += sx * sx;
        ++nx_slopes;
      }
      if (!std::isnan(sy)) {
        syy += sy * sy;
        ++ny_slopes;
      }
      if (!std::isnan(sx) && !std::isnan(sy)) {
        sxy += sx * sy;
        ++n_cross;
      }
      const double left = i > 0 ? h(i - 1, j) : NAN, down = j > 0 ? h(i, j - 1) : NAN;
      const double hxx = (right - 2 * here + left) / (dx * dx), hyy = (up - 2 * here + down) / (dy * dy);
      if (!std::isnan(hxx)) {
        cxx += hxx * hxx;
        ++n_xx;
      }
      if (!std::isnan(hyy)) {
        cyy += hyy * hyy;
        ++n_yy;
      }
      const double diagonal = i + 1 < nx && j + 1 < ny ? h(i + 1, j + 1) : NAN;
      const double hxy = (diagonal - right - up + here) / (dx * dy);
      if (!std::isnan(hxx) && !std::isnan(hyy) && !std::isnan(hxy)) {
        common_xx += hxx * hxx;
        common_yy += hyy * hyy;
        cxy += hxy * hxy;
        cxx_yy += hxx * hyy;
        cxx_xy += hxx * hxy;
        cyy_xy += hyy * hxy;
        ++n_curvature;
      }
    }
  if (nx_slopes == 0 || ny_slopes == 0 || n_xx == 0 || n_yy == 0)
    throw Error(map.source + ": no three valid points in a row in both directions: no spectral moments");
  moments.m2x = static_cast<double>(sxx / nx_slopes);
  moments.m2y = static_cast<double>(syy / ny_slopes);
  moments.m11 = n_cross ? static_cast<double>(sxy / n_cross) : 0;
  moments.m4x = static_cast<double>(cxx / n_xx);
  moments.m4y = static_cast<double>(cyy / n_yy);
  // principal directions of the slope tensor
  const double half_sum = 0.5 * (moments.m2x + moments.m2y), half_difference = 0.5 * (moments.m2x - moments.m2y);
  const double radius = std::hypot(half_difference, moments.m11);
  moments.principal_angle = 0.5 * std::atan2(2 * moments.m11, moments.m2x - moments.m2y);
  moments.m2_principal[0] = half_sum + radius;
  moments.m2_principal[1] = half_sum - radius;
  // the curvature variance along direction theta: <(c^2 hxx + 2 c s hxy + s^2 hyy)^2>, every
  // average over the points where the three differences exist
  const double a = n_curvature ? static_cast<double>(common_xx / n_curvature) : moments.m4x;
  const double b = n_curvature ? static_cast<double>(common_yy / n_curvature) : moments.m4y;
  const double c = n_curvature ? static_cast<double>(cxy / n_curvature) : 0;
  const double d = n_curvature ? static_cast<double>(cxx_yy / n_curvature) : 0;
  const double e = n_curvature ? static_cast<double>(cxx_xy / n_curvature) : 0;
  const double f = n_curvature ? static_cast<double>(cyy_xy / n_curvature) : 0;
  for (int k = 0; k < 2; ++k) {
    const double theta = moments.principal_angle + k * 1.5707963267948966;
    const double co = std::cos(theta), si = std::sin(theta);
    const double c2 = co * co, s2 = si * si, cs = co * si;
    moments.m4_principal[k] = c2 * c2 * a + s2 * s2 * b + 4 * cs * cs * c + 2 * c2 * s2 * d + 4 * c2 * cs * e +
                              4 * s2 * cs * f;
  }
  moments.anisotropy = moments.m2_principal[1] > 0 ? moments.m2_principal[0] / moments.m2_principal[1]
                                                   : std::numeric_limits<double>::infinity();
  moments.m2 = std::sqrt(std::max(0.0, moments.m2_principal[0]) * std::max(0.0, moments.m2_principal[1]));
  moments.m4 = std::sqrt(std::max(0.0, moments.m4_principal[0]) * std::max(0.0, moments.m4_principal[1]));
  moments.alpha = moments.m2 > 0 ? moments.m0 * moments.m4 / (moments.m2 * moments.m2) : 0;
  moments.slope_samples = nx_slopes + ny_slopes;
  moments.curvature_samples = n_xx + n_yy;
  return moments;
}

CorrelationLengths correlation_lengths(const HeightMap& map, double level) {
  const HeightStatistics stats = height_statistics(map);
  CorrelationLengths lengths;
  lengths.level = level;
  const double variance = stats.rms * stats.rms;
  if (!(variance > 0)) return lengths;
  for (int direction = 0; direction < 2; ++direction) {
    const bool along_x = direction == 0;
    const std::size_t along = along_x ? map.nx : map.ny, across = along_x ? map.ny : map.nx;
    const std::size_t max_lag = along / 2;
    // the mean autocovariance of every line at once, by FFT: O(N log n), not N x lag
    const std::vector<double> covariance =
        detail::mean_line_autocovariance(map.heights.data(), across, along, along_x ? map.nx : 1,
                                         along_x ? 1 : map.nx, stats.mean, max_lag);
    std::size_t lag = 1;
    for (; lag < max_lag; ++lag)
      if (!(covariance[lag] / variance >= level)) break;  // no pair (NaN) ends the search too
    (along_x ? lengths.x : lengths.y) = std::max<std::size_t>(lag, 1);
  }
  return lengths;
}

std::vector<double> thinned_heights(const HeightMap& map, const CorrelationLengths& lengths, std::size_t max_count) {
  const std::size_t sx = std::max<std::size_t>(1, lengths.x), sy = std::max<std::size_t>(1, lengths.y);
  std::vector<double> thinned;
  for (std::size_t j = 0; j < map.ny; j += sy)
    for (std::size_t i = 0; i < map.nx; i += sx)
      if (!std::isnan(map.at(i, j))) thinned.push_back(map.at(i, j));
  if (max_count > 0 && thinned.size() > max_count) {
    std::vector<double> kept;
    const double step = static_cast<double>(thinned.size()) / static_cast<double>(max_count);
    for (std::size_t k = 0; k < max_count; ++k) kept.push_back(thinned[static_cast<std::size_t>(static_cast<double>(k) * step)]);
    thinned.swap(kept);
  }
  return thinned;
}

}  // namespace asperity::topography
