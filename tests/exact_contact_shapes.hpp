// Shapes whose elastic contact has a closed form, as the exact contact's tests lay them on a grid.
#pragma once
#include <cstddef>

#include "asperity/topography/height_map.hpp"

namespace asperity::test {

// A paraboloid of radius `radius` centred on an n x n map of side `side`: the gap of a sphere over
// a flat (pixel centres at (i + 1/2 - n/2) dx).
inline topography::HeightMap sphere_map(std::size_t n, double side, double radius) {
  topography::HeightMap map;
  map.nx = map.ny = n;
  map.dx = map.dy = side / static_cast<double>(n);
  map.source = "sphere";
  map.format = "synthetic";
  map.heights.resize(n * n);
  for (std::size_t j = 0; j < n; ++j)
    for (std::size_t i = 0; i < n; ++i) {
      const double x = (static_cast<double>(i) + 0.5 - n / 2.0) * map.dx;
      const double y = (static_cast<double>(j) + 0.5 - n / 2.0) * map.dy;
      map.heights[j * n + i] = -(x * x + y * y) / (2 * radius);
    }
  return map;
}

}  // namespace asperity::test
