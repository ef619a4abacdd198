// Gwyddion's "ASCII data matrix" export: "# Key: value" header lines, then rows of heights.
// The header gives the field's size (Width, Height), not the point counts: a file cut at a row
// boundary reads as a smaller map, so the pixels the header implies are checked for squareness
// (Gwyddion's fields almost always have square pixels) within the header's printed precision.
#include <cmath>
#include <limits>

#include "asperity/number_text.hpp"
#include "asperity/topography/height_map_io.hpp"
#include "asperity/topography/units.hpp"
#include "input_file.hpp"
#include "reader_support.hpp"

namespace asperity::topography {
namespace {
using detail::fail;
using detail::printable;

constexpr std::size_t bytes_per_point = 40;            // the most text a point can need
constexpr std::size_t max_line_bytes = std::size_t{64} << 20;

// "10.00 µm" -> metres, and the relative precision of its printed digits
double header_length(const std::string& path, const std::string& key, const std::string& value, double& precision) {
  double metres = 0;
  try {
    metres = parse_length(value);
  } catch (const std::exception& error) {
    fail(path, "header '" + key + ": " + printable(value) + "': " + printable(error.what(), 200));
  }
  double number = 0;
  const std::size_t end = read_double_prefix(value, number);  // parse_length read it: a number leads
  if (end == 0) fail(path, "header '" + key + ": " + printable(value) + "': no number before the unit");
  number = std::fabs(number);
  precision = number > 0 ? 0.5 * detail::last_digit_value(value.substr(0, end)) / number : 1;
  return metres;
}
}  // namespace

HeightMap read_ascii_matrix(const std::string& path, const ReadOptions& options) {
  detail::InputFile file(path, bytes_per_point * std::uint64_t{options.max_points} + (std::uint64_t{1} << 20));
  detail::LineReader lines(file, max_line_bytes);
  HeightMap map;
  map.source = path;
  map.format = "ascii-matrix";
  double width = 0, height = 0, value_unit = 0, width_precision = 1, height_precision = 1;
  detail::DecimalResolution resolution;
  std::string line;
  bool data_started = false;
  while (lines.next(line)) {
    const std::string_view text = detail::trim(line);
    if (text.empty()) continue;
    if (text.front() == '#') {
      if (data_started)
        fail(path, "line " + std::to_string(lines.line_number()) + ": a header line after the data");
      const std::string_view body = detail::trim(text.substr(1));
      const std::size_t colon = body.find(':');
      if (colon == std::string_view::npos) continue;  // a comment
      const std::string key(detail::trim(body.substr(0, colon)));
      const std::string value(detail::trim(body.substr(colon + 1)));
      if (key == "Width") width = header_length(path, key, value, width_precision);
      else if (key == "Height") height = header_length(path, key, value, height_precision);
      else if (key == "Value units") {
        try {
          value_unit = length_unit_in_metres(value);
        } catch (const Error&) {
          fail(path, "header 'Value units: " + printable(value) +
                         "': not a length unit (only height maps are analysed)");
        }
      } else if (key == "Channel") map.notes.push_back("channel: " + printable(value));
      continue;
    }
    data_started = true;
    std::size_t count = 0, start = 0;
    while (start < text.size()) {
      const std::size_t end = text.find_first_of(" \t", start);
      const std::string_view token = text.substr(start, end == std::string_view::npos ? std::string_view::npos : end - start);
      start = end == std::string_view::npos ? text.size() : text.find_first_not_of(" \t", end);
      if (start == std::string_view::npos) start = text.size();
      double value = 0;
      if (detail::is_nan_token(token)) {
        value = std::numeric_limits<double>::quiet_NaN();
      } else if (detail::parse_double(token, value)) {
        resolution.add(token, value);
      } else {
        fail(path, "line " + std::to_string(lines.line_number()) + ", column " + std::to_string(count + 1) + ": '" +
                       printable(token) + "' is not a number" +
                       (token.find(',') != std::string_view::npos ? " (a decimal comma? export with a decimal dot)" : ""));
      }
      if (map.heights.size() >= options.max_points)
        fail(path, "holds more than " + std::to_string(options.max_points) + " points (ReadOptions::max_points)");
      map.heights.push_back(value);
      ++count;
    }
    if (map.ny == 0) {
      map.nx = count;
      // the first row's text tells about how many rows the file holds: reserve once
      const std::uint64_t rows = file.size() / (line.size() + 1) + 2;
      map.heights.reserve(static_cast<std::size_t>(std::min<std::uint64_t>(options.max_points, rows * count)));
    } else if (count != map.nx)
      fail(path, "line " + std::to_string(lines.line_number()) + " has " + std::to_string(count) +
                     " values; the first row has " + std::to_string(map.nx));
    ++map.ny;
  }
  if (map.ny == 0) fail(path, "holds no data rows");
  map.height_resolution = resolution.step();
  const bool has_size = width > 0 && height > 0;
  const bool given_pixel = options.pixel_size_x > 0 || options.pixel_size_y > 0;
  if (has_size) {
    map.dx = width / static_cast<double>(map.nx);
    map.dy = height / static_cast<double>(map.ny);
    // a file cut at a row boundary (or a column count that is not the header's) shows as
    // pixels that are not square beyond the header's rounding
    const double tolerance = 2 * (width_precision + height_precision) + 1e-12;
    if (!given_pixel && std::fabs(map.dx / map.dy - 1) > tolerance)
      fail(path, "the header's field of " + detail::shortest(width) + " m x " + detail::shortest(height) +
                     " m over " + std::to_string(map.nx) + " x " + std::to_string(map.ny) +
                     " points gives pixels that are not square (" + detail::shortest(map.dx) + " m x " +
                     detail::shortest(map.dy) +
                     " m): a file cut short (rows missing)? If the pixels really are not square, give "
                     "--pixel-size X,Y");
  } else if (width != 0 || height != 0) {
    fail(path, "the header's Width and Height must both be positive");
  }
  detail::apply_overrides(map, options, has_size, value_unit > 0, value_unit);
  return map;
}

}  // namespace asperity::topography
