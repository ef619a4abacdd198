// A measured height map: heights on a regular grid, in SI units, with missing points as NaN.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

namespace asperity::topography {

struct HeightMap {
  std::size_t nx = 0, ny = 0;     // points along x (the fastest index) and along y
  double dx = 0, dy = 0;          // sampling intervals [m]
  std::vector<double> heights;    // [m]; heights[j * nx + i] is the point (x = i dx, y = j dy); NaN: missing
  std::string source;             // the file it came from (for messages)
  std::string format;             // "x3p", "gsf", "ascii-matrix", "xyz", "synthetic"
  std::vector<std::string> notes; // where sizes and units came from, the instrument, what was done

  double at(std::size_t i, std::size_t j) const noexcept { return heights[j * nx + i]; }
  std::size_t size() const noexcept { return heights.size(); }
  std::size_t missing_points() const noexcept;
  double width() const noexcept { return static_cast<double>(nx) * dx; }   // [m]
  double length() const noexcept { return static_cast<double>(ny) * dy; }  // [m]
  // Throws asperity::Error naming the source: sizes inconsistent, intervals not finite and > 0,
  // an infinite height, fewer than 3 x 3 points, or no valid point at all.
  void validate() const;
};

}  // namespace asperity::topography
