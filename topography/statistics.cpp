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
  long double slope[2] = {0, 0}, curvature[2] = {0, 0};
  std::size_t slope_count[2] = {0, 0}, curvature_count[2] = {0, 0};
  const double step[2] = {map.dx, map.dy};
  for (int direction = 0; direction < 2; ++direction) {
    const std::size_t along = direction == 0 ? map.nx : map.ny, across = direction == 0 ? map.ny : map.nx;
    const double h = step[direction];
    for (std::size_t a = 0; a < across; ++a)
      for (std::size_t k = 1; k + 1 < along; ++k) {
        const auto value = [&](std::size_t position) {
          return direction == 0 ? map.at(position, a) : map.at(a, position);
        };
        const double before = value(k - 1), here = value(k), after = value(k + 1);
        if (std::isnan(before) || std::isnan(here) || std::isnan(after)) continue;
        const double first = (after - before) / (2 * h), second = (after - 2 * here + before) / (h * h);
        slope[direction] += first * first;
        curvature[direction] += second * second;
        ++slope_count[direction];
        ++curvature_count[direction];
      }
  }
  if (slope_count[0] == 0 || slope_count[1] == 0)
    throw Error(map.source + ": no three valid points in a row in both directions: no spectral moments");
  moments.m2x = static_cast<double>(slope[0] / slope_count[0]);
  moments.m2y = static_cast<double>(slope[1] / slope_count[1]);
  moments.m4x = static_cast<double>(curvature[0] / curvature_count[0]);
  moments.m4y = static_cast<double>(curvature[1] / curvature_count[1]);
  moments.m2 = 0.5 * (moments.m2x + moments.m2y);
  moments.m4 = 0.5 * (moments.m4x + moments.m4y);
  moments.alpha = moments.m2 > 0 ? moments.m0 * moments.m4 / (moments.m2 * moments.m2) : 0;
  moments.slope_samples = slope_count[0] + slope_count[1];
  moments.curvature_samples = curvature_count[0] + curvature_count[1];
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
