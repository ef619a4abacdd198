// Leveling: the least-squares plane through the valid points, subtracted (ISO 25178's
// F-operation of the simplest kind; no form or waviness filter).
#pragma once
#include "asperity/topography/height_map.hpp"

namespace asperity::topography {

// z = offset + slope_x x + slope_y y, with x = i dx and y = j dy [m].
struct Plane {
  double offset = 0, slope_x = 0, slope_y = 0;
};

// The least-squares plane over the valid points (missing points ignored).
Plane fit_plane(const HeightMap& map);
// Subtracts the plane in place; missing points stay missing.
void subtract_plane(HeightMap& map, const Plane& plane);

}  // namespace asperity::topography
