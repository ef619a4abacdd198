// A measured height map: heights on a regular grid, in SI units, with missing points as NaN.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

namespace asperity::topography {

// The physical range every map must lie in [m]: outside it, a length is a unit slip or
// garbage, and the statistics would under- or overflow (density 0, radius 0) instead of
// failing.
constexpr double min_sampling_interval = 1e-13;  // 0.1 pm, far below atomic spacing
constexpr double max_sampling_interval = 1e3;    // 1 km
constexpr double max_height = 1e3;               // |h| <= 1 km

struct HeightMap {
  std::size_t nx = 0, ny = 0;     // points along x (the fastest index) and along y
  double dx = 0, dy = 0;          // sampling intervals [m]
  std::vector<double> heights;    // [m]; heights[j * nx + i] is the point (x = i dx, y = j dy); NaN: missing
  std::string source;             // the file it came from (for messages)
  std::string format;             // "x3p", "gsf", "ascii-matrix", "xyz", "synthetic"
  std::vector<std::string> notes; // where sizes and units came from, the instrument, what was done
  // The largest rounding step of the heights as stored [m]: an integer format's increment, a
  // float's spacing at the largest height, the last printed digit of a text file; 0: unknown.
  // A roughness at this level is quantization, not a surface (the analysis refuses it).
  double height_resolution = 0;

  double at(std::size_t i, std::size_t j) const noexcept { return heights[j * nx + i]; }
  std::size_t size() const noexcept { return heights.size(); }
  std::size_t missing_points() const noexcept;
  double width() const noexcept { return static_cast<double>(nx) * dx; }   // [m]
  double length() const noexcept { return static_cast<double>(ny) * dy; }  // [m]
  // Throws asperity::Error naming the source: sizes inconsistent, intervals not within
  // [min_sampling_interval, max_sampling_interval], a height not finite (NaN is missing) or
  // beyond max_height, fewer than 3 x 3 points, or no valid point at all.
  void validate() const;
};

}  // namespace asperity::topography
