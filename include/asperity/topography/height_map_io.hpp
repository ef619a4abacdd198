// Reading measured height maps (untrusted files):
//   ISO 25178-72 X3P  a zip (libzip) holding main.xml (pugixml) and the binary points; axes CX, CY
//                     of type I (incremental: Increment in metres), CZ of type A with DataType
//                     I (int16), L (int32), F (float32) or D (float64), little-endian, x fastest,
//                     scaled by CZ Increment/Offset when present; ValidPointsLink (one bit per
//                     point, least significant first) or NaN mark missing points. The MD5 of the
//                     point data (Record3/DataLink/MD5ChecksumPointData) and of main.xml
//                     (md5checksum.hex) are verified (OpenSSL's libcrypto).
//   Gwyddion .gsf     "Gwyddion Simple Field 1.0\n", "Key = value" lines, 1 to 4 NUL bytes that
//                     align the data to 4 bytes, XRes x YRes float32 little-endian, row by row
//                     (x fastest); XReal/YReal in XYUnits (default m), ZUnits (default m).
//   Gwyddion ASCII    "# Width: 10.00 µm", "# Height: ...", "# Value units: m" (Gwyddion's ASCII
//                     data matrix export, English), then one row of heights per line (x fastest,
//                     first line y = 0); "nan" marks a missing point.
//   xyz / CSV         three columns x y z (blank, comma or semicolon separated, one optional
//                     header line) on a regular grid (at least half of it present); points absent from
//                     the grid are missing.
//                     These carry no units: ReadOptions::lateral_unit / height_unit are required.
// Every error is an asperity::Error naming the file and the problem (truncated, wrong checksum,
// sizes that do not match, an unknown unit, a hostile size: a header is never trusted to
// allocate more than ReadOptions::max_points points, nor more than the file holds).
#pragma once
#include <cstddef>
#include <string>

#include "asperity/topography/height_map.hpp"

namespace asperity::topography {

// The surface formats, the one list (X-macro: X is called once per format, in the order help texts
// list them). Everything that names the formats is made from it: HeightMapFormat's values, the
// table surface_formats() (surface_formats.hpp) and through it read_height_map's choice,
// --format and every help text, the Python enum and its read_ID functions; the fuzz targets
// (fuzz/CMakeLists.txt reads this file: one entry per line starting "X(ID,"). A format's reader
// is read_ID (declared below). Fields:
//   ID          the HeightMapFormat member, the Python name, the fuzz target fuzz_ID
//   NAME        what --format and Python's format= take (and HeightMap::format)
//   ALIASES     (...) other names it answers to
//   MAGIC       the bytes its files start with; nullptr: none (text)
//   EXTENSIONS  (...) lower case, without the dot: the choice by extension when no magic matches
//   NEEDS_UNITS true: its files carry no units (ReadOptions::lateral_unit is required)
//   DESCRIPTION one line, for help texts
// clang-format off
#define ASPERITY_SURFACE_FORMATS(X)                                                                    \
  X(x3p, "x3p", (), "PK\x03\x04", ("x3p"), false,                                                    \
    "ISO 25178-72 XML 3D surface profile (a zip archive)")                                             \
  X(gsf, "gsf", (), "Gwyddion Simple Field", ("gsf"), false, "Gwyddion Simple Field")                  \
  X(ascii_matrix, "ascii-matrix", ("matrix"), nullptr, ("txt", "asc", "dat"), false,                   \
    "a matrix of heights as text (Gwyddion's ASCII export, AFM text dumps)")                           \
  X(xyz, "xyz", ("csv"), nullptr, ("xyz", "csv"), true, "x y z points on a grid, as text")
// clang-format on

#define ASPERITY_SURFACE_FORMAT_ENUMERATOR(id, ...) id,
enum class HeightMapFormat { automatic, ASPERITY_SURFACE_FORMATS(ASPERITY_SURFACE_FORMAT_ENUMERATOR) };
#undef ASPERITY_SURFACE_FORMAT_ENUMERATOR

struct ReadOptions {
  HeightMapFormat format = HeightMapFormat::automatic;  // automatic: by magic bytes, then extension
  // Sampling intervals [m] for formats without them, or overriding the file's (noted in the map).
  double pixel_size_x = 0, pixel_size_y = 0;
  // Units for formats without them ("um", "nm", ...); for the others they override the file's.
  std::string lateral_unit, height_unit;
  std::size_t max_points = std::size_t{1} << 26;  // 67 M points (512 MiB of heights)
};

HeightMap read_height_map(const std::string& path, const ReadOptions& options = {});
// Each format's reader, read_ID (a format without one does not link).
HeightMap read_x3p(const std::string& path, const ReadOptions& options = {});
HeightMap read_gsf(const std::string& path, const ReadOptions& options = {});
HeightMap read_ascii_matrix(const std::string& path, const ReadOptions& options = {});
HeightMap read_xyz(const std::string& path, const ReadOptions& options = {});

// A format's NAME or one of its ALIASES ("x3p", "matrix", ...), or "auto"; false for anything else.
bool parse_height_map_format(const std::string& name, HeightMapFormat& out);

// Writes a height map as .gsf (float32: heights lose digits beyond ~7) under the output policy
// (asperity/output.hpp: a file that is not a .gsf of ours replaced only with `overwrite`). Throws
// on a write error.
void write_gsf(const HeightMap& map, const std::string& path, bool overwrite = false);

}  // namespace asperity::topography
