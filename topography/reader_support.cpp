#include "reader_support.hpp"

#include <charconv>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "asperity/topography/units.hpp"

namespace asperity::topography::detail {

void fail(const std::string& path, const std::string& problem) { throw Error(path + ": " + problem); }

std::string_view trim(std::string_view text) {
  const char* blanks = " \t\r\n\f\v";
  const std::size_t first = text.find_first_not_of(blanks);
  if (first == std::string_view::npos) return {};
  const std::size_t last = text.find_last_not_of(blanks);
  return text.substr(first, last - first + 1);
}

bool parse_double(std::string_view token, double& out) {
  token = trim(token);
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  if (token.empty() || token.front() == '+') return false;
  double value = 0;
  const auto result = std::from_chars(token.data(), token.data() + token.size(), value);
  if (result.ec != std::errc() || result.ptr != token.data() + token.size() || !std::isfinite(value)) return false;
  out = value;
  return true;
}

bool is_nan_token(std::string_view token) {
  token = trim(token);
  if (!token.empty() && (token.front() == '-' || token.front() == '+')) token.remove_prefix(1);
  if (token.size() != 3) return false;
  return (token[0] == 'n' || token[0] == 'N') && (token[1] == 'a' || token[1] == 'A') &&
         (token[2] == 'n' || token[2] == 'N');
}

bool parse_size(std::string_view token, std::uint64_t limit, std::uint64_t& out) {
  token = trim(token);
  if (token.empty()) return false;
  std::uint64_t value = 0;
  const auto result = std::from_chars(token.data(), token.data() + token.size(), value);
  if (result.ec != std::errc() || result.ptr != token.data() + token.size() || value == 0 || value > limit)
    return false;
  out = value;
  return true;
}

std::uint64_t file_size_of(const std::string& path) {
  std::error_code error;
  const auto status = std::filesystem::status(path, error);
  if (error || !std::filesystem::exists(status)) fail(path, "cannot open (no such file)");
  if (!std::filesystem::is_regular_file(status)) fail(path, "not a regular file");
  const std::uint64_t size = std::filesystem::file_size(path, error);
  if (error) fail(path, "cannot read its size: " + error.message());
  return size;
}

std::vector<unsigned char> read_file_prefix(const std::string& path, std::size_t count) {
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(path, "cannot open");
  std::vector<unsigned char> bytes(count);
  in.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(count));
  if (in.bad()) fail(path, "read error");
  bytes.resize(static_cast<std::size_t>(in.gcount()));
  return bytes;
}

namespace {
std::uint32_t load_le_u32(const unsigned char* b) noexcept {
  return std::uint32_t{b[0]} | std::uint32_t{b[1]} << 8 | std::uint32_t{b[2]} << 16 | std::uint32_t{b[3]} << 24;
}
std::uint64_t load_le_u64(const unsigned char* b) noexcept {
  return std::uint64_t{load_le_u32(b)} | std::uint64_t{load_le_u32(b + 4)} << 32;
}
}  // namespace

double load_le_float32(const unsigned char* bytes) noexcept {
  const std::uint32_t bits = load_le_u32(bytes);
  float value;
  std::memcpy(&value, &bits, sizeof value);
  return value;
}
double load_le_float64(const unsigned char* bytes) noexcept {
  const std::uint64_t bits = load_le_u64(bytes);
  double value;
  std::memcpy(&value, &bits, sizeof value);
  return value;
}
std::int32_t load_le_int32(const unsigned char* bytes) noexcept {
  const std::uint32_t bits = load_le_u32(bytes);
  std::int32_t value;
  std::memcpy(&value, &bits, sizeof value);
  return value;
}
std::int16_t load_le_int16(const unsigned char* bytes) noexcept {
  const std::uint16_t bits = static_cast<std::uint16_t>(bytes[0] | bytes[1] << 8);
  std::int16_t value;
  std::memcpy(&value, &bits, sizeof value);
  return value;
}

namespace {
std::string format_length(double metres) {
  std::ostringstream text;
  text.precision(6);
  text << metres << " m";
  return text.str();
}
}  // namespace

void apply_overrides(HeightMap& map, const ReadOptions& options, bool file_has_pixel_size,
                     bool file_has_height_unit, double file_height_unit_metres) {
  const bool given_pixel = options.pixel_size_x > 0 || options.pixel_size_y > 0;
  if (given_pixel) {
    const double px = options.pixel_size_x > 0 ? options.pixel_size_x : options.pixel_size_y;
    const double py = options.pixel_size_y > 0 ? options.pixel_size_y : px;
    if (!std::isfinite(px) || !std::isfinite(py)) fail(map.source, "the given pixel size is not finite");
    map.notes.push_back(std::string("sampling intervals ") + format_length(px) + " x " + format_length(py) +
                        (file_has_pixel_size ? " from the command line (overriding the file's " +
                                                   format_length(map.dx) + " x " + format_length(map.dy) + ")"
                                             : " from the command line (the file has none)"));
    map.dx = px;
    map.dy = py;
  } else if (!file_has_pixel_size) {
    fail(map.source, "the file gives no pixel size: give one (--pixel-size, e.g. 1.5um)");
  } else {
    map.notes.push_back("sampling intervals " + format_length(map.dx) + " x " + format_length(map.dy) +
                        " from the file");
  }
  double scale = 1;
  if (!options.height_unit.empty()) {
    // the file's numbers are read in the given unit
    scale = length_unit_in_metres(options.height_unit);
    map.notes.push_back("heights in " + options.height_unit + " from the command line" +
                        (file_has_height_unit ? " (overriding the file's unit)" : " (the file has none)"));
  } else if (!file_has_height_unit) {
    fail(map.source, "the file gives no height unit: give one (--height-unit, e.g. nm)");
  } else {
    scale = file_height_unit_metres;
    map.notes.push_back("height unit from the file (" + format_length(file_height_unit_metres) + " per unit)");
  }
  if (scale != 1)
    for (double& h : map.heights) h *= scale;
}

void check_point_count(const std::string& path, std::uint64_t nx, std::uint64_t ny, std::size_t max_points) {
  if (nx == 0 || ny == 0) fail(path, "the grid is empty (" + std::to_string(nx) + " x " + std::to_string(ny) + ")");
  if (nx > max_points || ny > max_points || nx > max_points / ny)
    fail(path, "claims " + std::to_string(nx) + " x " + std::to_string(ny) + " points, more than the limit of " +
                   std::to_string(max_points) + " (ReadOptions::max_points)");
}

}  // namespace asperity::topography::detail
