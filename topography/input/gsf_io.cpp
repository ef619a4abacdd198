// Gwyddion Simple Field (.gsf): magic line, "Key = value" header, 1-4 NUL bytes aligning the
// data to a multiple of 4, then XRes x YRes little-endian float32, row by row, x fastest.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>

#include "asperity/output.hpp"
#include "asperity/topography/height_map_io.hpp"
#include "asperity/topography/units.hpp"
#include "input_file.hpp"
#include "reader_support.hpp"

namespace asperity::topography {
namespace {
using detail::fail;
constexpr char magic[] = "Gwyddion Simple Field 1.0\n";
constexpr std::size_t magic_size = sizeof(magic) - 1;
constexpr std::size_t max_header_bytes = std::size_t{1} << 20;
}  // namespace

HeightMap read_gsf(const std::string& path, const ReadOptions& options) {
  // the header (at most 1 MiB) and 4 bytes a point
  detail::InputFile file(path, max_header_bytes + 4 * std::uint64_t{options.max_points});
  const std::uint64_t file_size = file.size();
  std::vector<unsigned char> head(static_cast<std::size_t>(std::min<std::uint64_t>(file_size, max_header_bytes)));
  file.read_at(0, head.data(), head.size());
  if (head.size() < magic_size || std::memcmp(head.data(), magic, magic_size) != 0)
    fail(path, "not a Gwyddion Simple Field file (no 'Gwyddion Simple Field 1.0' line)");
  std::size_t nul = magic_size;
  while (nul < head.size() && head[nul] != 0) ++nul;
  if (nul == head.size())
    fail(path, head.size() < max_header_bytes ? "the header is truncated (no NUL padding after it)"
                                              : "the header is longer than 1 MiB");
  // data start: the next multiple of 4 after the header, with at least one NUL
  const std::size_t data_start = nul + (4 - nul % 4);
  for (std::size_t k = nul; k < data_start; ++k)
    if (k >= head.size() || head[k] != 0) fail(path, "the header's NUL padding is truncated or wrong");

  std::map<std::string, std::string> fields;
  const std::string_view header(reinterpret_cast<const char*>(head.data()) + magic_size, nul - magic_size);
  int line_number = 1;
  for (std::size_t start = 0; start < header.size();) {
    const std::size_t end = std::min(header.find('\n', start), header.size());
    const std::string_view line = header.substr(start, end - start);
    start = end + 1;
    ++line_number;
    if (detail::trim(line).empty()) continue;
    const std::size_t equals = line.find('=');
    if (equals == std::string_view::npos)
      fail(path, "header line " + std::to_string(line_number) + " is not 'name = value': '" +
                     detail::printable(line) + "'");
    fields[std::string(detail::trim(line.substr(0, equals)))] = std::string(detail::trim(line.substr(equals + 1)));
  }
  std::uint64_t xres = 0, yres = 0;
  for (const auto& [key, out] : {std::pair<const char*, std::uint64_t*>{"XRes", &xres}, {"YRes", &yres}}) {
    const auto found = fields.find(key);
    if (found == fields.end()) fail(path, std::string("the header has no ") + key);
    if (!detail::parse_size(found->second, std::numeric_limits<std::uint32_t>::max(), *out))
      fail(path, std::string(key) + " is not a positive integer ('" + detail::printable(found->second) + "')");
  }
  detail::check_point_count(path, xres, yres, options.max_points);
  const std::uint64_t expected = data_start + 4 * xres * yres;
  if (file_size != expected)
    fail(path, "holds " + std::to_string(file_size) + " bytes; its header (" + std::to_string(xres) + " x " +
                   std::to_string(yres) + " float32) needs " + std::to_string(expected) +
                   (file_size < expected ? ": truncated" : ": extra bytes at the end"));

  HeightMap map;
  map.source = path;
  map.format = "gsf";
  map.nx = static_cast<std::size_t>(xres);
  map.ny = static_cast<std::size_t>(yres);
  const auto unit_of = [&](const char* key) {
    const auto found = fields.find(key);
    if (found == fields.end()) {
      map.notes.push_back(std::string("GSF: no ") + key + ", metres assumed (Gwyddion's base unit)");
      return 1.0;
    }
    return detail::unit_in_metres(path, std::string(key) + " = " + found->second, found->second);
  };
  const double lateral_unit = unit_of("XYUnits");
  const double height_unit = unit_of("ZUnits");
  const auto xreal = fields.find("XReal"), yreal = fields.find("YReal");
  const bool has_size = xreal != fields.end() && yreal != fields.end();
  if (has_size) {
    double x = 0, y = 0;
    if (!detail::parse_double(xreal->second, x) || !(x > 0) || !detail::parse_double(yreal->second, y) || !(y > 0))
      fail(path, "XReal and YReal must be positive numbers");
    map.dx = x * lateral_unit / static_cast<double>(xres);
    map.dy = y * lateral_unit / static_cast<double>(yres);
  }
  if (const auto title = fields.find("Title"); title != fields.end())
    map.notes.push_back("channel: " + detail::printable(title->second));

  // the points in blocks: no second copy of the data in memory
  map.heights.resize(map.nx * map.ny);
  std::vector<unsigned char> block(std::size_t{1} << 20);
  float largest = 0;
  for (std::size_t k = 0; k < map.heights.size();) {
    const std::size_t count = std::min(block.size() / 4, map.heights.size() - k);
    file.read_at(data_start + 4 * std::uint64_t{k}, block.data(), 4 * count);
    for (std::size_t m = 0; m < count; ++m, ++k) {
      const float value = detail::load_le_float32_exact(block.data() + 4 * m);
      if (std::isinf(value)) fail(path, "an infinite height at point " + std::to_string(k));
      if (!std::isnan(value)) largest = std::max(largest, std::fabs(value));
      map.heights[k] = value;
    }
  }
  map.height_resolution = detail::float32_spacing(largest);
  detail::apply_overrides(map, options, has_size, true, height_unit);
  return map;
}

void write_gsf(const HeightMap& map, const std::string& path, bool overwrite) {
  std::ostringstream header;
  header.precision(17);
  header << magic << "XRes = " << map.nx << "\nYRes = " << map.ny << "\nXReal = " << map.width()
         << "\nYReal = " << map.length() << "\nXYUnits = m\nZUnits = m\n";
  std::string text = header.str();
  text.append(4 - text.size() % 4, '\0');
  std::vector<unsigned char> data(4 * map.heights.size());
  for (std::size_t k = 0; k < map.heights.size(); ++k) {
    const float value = static_cast<float>(map.heights[k]);
    std::uint32_t bits;
    std::memcpy(&bits, &value, 4);
    for (int b = 0; b < 4; ++b) data[4 * k + b] = static_cast<unsigned char>(bits >> (8 * b));
  }
  text.append(reinterpret_cast<const char*>(data.data()), data.size());
  write_output_file(path, text, output_kinds::gsf_height_map, overwrite);
}

}  // namespace asperity::topography
