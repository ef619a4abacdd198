// The least-squares plane of any height function on a map's grid (internal): fit_plane
// (leveling.hpp) is this of the map's own heights; the surrogate ensembles fit the plane of a
// transformed field without writing the field out (surface_tests.cpp).
#pragma once
#include <cmath>
#include <cstddef>
#include <string>

#include "asperity/topography/leveling.hpp"

namespace asperity::topography::detail {

// The normal equations' sums, in centred coordinates (well conditioned).
struct PlaneSums {
  long double n = 0, sx = 0, sy = 0, sz = 0, sxx = 0, syy = 0, sxy = 0, sxz = 0, syz = 0;
};

// The plane from its sums on `grid` (its steps and size); throws asperity::Error, naming
// `source`, for fewer than 3 points or collinear ones.
Plane solve_plane(const PlaneSums& sums, const HeightMap& grid, const std::string& source);

// `height(k)`: the height of point k = j nx + i (NaN: missing, left out). Each row's sums in
// double (a row is short: its rounding stays near 1e-16 relative), the rows combined in long
// double (x87 arithmetic per point cost a fifth of a surface test's ensemble).
template <class Height>
Plane fit_plane_of(const HeightMap& grid, const std::string& source, Height height) {
  const double xc = 0.5 * static_cast<double>(grid.nx - 1), yc = 0.5 * static_cast<double>(grid.ny - 1);
  PlaneSums s;
  for (std::size_t j = 0; j < grid.ny; ++j) {
    double rn = 0, rx = 0, rxx = 0, rz = 0, rxz = 0;
    for (std::size_t i = 0; i < grid.nx; ++i) {
      const double z = height(j * grid.nx + i);
      if (std::isnan(z)) continue;
      const double x = static_cast<double>(i) - xc;
      rn += 1;
      rx += x;
      rxx += x * x;
      rz += z;
      rxz += x * z;
    }
    const long double y = static_cast<double>(j) - yc;
    s.n += rn;
    s.sx += rx;
    s.sy += y * rn;
    s.sz += rz;
    s.sxx += rxx;
    s.syy += y * y * rn;
    s.sxy += y * rx;
    s.sxz += rxz;
    s.syz += y * rz;
  }
  return solve_plane(s, grid, source);
}

}  // namespace asperity::topography::detail
