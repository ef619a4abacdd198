#include "asperity/topography/summits.hpp"

#include <cmath>

#include "asperity/error.hpp"

namespace asperity::topography {

Summits find_summits(const HeightMap& map, const SummitOptions& options) {
  if (options.window < 1) throw Error("summits: the window must be at least 1 point");
  if (!(options.min_drop >= 0) || !std::isfinite(options.min_drop))
    throw Error("summits: the height threshold must be finite and >= 0");
  Summits summits;
  summits.options = options;
  summits.dx = map.dx;
  summits.dy = map.dy;
  const std::size_t w = static_cast<std::size_t>(options.window);
  if (map.nx <= 2 * w || map.ny <= 2 * w) throw Error(map.source + ": too small for the summit window");
  long double curvature_sum = 0;
  for (std::size_t j = w; j + w < map.ny; ++j)
    for (std::size_t i = w; i + w < map.nx; ++i) {
      const double h = map.at(i, j);
      if (std::isnan(h)) continue;
      bool complete = true, summit = true;
      for (std::size_t q = j - w; q <= j + w && complete; ++q)
        for (std::size_t p = i - w; p <= i + w; ++p) {
          if (p == i && q == j) continue;
          const double other = map.at(p, q);
          if (std::isnan(other)) {
            complete = false;
            break;
          }
          const bool before = q < j || (q == j && p < i);
          if (before ? !(h > other) : !(h >= other)) summit = false;
        }
      if (!complete) continue;
      ++summits.candidates;
      if (!summit) continue;
      const double left = map.at(i - 1, j), right = map.at(i + 1, j), down = map.at(i, j - 1), up = map.at(i, j + 1);
      const double neighbours = left + right + down + up + map.at(i - 1, j - 1) + map.at(i + 1, j - 1) +
                                map.at(i - 1, j + 1) + map.at(i + 1, j + 1);
      if (h - neighbours / 8 < options.min_drop) {
        ++summits.rejected_by_drop;
        continue;
      }
      const double hxx = (right - 2 * h + left) / (map.dx * map.dx);
      const double hyy = (up - 2 * h + down) / (map.dy * map.dy);
      const double hxy = (map.at(i + 1, j + 1) - map.at(i + 1, j - 1) - map.at(i - 1, j + 1) + map.at(i - 1, j - 1)) /
                         (4 * map.dx * map.dy);
      Summit s;
      s.i = i;
      s.j = j;
      s.height = h;
      s.mean_curvature = -0.5 * (hxx + hyy);
      // eigenvalues of -[[hxx, hxy], [hxy, hyy]]
      const double half_difference = 0.5 * (hxx - hyy);
      const double root = std::sqrt(half_difference * half_difference + hxy * hxy);
      s.kappa1 = s.mean_curvature + root;
      s.kappa2 = s.mean_curvature - root;
      curvature_sum += s.mean_curvature;
      summits.list.push_back(s);
    }
  summits.area_searched = static_cast<double>(summits.candidates) * map.dx * map.dy;
  if (summits.area_searched > 0) summits.density = static_cast<double>(summits.list.size()) / summits.area_searched;
  if (!summits.list.empty()) {
    summits.mean_curvature = static_cast<double>(curvature_sum / summits.list.size());
    summits.radius = summits.mean_curvature > 0 ? 1 / summits.mean_curvature : 0;
  }
  return summits;
}

HeightMap decimated(const HeightMap& map, std::size_t factor) {
  if (factor < 1) throw Error("decimated: the factor must be at least 1");
  HeightMap out;
  out.source = map.source;
  out.format = map.format;
  out.notes = map.notes;
  // ceil(n / factor), without n + factor - 1 (it wraps for a factor near the largest size)
  const auto every = [factor](std::size_t n) { return n == 0 ? 0 : (n - 1) / factor + 1; };
  out.nx = every(map.nx);
  out.ny = every(map.ny);
  out.dx = map.dx * static_cast<double>(factor);
  out.dy = map.dy * static_cast<double>(factor);
  out.heights.reserve(out.nx * out.ny);
  for (std::size_t j = 0; j < map.ny; j += factor)
    for (std::size_t i = 0; i < map.nx; i += factor) out.heights.push_back(map.at(i, j));
  return out;
}

}  // namespace asperity::topography
