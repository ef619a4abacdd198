// Gwyddion's "ASCII data matrix" export: "# Key: value" header lines, then rows of heights.
#include <cmath>
#include <fstream>
#include <limits>

#include "asperity/topography/height_map_io.hpp"
#include "asperity/topography/units.hpp"
#include "reader_support.hpp"

namespace asperity::topography {
namespace {
using detail::fail;

// "10.00 µm" -> metres
double header_length(const std::string& path, const std::string& key, const std::string& value) {
  try {
    return parse_length(value);
  } catch (const Error& error) {
    fail(path, "header '" + key + ": " + value + "': " + error.what());
  }
}
}  // namespace

HeightMap read_ascii_matrix(const std::string& path, const ReadOptions& options) {
  const std::uint64_t file_size = detail::file_size_of(path);
  // no more text than the point limit can need (40 characters a point), so a hostile file
  // cannot make us hold more than that
  if (file_size / 40 > options.max_points)
    fail(path, "is " + std::to_string(file_size) + " bytes, more text than " + std::to_string(options.max_points) +
                   " points need (ReadOptions::max_points)");
  std::ifstream in(path);
  if (!in) fail(path, "cannot open");
  HeightMap map;
  map.source = path;
  map.format = "ascii-matrix";
  double width = 0, height = 0, value_unit = 0;
  std::string line;
  std::size_t line_number = 0;
  bool data_started = false;
  while (std::getline(in, line)) {
    ++line_number;
    const std::string_view text = detail::trim(line);
    if (text.empty()) continue;
    if (text.front() == '#') {
      if (data_started) fail(path, "line " + std::to_string(line_number) + ": a header line after the data");
      const std::string_view body = detail::trim(text.substr(1));
      const std::size_t colon = body.find(':');
      if (colon == std::string_view::npos) continue;  // a comment
      const std::string key(detail::trim(body.substr(0, colon)));
      const std::string value(detail::trim(body.substr(colon + 1)));
      if (key == "Width") width = header_length(path, key, value);
      else if (key == "Height") height = header_length(path, key, value);
      else if (key == "Value units") {
        try {
          value_unit = length_unit_in_metres(value);
        } catch (const Error&) {
          fail(path, "header 'Value units: " + value + "': not a length unit (only height maps are analysed)");
        }
      } else if (key == "Channel") map.notes.push_back("channel: " + value);
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
      if (detail::is_nan_token(token)) value = std::numeric_limits<double>::quiet_NaN();
      else if (!detail::parse_double(token, value))
        fail(path, "line " + std::to_string(line_number) + ", column " + std::to_string(count + 1) + ": '" +
                       std::string(token) + "' is not a number" +
                       (token.find(',') != std::string_view::npos ? " (a decimal comma? export with a decimal dot)" : ""));
      map.heights.push_back(value);
      ++count;
      if (map.heights.size() > options.max_points)
        fail(path, "holds more than " + std::to_string(options.max_points) + " points (ReadOptions::max_points)");
    }
    if (map.ny == 0) map.nx = count;
    else if (count != map.nx)
      fail(path, "line " + std::to_string(line_number) + " has " + std::to_string(count) + " values; the first row has " +
                     std::to_string(map.nx));
    ++map.ny;
  }
  if (in.bad()) fail(path, "read error");
  if (map.ny == 0) fail(path, "holds no data rows");
  const bool has_size = width > 0 && height > 0;
  if (has_size) {
    map.dx = width / static_cast<double>(map.nx);
    map.dy = height / static_cast<double>(map.ny);
  } else if (width != 0 || height != 0) {
    fail(path, "the header's Width and Height must both be positive");
  }
  detail::apply_overrides(map, options, has_size, value_unit > 0, value_unit);
  return map;
}

}  // namespace asperity::topography
