#include "asperity/topography/leveling.hpp"

#include <cmath>

#include "asperity/error.hpp"
#include "plane_fit.hpp"

namespace asperity::topography {

namespace detail {

Plane solve_plane(const PlaneSums& sums, const HeightMap& map, const std::string& source) {
  const long double n = sums.n, sx = sums.sx, sy = sums.sy, sz = sums.sz, sxx = sums.sxx, syy = sums.syy,
                    sxy = sums.sxy, sxz = sums.sxz, syz = sums.syz;
  const double xc = 0.5 * static_cast<double>(map.nx - 1), yc = 0.5 * static_cast<double>(map.ny - 1);
  if (n < 3) throw Error(source + ": fewer than 3 valid points: no plane");
  // Solve [[n sx sy][sx sxx sxy][sy sxy syy]] c = [sz sxz syz] by Cramer's rule.
  const auto det3 = [](long double a, long double b, long double c, long double d, long double e, long double f,
                       long double g, long double h, long double k) {
    return a * (e * k - f * h) - b * (d * k - f * g) + c * (d * h - e * g);
  };
  const long double det = det3(n, sx, sy, sx, sxx, sxy, sy, sxy, syy);
  if (!(std::fabs(static_cast<double>(det)) > 0)) throw Error(source + ": the valid points are collinear: no plane");
  const long double c0 = det3(sz, sx, sy, sxz, sxx, sxy, syz, sxy, syy) / det;
  const long double c1 = det3(n, sz, sy, sx, sxz, sxy, sy, syz, syy) / det;
  const long double c2 = det3(n, sx, sz, sx, sxx, sxz, sy, sxy, syz) / det;
  Plane plane;
  plane.slope_x = static_cast<double>(c1) / map.dx;
  plane.slope_y = static_cast<double>(c2) / map.dy;
  plane.offset = static_cast<double>(c0 - c1 * xc - c2 * yc);
  return plane;
}

}  // namespace detail

Plane fit_plane(const HeightMap& map) {
  return detail::fit_plane_of(map, map.source, [&](std::size_t k) { return map.heights[k]; });
}

void subtract_plane(HeightMap& map, const Plane& plane) {
  for (std::size_t j = 0; j < map.ny; ++j)
    for (std::size_t i = 0; i < map.nx; ++i) {
      map.heights[j * map.nx + i] -= plane_height(plane, map, i, j);
    }
}

}  // namespace asperity::topography
