#include "asperity/topography/height_map.hpp"

#include <cmath>

#include "asperity/error.hpp"

namespace asperity::topography {

std::size_t HeightMap::missing_points() const noexcept {
  std::size_t missing = 0;
  for (double h : heights) missing += std::isnan(h) ? 1 : 0;
  return missing;
}

void HeightMap::validate() const {
  const std::string name = source.empty() ? std::string("height map") : source;
  if (nx < 3 || ny < 3) throw Error(name + ": fewer than 3 x 3 points (" + std::to_string(nx) + " x " + std::to_string(ny) + ")");
  if (heights.size() != nx * ny) throw Error(name + ": " + std::to_string(heights.size()) + " heights for " + std::to_string(nx) + " x " + std::to_string(ny) + " points");
  if (!(std::isfinite(dx) && dx > 0 && std::isfinite(dy) && dy > 0))
    throw Error(name + ": sampling intervals must be finite and positive");
  std::size_t valid = 0;
  for (double h : heights) {
    if (std::isinf(h)) throw Error(name + ": an infinite height");
    valid += std::isnan(h) ? 0 : 1;
  }
  if (valid == 0) throw Error(name + ": no valid point (every height is missing)");
}

}  // namespace asperity::topography
