// x y z text (blank-, comma- or semicolon-separated) on a regular grid; no units in the file.
#include <algorithm>
#include <cmath>
#include <limits>

#include "asperity/topography/height_map_io.hpp"
#include "asperity/topography/units.hpp"
#include "input_file.hpp"
#include "reader_support.hpp"

namespace asperity::topography {
namespace {
using detail::fail;

struct Axis {
  double origin = 0, step = 0;
  std::size_t count = 0;
};

// The regular grid the coordinates lie on: the step is the smallest gap between distinct
// values; every value must lie within 1e-3 steps of a grid node.
Axis grid_axis(const std::string& path, std::vector<double> values, const char* name, std::size_t max_points) {
  std::sort(values.begin(), values.end());
  values.erase(std::unique(values.begin(), values.end()), values.end());
  Axis axis;
  axis.origin = values.front();
  if (values.size() == 1) fail(path, std::string("every point has the same ") + name + ": not a map");
  double step = std::numeric_limits<double>::infinity();
  for (std::size_t k = 1; k < values.size(); ++k) step = std::min(step, values[k] - values[k - 1]);
  const double span = (values.back() - values.front()) / step;
  if (!(span < static_cast<double>(max_points)))
    fail(path, std::string("the ") + name + " coordinates do not form a regular grid within the point limit");
  axis.step = step;
  axis.count = static_cast<std::size_t>(std::llround(span)) + 1;
  for (double v : values) {
    const double position = (v - axis.origin) / step;
    if (std::abs(position - std::round(position)) > 1e-3)
      fail(path, std::string("the ") + name + " coordinates are not on a regular grid (" + detail::shortest(v) +
                     " is off the step " + detail::shortest(step) + ")");
  }
  return axis;
}
}  // namespace

HeightMap read_xyz(const std::string& path, const ReadOptions& options) {
  if (options.lateral_unit.empty())
    fail(path, "xyz files carry no units: give the unit of x and y (--unit, e.g. um; heights too unless --height-unit)");
  const double lateral = detail::unit_in_metres(path, "--unit " + options.lateral_unit, options.lateral_unit);
  // three doubles a point while reading, then the grid's heights: a quarter of the point limit
  // keeps the memory within what the other formats need at the limit
  const std::size_t max_points = std::max<std::size_t>(options.max_points / 4, 9);
  detail::InputFile file(path, 80 * std::uint64_t{max_points} + (std::uint64_t{1} << 20));
  detail::LineReader lines(file, 4096);
  std::vector<double> xs, ys, zs;
  std::string line;
  detail::DecimalResolution resolution;
  while (lines.next(line)) {
    const std::size_t line_number = lines.line_number();
    const std::string_view text = detail::trim(line);
    if (text.empty() || text.front() == '#') continue;
    double values[3];
    int count = 0;
    bool numeric = true;
    std::size_t start = 0;
    while (start < text.size()) {
      const std::size_t end = text.find_first_of(" \t,;", start);
      const std::string_view token = text.substr(start, end == std::string_view::npos ? std::string_view::npos : end - start);
      start = end == std::string_view::npos ? text.size() : end + 1;
      if (detail::trim(token).empty()) continue;
      if (count == 3) fail(path, "line " + std::to_string(line_number) + " has more than three columns");
      if (count == 2 && detail::is_nan_token(token)) values[count++] = std::numeric_limits<double>::quiet_NaN();
      else if (detail::parse_double(token, values[count])) {
        if (count == 2) resolution.add(detail::trim(token), values[count]);
        ++count;
      } else {
        numeric = false;
        break;
      }
    }
    if (!numeric) {
      if (xs.empty() && line_number == 1) continue;  // one header line
      fail(path, "line " + std::to_string(line_number) + " is not three numbers x y z");
    }
    if (count != 3) fail(path, "line " + std::to_string(line_number) + " has " + std::to_string(count) + " columns, not x y z");
    if (xs.size() >= max_points)
      fail(path, "holds more than " + std::to_string(max_points) + " points (ReadOptions::max_points / 4 for xyz)");
    xs.push_back(values[0]);
    ys.push_back(values[1]);
    zs.push_back(values[2]);
  }
  if (xs.size() < 9) fail(path, "holds fewer than 9 points");
  const Axis ax = grid_axis(path, xs, "x", options.max_points), ay = grid_axis(path, ys, "y", options.max_points);
  detail::check_point_count(path, ax.count, ay.count, options.max_points);
  if (ax.count * ay.count > 2 * xs.size())
    fail(path, "the points cover less than half of their grid (" + std::to_string(ax.count) + " x " +
                   std::to_string(ay.count) + "): not a regular map");
  HeightMap map;
  map.source = path;
  map.format = "xyz";
  map.nx = ax.count;
  map.ny = ay.count;
  map.dx = ax.step * lateral;
  map.dy = ay.step * lateral;
  map.heights.assign(map.nx * map.ny, std::numeric_limits<double>::quiet_NaN());
  map.height_resolution = resolution.step();
  std::vector<bool> seen(map.heights.size(), false);
  for (std::size_t k = 0; k < xs.size(); ++k) {
    const std::size_t i = static_cast<std::size_t>(std::llround((xs[k] - ax.origin) / ax.step));
    const std::size_t j = static_cast<std::size_t>(std::llround((ys[k] - ay.origin) / ay.step));
    if (seen[j * map.nx + i])
      fail(path, "two points at the same x, y (" + detail::shortest(xs[k]) + ", " + detail::shortest(ys[k]) + ")");
    seen[j * map.nx + i] = true;
    map.heights[j * map.nx + i] = zs[k];
  }
  const std::size_t absent = map.heights.size() - xs.size();
  if (absent > 0) map.notes.push_back("xyz: " + std::to_string(absent) + " grid points absent from the file (missing)");
  map.notes.push_back("xyz: x and y in " + options.lateral_unit + " (given)");
  ReadOptions heights = options;
  if (heights.height_unit.empty()) heights.height_unit = options.lateral_unit;
  // the pixel size came from the coordinates; a given one overrides it
  detail::apply_overrides(map, heights, true, false, 1.0);
  return map;
}

}  // namespace asperity::topography
