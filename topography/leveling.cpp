#include "asperity/topography/leveling.hpp"

#include <cmath>

#include "asperity/error.hpp"

namespace asperity::topography {

Plane fit_plane(const HeightMap& map) {
  // Normal equations in centred coordinates (well conditioned). Each row's sums in double (a
  // row is short: its rounding stays near 1e-16 relative), the rows combined in long double; x87
  // arithmetic per point cost a fifth of a surface test's ensemble (two planes a surrogate).
  const double xc = 0.5 * static_cast<double>(map.nx - 1), yc = 0.5 * static_cast<double>(map.ny - 1);
  long double n = 0, sx = 0, sy = 0, sz = 0, sxx = 0, syy = 0, sxy = 0, sxz = 0, syz = 0;
  for (std::size_t j = 0; j < map.ny; ++j) {
    const double* row = map.heights.data() + j * map.nx;
    double rn = 0, rx = 0, rxx = 0, rz = 0, rxz = 0;
    for (std::size_t i = 0; i < map.nx; ++i) {
      const double z = row[i];
      if (std::isnan(z)) continue;
      const double x = static_cast<double>(i) - xc;
      rn += 1;
      rx += x;
      rxx += x * x;
      rz += z;
      rxz += x * z;
    }
    const long double y = static_cast<double>(j) - yc;
    n += rn;
    sx += rx;
    sy += y * rn;
    sz += rz;
    sxx += rxx;
    syy += y * y * rn;
    sxy += y * rx;
    sxz += rxz;
    syz += y * rz;
  }
  if (n < 3) throw Error(map.source + ": fewer than 3 valid points: no plane");
  // Solve [[n sx sy][sx sxx sxy][sy sxy syy]] c = [sz sxz syz] by Cramer's rule.
  const auto det3 = [](long double a, long double b, long double c, long double d, long double e, long double f,
                       long double g, long double h, long double k) {
    return a * (e * k - f * h) - b * (d * k - f * g) + c * (d * h - e * g);
  };
  const long double det = det3(n, sx, sy, sx, sxx, sxy, sy, sxy, syy);
  if (!(std::fabs(static_cast<double>(det)) > 0)) throw Error(map.source + ": the valid points are collinear: no plane");
  const long double c0 = det3(sz, sx, sy, sxz, sxx, sxy, syz, sxy, syy) / det;
  const long double c1 = det3(n, sz, sy, sx, sxz, sxy, sy, syz, syy) / det;
  const long double c2 = det3(n, sx, sz, sx, sxx, sxz, sy, sxy, syz) / det;
  Plane plane;
  plane.slope_x = static_cast<double>(c1) / map.dx;
  plane.slope_y = static_cast<double>(c2) / map.dy;
  plane.offset = static_cast<double>(c0 - c1 * xc - c2 * yc);
  return plane;
}

void subtract_plane(HeightMap& map, const Plane& plane) {
  for (std::size_t j = 0; j < map.ny; ++j)
    for (std::size_t i = 0; i < map.nx; ++i) {
      double& z = map.heights[j * map.nx + i];
      z -= plane.offset + plane.slope_x * (static_cast<double>(i) * map.dx) + plane.slope_y * (static_cast<double>(j) * map.dy);
    }
}

}  // namespace asperity::topography
