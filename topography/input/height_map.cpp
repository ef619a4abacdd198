#include "asperity/topography/height_map.hpp"

#include <charconv>
#include <cmath>

#include "asperity/error.hpp"

namespace asperity::topography {
namespace {
std::string shortest(double value) {
  char text[32];
  const auto end = std::to_chars(text, text + sizeof text, value).ptr;
  return std::string(text, end);
}
}  // namespace

std::size_t HeightMap::missing_points() const noexcept {
  std::size_t missing = 0;
  for (double h : heights) missing += std::isnan(h) ? 1 : 0;
  return missing;
}

void HeightMap::validate() const {
  const std::string name = source.empty() ? std::string("height map") : source;
  if (nx < 3 || ny < 3) throw Error(name + ": fewer than 3 x 3 points (" + std::to_string(nx) + " x " + std::to_string(ny) + ")");
  if (heights.size() != nx * ny) throw Error(name + ": " + std::to_string(heights.size()) + " heights for " + std::to_string(nx) + " x " + std::to_string(ny) + " points");
  for (const double step : {dx, dy})
    if (!(step >= min_sampling_interval && step <= max_sampling_interval))
      throw Error(name + ": a sampling interval of " + shortest(step) + " m is outside [" +
                  shortest(min_sampling_interval) + ", " + shortest(max_sampling_interval) +
                  "] m (a wrong unit?)");
  std::size_t valid = 0;
  for (std::size_t k = 0; k < heights.size(); ++k) {
    const double h = heights[k];
    if (std::isnan(h)) continue;
    if (!(std::fabs(h) <= max_height))
      throw Error(name + ": the height " + shortest(h) + " m at point (" + std::to_string(k % nx) + ", " +
                  std::to_string(k / nx) + ") is beyond " + shortest(max_height) + " m (a wrong unit?)");
    ++valid;
  }
  if (valid == 0) throw Error(name + ": no valid point (every height is missing)");
}

}  // namespace asperity::topography
