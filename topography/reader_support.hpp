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

[[noreturn]] void fail(const std::string& path, const std::string& problem);

std::string_view trim(std::string_view text);
// A whole token as a finite double (C locale, '+' allowed); false otherwise.
bool parse_double(std::string_view token, double& out);
// "nan" / "NaN" / "-nan" (case-insensitive): a missing point.
bool is_nan_token(std::string_view token);
// A whole token as a positive integer no larger than limit; false otherwise.
bool parse_size(std::string_view token, std::uint64_t limit, std::uint64_t& out);

// The file's size, or fail (missing, not a regular file).
std::uint64_t file_size_of(const std::string& path);
// The first `count` bytes of the file (all of it when count is larger); fails on a read error.
std::vector<unsigned char> read_file_prefix(const std::string& path, std::size_t count);

// Little-endian decoding, independent of the host's byte order.
double load_le_float32(const unsigned char* bytes) noexcept;
double load_le_float64(const unsigned char* bytes) noexcept;
std::int32_t load_le_int32(const unsigned char* bytes) noexcept;
std::int16_t load_le_int16(const unsigned char* bytes) noexcept;

// Applies ReadOptions' pixel-size and unit overrides after a reader has filled the map from the
// file, and notes what came from where. `file_has_pixel_size` / `file_has_height_unit`: the
// file said it; otherwise the option is required.
void apply_overrides(HeightMap& map, const ReadOptions& options, bool file_has_pixel_size,
                     bool file_has_height_unit, double file_height_unit_metres);

// Counts points against ReadOptions::max_points before anything is allocated for them.
void check_point_count(const std::string& path, std::uint64_t nx, std::uint64_t ny, std::size_t max_points);

}  // namespace asperity::topography::detail
