#include "reader_support.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>
#include <limits>
#include <sstream>

#include "asperity/number_text.hpp"
#include "asperity/topography/units.hpp"

namespace asperity::topography::detail {

void fail(const std::string& path, const std::string& problem) { throw Error(printable(path, 4096) + ": " + problem); }

std::string shortest(double value) {
  char text[32];
  const auto end = std::to_chars(text, text + sizeof text, value).ptr;
  return std::string(text, end);
}

// The library's one rule for quoting outside text (number_text.hpp): control bytes, DEL, C1
// controls and bytes that are not UTF-8 as \xNN, cut after `limit` bytes.
std::string printable(std::string_view text, std::size_t limit) { return terminal_text(quote_text(text, limit)); }

std::string_view trim(std::string_view text) {
  const char* blanks = " \t\r\n\f\v";
  const std::size_t first = text.find_first_not_of(blanks);
  if (first == std::string_view::npos) return {};
  const std::size_t last = text.find_last_not_of(blanks);
  return text.substr(first, last - first + 1);
}

bool parse_double(std::string_view token, double& out) {
  double value = 0;
  if (!read_double(trim(token), value) || !std::isfinite(value)) return false;
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
  constexpr std::uint64_t largest = static_cast<std::uint64_t>(std::numeric_limits<long long>::max());
  long long value = 0;
  if (!read_whole_number(trim(token), 1, static_cast<long long>(std::min(limit, largest)), value)) return false;
  out = static_cast<std::uint64_t>(value);
  return true;
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
float load_le_float32_exact(const unsigned char* bytes) noexcept {
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

double unit_in_metres(const std::string& path, const std::string& what, std::string_view unit) {
  try {
    return length_unit_in_metres(unit);
  } catch (const Error& error) {
    fail(path, "'" + printable(what) + "': " + printable(error.what(), 200));
  }
}

double float32_spacing(float largest_magnitude) noexcept {
  const float next = std::nextafter(largest_magnitude, std::numeric_limits<float>::infinity());
  return static_cast<double>(next) - static_cast<double>(largest_magnitude);
}

double float64_spacing(double largest_magnitude) noexcept {
  return std::nextafter(largest_magnitude, std::numeric_limits<double>::infinity()) - largest_magnitude;
}

void DecimalResolution::add(std::string_view token, double value) noexcept {
  int digits = 0;
  bool leading = true;
  for (const char c : token) {
    if (c == 'e' || c == 'E') break;
    if (c < '0' || c > '9') continue;
    if (leading && c == '0') continue;
    leading = false;
    ++digits;
  }
  digits_ = std::max(digits_, digits);
  largest_ = std::max(largest_, std::fabs(value));
}

double DecimalResolution::step() const noexcept {
  if (!(largest_ > 0) || digits_ == 0) return 0;
  const double exponent = std::floor(std::log10(largest_));
  return std::pow(10.0, exponent - digits_ + 1);
}

double last_digit_value(std::string_view token) noexcept {
  // digits after the point, and the exponent
  std::size_t k = 0;
  if (k < token.size() && (token[k] == '+' || token[k] == '-')) ++k;
  long decimals = 0;
  bool after_point = false;
  for (; k < token.size(); ++k) {
    const char c = token[k];
    if (c == '.') after_point = true;
    else if (c >= '0' && c <= '9') decimals += after_point ? 1 : 0;
    else break;
  }
  long exponent = 0;
  if (k < token.size() && (token[k] == 'e' || token[k] == 'E')) {
    ++k;
    bool negative = false;
    if (k < token.size() && (token[k] == '+' || token[k] == '-')) negative = token[k++] == '-';
    for (; k < token.size() && token[k] >= '0' && token[k] <= '9' && exponent < 100000; ++k)
      exponent = 10 * exponent + (token[k] - '0');
    if (negative) exponent = -exponent;
  }
  return std::pow(10.0, static_cast<double>(exponent - decimals));
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
  if (scale != 1) {
    for (double& h : map.heights) h *= scale;
    map.height_resolution *= scale;
  }
}

void check_point_count(const std::string& path, std::uint64_t nx, std::uint64_t ny, std::size_t max_points) {
  if (nx == 0 || ny == 0) fail(path, "the grid is empty (" + std::to_string(nx) + " x " + std::to_string(ny) + ")");
  if (nx > max_points || ny > max_points || nx > max_points / ny)
    fail(path, "claims " + std::to_string(nx) + " x " + std::to_string(ny) + " points, more than the limit of " +
                   std::to_string(max_points) + " (ReadOptions::max_points)");
}

}  // namespace asperity::topography::detail
