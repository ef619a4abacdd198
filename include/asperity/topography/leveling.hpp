// Leveling: the least-squares plane through the valid points, subtracted (ISO 25178's
// F-operation of the simplest kind; no form or waviness filter).
#pragma once
#include <cstddef>

#include "asperity/topography/height_map.hpp"

namespace asperity::topography {

// z = offset + slope_x x + slope_y y, with x = i dx and y = j dy [m].
struct Plane {
  double offset = 0, slope_x = 0, slope_y = 0;
};

// The plane's height at point (i, j) of `map`'s grid.
inline double plane_height(const Plane& plane, const HeightMap& map, std::size_t i, std::size_t j) noexcept {
  return plane.offset + plane.slope_x * (static_cast<double>(i) * map.dx) + plane.slope_y * (static_cast<double>(j) * map.dy);
}

// The least-squares plane over the valid points (missing points ignored).
Plane fit_plane(const HeightMap& map);
// Subtracts the plane in place; missing points stay missing.
void subtract_plane(HeightMap& map, const Plane& plane);

}  // namespace asperity::topography
