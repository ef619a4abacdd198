#include "asperity/topography/summits.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "asperity/error.hpp"

namespace asperity::topography {
namespace {

// a beats b: higher, or as high and earlier in raster order (a flat top counts once)
struct Beats {
  const double* h;
  bool operator()(std::size_t a, std::size_t b) const noexcept { return h[a] > h[b] || (h[a] == h[b] && a < b); }
};

// out[k] = the best of in[k - w ... k + w] along one line (entries first + k * stride, k < n),
// by a monotonic queue of (position, candidate): O(n) whatever the window.
void sliding_best(const Beats& beats, const std::size_t* in, std::size_t* out, std::size_t first, std::size_t n,
                  std::size_t stride, std::size_t w, std::vector<std::pair<std::size_t, std::size_t>>& queue) {
  queue.clear();
  std::size_t head = 0, entered = 0;
  for (std::size_t k = 0; k < n; ++k) {
    for (const std::size_t last = std::min(n - 1, k + w); entered <= last; ++entered) {
      const std::size_t candidate = in[first + entered * stride];
      while (queue.size() > head && !beats(queue.back().second, candidate)) queue.pop_back();
      queue.emplace_back(entered, candidate);
    }
    while (queue[head].first + w < k) ++head;  // left the window
    out[first + k * stride] = queue[head].second;
  }
}

// The summits of a window larger than 3 x 3: a point is a summit when it is the best point of
// its window, found by a separable sliding maximum (rows, then columns) in O(N) whatever the
// window's size (the direct test costs (2w + 1)^2 a point); windows with a missing point are
// found by a summed-area table of missing points.
std::vector<char> window_maxima(const HeightMap& map, std::size_t w) {
  const std::size_t nx = map.nx, ny = map.ny;
  const Beats beats{map.heights.data()};
  std::vector<std::size_t> identity(nx * ny), row_best(nx * ny), best(nx * ny);
  for (std::size_t k = 0; k < identity.size(); ++k) identity[k] = k;
  std::vector<std::pair<std::size_t, std::size_t>> queue;
  for (std::size_t j = 0; j < ny; ++j) sliding_best(beats, identity.data(), row_best.data(), j * nx, nx, 1, w, queue);
  identity.clear();
  identity.shrink_to_fit();
  for (std::size_t i = 0; i < nx; ++i) sliding_best(beats, row_best.data(), best.data(), i, ny, nx, w, queue);
  row_best.clear();
  row_best.shrink_to_fit();
  // missing points in each window: a summed-area table over (ny + 1) x (nx + 1)
  std::vector<std::size_t> missing((nx + 1) * (ny + 1), 0);
  for (std::size_t j = 0; j < ny; ++j)
    for (std::size_t i = 0; i < nx; ++i)
      missing[(j + 1) * (nx + 1) + i + 1] = (std::isnan(map.heights[j * nx + i]) ? 1 : 0) +
                                            missing[j * (nx + 1) + i + 1] + missing[(j + 1) * (nx + 1) + i] -
                                            missing[j * (nx + 1) + i];
  std::vector<char> result(nx * ny, 0);  // 0: not a candidate, 1: a candidate, 2: a summit
  for (std::size_t j = w; j + w < ny; ++j)
    for (std::size_t i = w; i + w < nx; ++i) {
      const std::size_t x0 = i - w, x1 = i + w + 1, y0 = j - w, y1 = j + w + 1;
      const std::size_t holes = missing[y1 * (nx + 1) + x1] - missing[y0 * (nx + 1) + x1] -
                                missing[y1 * (nx + 1) + x0] + missing[y0 * (nx + 1) + x0];
      if (holes != 0) continue;
      result[j * nx + i] = best[j * nx + i] == j * nx + i ? 2 : 1;
    }
  return result;
}

}  // namespace

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
  const std::vector<char> maxima = w > 1 ? window_maxima(map, w) : std::vector<char>();
  // rows without a missing point: there every neighbourhood is complete, and a point is
  // dismissed at its first higher neighbour (most points: the search's cost)
  std::vector<char> row_complete(map.ny, 1);
  for (std::size_t j = 0; j < map.ny; ++j)
    for (std::size_t i = 0; i < map.nx && row_complete[j]; ++i)
      if (std::isnan(map.at(i, j))) row_complete[j] = 0;
  long double curvature_sum = 0;
  for (std::size_t j = w; j + w < map.ny; ++j)
    for (std::size_t i = w; i + w < map.nx; ++i) {
      const double h = map.at(i, j);
      if (std::isnan(h)) continue;
      bool complete = true, summit = true;
      if (w > 1) {
        complete = maxima[j * map.nx + i] != 0;
        summit = maxima[j * map.nx + i] == 2;
      } else if (row_complete[j - 1] && row_complete[j] && row_complete[j + 1]) {
        // the same order of comparisons as below: strictly above the neighbours before (i, j),
        // at least as high as those after
        const double* below = &map.heights[(j - 1) * map.nx + i];
        const double* row = &map.heights[j * map.nx + i];
        const double* above = &map.heights[(j + 1) * map.nx + i];
        summit = h >= row[1] && h > row[-1] && h > below[-1] && h > below[0] && h > below[1] && h >= above[-1] &&
                 h >= above[0] && h >= above[1];
      } else {
        // the 8 neighbours directly: no tables
        for (std::size_t q = j - 1; q <= j + 1 && complete; ++q)
          for (std::size_t p = i - 1; p <= i + 1; ++p) {
            if (p == i && q == j) continue;
            const double other = map.at(p, q);
            if (std::isnan(other)) {
              complete = false;
              break;
            }
            const bool before = q < j || (q == j && p < i);
            if (before ? !(h > other) : !(h >= other)) summit = false;
          }
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
