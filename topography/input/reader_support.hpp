// Helpers shared by the height-map readers (internal).
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "asperity/error.hpp"
#include "asperity/topography/height_map.hpp"
#include "asperity/topography/height_map_io.hpp"

namespace asperity::topography::detail {

// Throws asperity::Error "PATH: problem", the path made printable.
[[noreturn]] void fail(const std::string& path, const std::string& problem);

// Text from a file (or a path), made safe to show on a terminal (an escape sequence in a file must
// not reach the user's terminal): terminal_text(quote_text(text, limit)), number_text.hpp's rule.
std::string printable(std::string_view text, std::size_t limit = 80);

// A number for a message, in the shortest form that reads back to it ("1e-200", "3.5e-07").
std::string shortest(double value);

std::string_view trim(std::string_view text);
// A whole token as a finite double (C locale, '+' allowed); false otherwise.
bool parse_double(std::string_view token, double& out);
// "nan" / "NaN" / "-nan" (case-insensitive): a missing point.
bool is_nan_token(std::string_view token);
// A whole token as a positive integer no larger than limit; false otherwise.
bool parse_size(std::string_view token, std::uint64_t limit, std::uint64_t& out);

// Little-endian decoding, independent of the host's byte order.
double load_le_float32(const unsigned char* bytes) noexcept;
float load_le_float32_exact(const unsigned char* bytes) noexcept;
double load_le_float64(const unsigned char* bytes) noexcept;
std::int32_t load_le_int32(const unsigned char* bytes) noexcept;
std::int16_t load_le_int16(const unsigned char* bytes) noexcept;

// The metres in a unit read from the file (`what` quotes where), or fail naming the file.
double unit_in_metres(const std::string& path, const std::string& what, std::string_view unit);

// Rounding steps of stored heights (HeightMap::height_resolution): the spacing of floats or
// doubles at the largest magnitude stored.
double float32_spacing(float largest_magnitude) noexcept;
double float64_spacing(double largest_magnitude) noexcept;

// The rounding step of numbers written as text: the writer's significant digits S (the most any
// token shows: "%g" drops trailing zeros, so one token may show fewer) at the largest magnitude
// written, 10^(E - S + 1) with E its decimal exponent. "1.8823e-008" ... "2.4022e-007": 1e-11;
// "%.3f" numbers up to 123.456: 1e-3.
class DecimalResolution {
 public:
  void add(std::string_view token, double value) noexcept;
  double step() const noexcept;  // 0 before any nonzero number

 private:
  int digits_ = 0;
  double largest_ = 0;
};
// The place value of a decimal number's last digit as written ("10.00": 0.01).
double last_digit_value(std::string_view token) noexcept;

// Applies ReadOptions' pixel-size and unit overrides after a reader has filled the map from the
// file, and notes what came from where. `file_has_pixel_size` / `file_has_height_unit`: the
// file said it; otherwise the option is required.
void apply_overrides(HeightMap& map, const ReadOptions& options, bool file_has_pixel_size,
                     bool file_has_height_unit, double file_height_unit_metres);

// Counts points against ReadOptions::max_points before anything is allocated for them.
void check_point_count(const std::string& path, std::uint64_t nx, std::uint64_t ny, std::size_t max_points);

}  // namespace asperity::topography::detail
