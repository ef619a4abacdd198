// ISO 25178-72 X3P (the openGPS ISO5436_2 schema): a zip with main.xml and the point data.
//
// Bounded whatever the bytes: main.xml at most 64 MiB and 2^21 elements (counted before
// pugixml builds its tree: a 97 KB zip can inflate to 16 M elements), its tree freed before
// the points are read; the points streamed from the archive in blocks (MD5 as they come), so
// memory is the heights (8 bytes a point), the valid-point mask (1 bit a point) and the tree.
#include <unistd.h>
#include <zip.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <pugixml.hpp>

#include "asperity/topography/height_map_io.hpp"
#include "input_file.hpp"
#include "md5.hpp"
#include "reader_support.hpp"

namespace asperity::topography {
namespace {
using detail::fail;
using detail::printable;

constexpr std::size_t max_main_xml_bytes = std::size_t{64} << 20;
constexpr std::size_t max_main_xml_elements = std::size_t{1} << 21;  // inline DataList up to ~2 M points

struct ZipCloser {
  void operator()(zip_t* archive) const noexcept { zip_discard(archive); }
};
struct ZipFileCloser {
  void operator()(zip_file_t* file) const noexcept { zip_fclose(file); }
};
using Archive = std::unique_ptr<zip_t, ZipCloser>;
using Entry = std::unique_ptr<zip_file_t, ZipFileCloser>;

// The archive on the checked descriptor (libzip owns a duplicate of it).
Archive open_archive(const detail::InputFile& file) {
  const int fd = ::dup(file.descriptor());
  if (fd < 0) fail(file.path(), "cannot open (no descriptor left)");
  int code = 0;
  zip_t* archive = zip_fdopen(fd, ZIP_CHECKCONS, &code);
  if (!archive) {
    ::close(fd);
    zip_error_t error;
    zip_error_init_with_code(&error, code);
    const std::string message = zip_error_strerror(&error);
    zip_error_fini(&error);
    fail(file.path(), "not a readable X3P (zip) file: " + message);
  }
  return Archive(archive);
}

// One entry, opened after its size is checked: at most max_bytes; `expected` (if not 0) must
// be its exact size.
Entry open_entry(const std::string& path, zip_t* archive, const std::string& name, std::uint64_t max_bytes,
                 std::uint64_t expected, std::uint64_t& size) {
  zip_stat_t stat;
  zip_stat_init(&stat);
  if (zip_stat(archive, name.c_str(), 0, &stat) != 0) fail(path, "the archive has no '" + printable(name) + "'");
  if (!(stat.valid & ZIP_STAT_SIZE)) fail(path, "'" + printable(name) + "' has no size in the archive");
  if (expected != 0 && stat.size != expected)
    fail(path, "'" + printable(name) + "' holds " + std::to_string(stat.size) + " bytes; main.xml's sizes need " +
                   std::to_string(expected));
  if (stat.size > max_bytes)
    fail(path, "'" + printable(name) + "' is " + std::to_string(stat.size) + " bytes, more than the limit of " +
                   std::to_string(max_bytes));
  Entry entry(zip_fopen(archive, name.c_str(), 0));
  if (!entry) fail(path, "cannot open '" + printable(name) + "' in the archive: " + zip_strerror(archive));
  size = stat.size;
  return entry;
}

// Reads an entry to its end in blocks, handing each to `consume`; checks that it holds exactly
// `size` bytes (reading to the end makes libzip check the CRC).
template <class Consume>
void stream_entry(const std::string& path, const std::string& name, zip_file_t* entry, std::uint64_t size,
                  Consume consume) {
  std::vector<unsigned char> block(static_cast<std::size_t>(std::min<std::uint64_t>(size, std::uint64_t{1} << 20)) + 1);
  std::uint64_t filled = 0;
  for (;;) {
    const std::uint64_t wanted = std::min<std::uint64_t>(block.size() - 1, size - filled);
    const zip_int64_t got = zip_fread(entry, block.data(), wanted == 0 ? 1 : wanted);
    if (got < 0) fail(path, "cannot read '" + printable(name) + "': " + zip_file_strerror(entry));
    if (got == 0) break;
    if (wanted == 0) fail(path, "'" + printable(name) + "' holds more bytes than the archive says");
    consume(block.data(), static_cast<std::size_t>(got), filled);
    filled += static_cast<std::uint64_t>(got);
  }
  if (filled < size)
    fail(path, "'" + printable(name) + "' is truncated: " + std::to_string(filled) + " of " + std::to_string(size) +
                   " bytes");
}

std::vector<unsigned char> read_entry(const std::string& path, zip_t* archive, const std::string& name,
                                      std::uint64_t max_bytes, std::uint64_t expected) {
  std::uint64_t size = 0;
  const Entry entry = open_entry(path, archive, name, max_bytes, expected, size);
  std::vector<unsigned char> bytes(static_cast<std::size_t>(size));
  stream_entry(path, name, entry.get(), size, [&](const unsigned char* data, std::size_t count, std::uint64_t at) {
    std::memcpy(bytes.data() + at, data, count);
  });
  return bytes;
}

// Elements in an XML text, counted before a tree is built for them: '<' not followed by '/',
// '!' or '?' (a '<' inside an attribute value is not well-formed XML, so this never
// undercounts what pugixml would build).
std::size_t count_elements(const std::vector<unsigned char>& xml) {
  std::size_t count = 0;
  for (std::size_t k = 0; k + 1 < xml.size(); ++k)
    if (xml[k] == '<' && xml[k + 1] != '/' && xml[k + 1] != '!' && xml[k + 1] != '?') ++count;
  return count;
}

// Children of the ISO5436_2 records are unqualified; the root carries a namespace prefix.
const char* local_name(const char* name) {
  const char* colon = std::strrchr(name, ':');
  return colon ? colon + 1 : name;
}

pugi::xml_node child(const std::string& path, pugi::xml_node node, const char* name, const char* where) {
  for (pugi::xml_node c = node.first_child(); c; c = c.next_sibling())
    if (c.type() == pugi::node_element && std::strcmp(local_name(c.name()), name) == 0) return c;
  fail(path, std::string("main.xml has no ") + where + "/" + name);
}

pugi::xml_node optional_child(pugi::xml_node node, const char* name) {
  for (pugi::xml_node c = node.first_child(); c; c = c.next_sibling())
    if (c.type() == pugi::node_element && std::strcmp(local_name(c.name()), name) == 0) return c;
  return {};
}

std::string text_of(pugi::xml_node node) { return std::string(detail::trim(node.text().as_string())); }

double number_of(const std::string& path, pugi::xml_node node, const char* what) {
  double value = 0;
  if (!detail::parse_double(text_of(node), value))
    fail(path, std::string("main.xml: ") + what + " is not a finite number ('" + printable(text_of(node)) + "')");
  return value;
}

std::string lower(std::string text) {
  for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

void check_md5(const std::string& path, const std::string& actual, const std::string& expected, const std::string& what,
               HeightMap& map) {
  if (expected.empty()) {
    map.notes.push_back("X3P: no MD5 checksum for " + what + " (not verified)");
    return;
  }
  if (lower(expected) != actual)
    fail(path, "MD5 checksum of " + what + " does not match (file says " + printable(expected) + ", content is " +
                   actual + "): the file is corrupt");
  map.notes.push_back("X3P: MD5 of " + what + " verified");
}

// What main.xml says, read out of the tree so that the tree can go before the points come.
struct Description {
  double dx = 0, dy = 0, z_increment = 1, z_offset = 0;
  std::string data_type;
  std::size_t point_bytes = 0, nx = 0, ny = 0;
  bool inline_data = false;
  std::string data_name, data_md5, valid_name, valid_md5;
};

Description describe(const std::string& path, zip_t* archive, const ReadOptions& options, HeightMap& map) {
  std::vector<unsigned char> xml_bytes = read_entry(path, archive, "main.xml", max_main_xml_bytes, 0);
  // main.xml's own checksum: md5checksum.hex ("<32 hex digits> *main.xml")
  if (zip_name_locate(archive, "md5checksum.hex", 0) >= 0) {
    const std::vector<unsigned char> sum = read_entry(path, archive, "md5checksum.hex", 4096, 0);
    const std::string text(sum.begin(), sum.end());
    const std::string digest = std::string(detail::trim(text.substr(0, std::min<std::size_t>(32, text.size()))));
    if (digest.size() != 32 ||
        !std::all_of(digest.begin(), digest.end(), [](char c) { return std::isxdigit(static_cast<unsigned char>(c)); }))
      fail(path, "md5checksum.hex does not start with an MD5 digest");
    check_md5(path, detail::md5_hex(xml_bytes.data(), xml_bytes.size()), digest, "main.xml", map);
  } else {
    map.notes.push_back("X3P: no md5checksum.hex (main.xml not verified)");
  }
  const std::size_t elements = count_elements(xml_bytes);
  if (elements > max_main_xml_elements)
    fail(path, "main.xml holds " + std::to_string(elements) + " elements, more than the limit of " +
                   std::to_string(max_main_xml_elements) + " (inline DataList maps beyond ~2 M points are not read)");

  pugi::xml_document document;
  const pugi::xml_parse_result parsed = document.load_buffer_inplace(xml_bytes.data(), xml_bytes.size());
  if (!parsed)
    fail(path, std::string("main.xml is not well-formed XML: ") + parsed.description() + " at byte " +
                   std::to_string(parsed.offset));
  const pugi::xml_node root = document.document_element();
  if (std::strcmp(local_name(root.name()), "ISO5436_2") != 0)
    fail(path, "main.xml's root is '" + printable(root.name()) + "', not ISO5436_2");

  Description d;
  const pugi::xml_node record1 = child(path, root, "Record1", "ISO5436_2");
  const std::string feature = text_of(child(path, record1, "FeatureType", "Record1"));
  if (feature != "SUR")
    fail(path, "FeatureType is '" + printable(feature) +
                   "': only areal surfaces (SUR) are supported, not profiles or point clouds");
  const pugi::xml_node axes = child(path, record1, "Axes", "Record1");
  const pugi::xml_node cx = child(path, axes, "CX", "Axes"), cy = child(path, axes, "CY", "Axes"),
                       cz = child(path, axes, "CZ", "Axes");
  for (const auto& [axis, name] : {std::pair{cx, "CX"}, std::pair{cy, "CY"}}) {
    const std::string type = text_of(child(path, axis, "AxisType", name));
    if (type != "I")
      fail(path, std::string("axis ") + name + " has AxisType '" + printable(type) +
                     "': only incremental axes (I, a regular grid) are supported");
  }
  if (text_of(child(path, cz, "AxisType", "CZ")) != "A") fail(path, "axis CZ must have AxisType A (absolute heights)");
  d.dx = number_of(path, child(path, cx, "Increment", "CX"), "CX Increment");
  d.dy = number_of(path, child(path, cy, "Increment", "CY"), "CY Increment");
  for (const auto& [step, name] : {std::pair{d.dx, "CX"}, std::pair{d.dy, "CY"}})
    if (!(step >= min_sampling_interval && step <= max_sampling_interval))
      fail(path, std::string(name) + " Increment " + detail::shortest(step) + " m is outside [1e-13, 1e3] m (a wrong unit?)");
  d.data_type = text_of(child(path, cz, "DataType", "CZ"));
  if (d.data_type == "I") d.point_bytes = 2;
  else if (d.data_type == "L") d.point_bytes = 4;
  else if (d.data_type == "F") d.point_bytes = 4;
  else if (d.data_type == "D") d.point_bytes = 8;
  else fail(path, "CZ DataType '" + printable(d.data_type) + "' is not one of I, L, F, D");
  if (const pugi::xml_node node = optional_child(cz, "Increment")) d.z_increment = number_of(path, node, "CZ Increment");
  if (const pugi::xml_node node = optional_child(cz, "Offset")) d.z_offset = number_of(path, node, "CZ Offset");
  // the heights' scale: a normal number (a subnormal or zero increment makes every height 0)
  if (!(std::fabs(d.z_increment) >= std::numeric_limits<double>::min() && std::fabs(d.z_increment) <= max_height))
    fail(path, "CZ Increment " + detail::shortest(d.z_increment) + " is not a usable height scale (zero, subnormal or over 1 km)");
  if (!(std::fabs(d.z_offset) <= max_height)) fail(path, "CZ Offset is beyond 1 km");

  const pugi::xml_node record3 = child(path, root, "Record3", "ISO5436_2");
  const pugi::xml_node dimension = child(path, record3, "MatrixDimension", "Record3");
  std::uint64_t sizes[3] = {0, 0, 0};
  const char* size_names[3] = {"SizeX", "SizeY", "SizeZ"};
  for (int k = 0; k < 3; ++k) {
    const std::string text = text_of(child(path, dimension, size_names[k], "MatrixDimension"));
    if (!detail::parse_size(text, std::numeric_limits<std::uint32_t>::max(), sizes[k]))
      fail(path, std::string("MatrixDimension/") + size_names[k] + " is not a positive integer ('" + printable(text) + "')");
  }
  if (sizes[2] != 1) fail(path, "SizeZ is " + std::to_string(sizes[2]) + ": only one layer of heights is supported");
  detail::check_point_count(path, sizes[0], sizes[1], options.max_points);
  d.nx = static_cast<std::size_t>(sizes[0]);
  d.ny = static_cast<std::size_t>(sizes[1]);
  const std::size_t n = d.nx * d.ny;

  if (const pugi::xml_node link = optional_child(record3, "DataLink")) {
    d.data_name = text_of(child(path, link, "PointDataLink", "DataLink"));
    if (const pugi::xml_node sum = optional_child(link, "MD5ChecksumPointData")) d.data_md5 = text_of(sum);
    if (const pugi::xml_node valid_link = optional_child(link, "ValidPointsLink")) {
      d.valid_name = text_of(valid_link);
      if (const pugi::xml_node valid_sum = optional_child(link, "MD5ChecksumValidPoints")) d.valid_md5 = text_of(valid_sum);
    }
  } else if (const pugi::xml_node list = optional_child(record3, "DataList")) {
    d.inline_data = true;
    map.heights.reserve(n);
    detail::DecimalResolution resolution;
    for (pugi::xml_node datum = list.first_child(); datum; datum = datum.next_sibling()) {
      if (datum.type() != pugi::node_element || std::strcmp(local_name(datum.name()), "Datum") != 0) continue;
      if (map.heights.size() == n) fail(path, "DataList holds more Datum elements than SizeX x SizeY");
      const std::string text = text_of(datum);
      double value = std::numeric_limits<double>::quiet_NaN();  // an empty Datum is a missing point
      if (!text.empty() && !detail::is_nan_token(text)) {
        if (!detail::parse_double(text, value)) fail(path, "DataList: Datum '" + printable(text) + "' is not a number");
        resolution.add(text, value);
        value = d.z_increment * value + d.z_offset;
      }
      map.heights.push_back(value);
    }
    if (map.heights.size() != n)
      fail(path, "DataList holds " + std::to_string(map.heights.size()) + " Datum elements for " + std::to_string(n) +
                     " points");
    map.height_resolution = resolution.step() * std::fabs(d.z_increment);
    map.notes.push_back("X3P: heights inline (DataList), no checksum of their own");
  } else {
    fail(path, "Record3 has neither DataLink nor DataList");
  }

  if (const pugi::xml_node record2 = optional_child(root, "Record2"))
    if (const pugi::xml_node instrument = optional_child(record2, "Instrument")) {
      std::string what;
      for (const char* key : {"Manufacturer", "Model", "Version"})
        if (const pugi::xml_node node = optional_child(instrument, key))
          what += (what.empty() ? "" : ", ") + printable(text_of(node));
      if (!what.empty()) map.notes.push_back("instrument: " + what);
    }
  return d;
}

}  // namespace

HeightMap read_x3p(const std::string& path, const ReadOptions& options) {
  // within the limits: the points (8 bytes each at most), their mask, main.xml and a margin
  const std::uint64_t n_max = options.max_points;
  detail::InputFile file(path, 8 * n_max + n_max / 8 + max_main_xml_bytes + (std::uint64_t{1} << 20));
  const Archive archive = open_archive(file);
  HeightMap map;
  map.source = path;
  map.format = "x3p";
  const Description d = describe(path, archive.get(), options, map);  // the XML tree is gone after this
  map.nx = d.nx;
  map.ny = d.ny;
  map.dx = d.dx;
  map.dy = d.dy;
  const std::size_t n = d.nx * d.ny;

  if (!d.inline_data) {
    std::vector<unsigned char> valid;  // one bit a point, least significant first; empty: all valid
    if (!d.valid_name.empty()) {
      valid = read_entry(path, archive.get(), d.valid_name, (std::uint64_t{n} + 7) / 8, (std::uint64_t{n} + 7) / 8);
      check_md5(path, detail::md5_hex(valid.data(), valid.size()), d.valid_md5,
                "the valid-points mask (" + printable(d.valid_name) + ")", map);
    }
    std::uint64_t size = 0;
    const Entry entry = open_entry(path, archive.get(), d.data_name, n * d.point_bytes, n * d.point_bytes, size);
    map.heights.resize(n);
    detail::Md5 md5;
    double largest = 0;  // of the raw values, for the rounding step
    std::vector<unsigned char> carry;  // a point split across blocks
    std::size_t k = 0;
    const auto decode = [&](const unsigned char* p) {
      if (!valid.empty() && !(valid[k / 8] & (1u << (k % 8)))) {
        map.heights[k++] = std::numeric_limits<double>::quiet_NaN();
        return;
      }
      double raw = 0;
      if (d.data_type == "I") raw = detail::load_le_int16(p);
      else if (d.data_type == "L") raw = detail::load_le_int32(p);
      else if (d.data_type == "F") raw = detail::load_le_float32(p);
      else raw = detail::load_le_float64(p);
      if (std::isinf(raw)) fail(path, "an infinite height at point " + std::to_string(k));
      if (!std::isnan(raw)) largest = std::max(largest, std::fabs(raw));
      map.heights[k++] = std::isnan(raw) ? raw : d.z_increment * raw + d.z_offset;
    };
    stream_entry(path, d.data_name, entry.get(), size, [&](const unsigned char* data, std::size_t count, std::uint64_t) {
      md5.update(data, count);
      std::size_t at = 0;
      while (!carry.empty() && at < count) {
        carry.push_back(data[at++]);
        if (carry.size() == d.point_bytes) {
          decode(carry.data());
          carry.clear();
        }
      }
      for (; at + d.point_bytes <= count; at += d.point_bytes) decode(data + at);
      carry.insert(carry.end(), data + at, data + count);
    });
    check_md5(path, md5.hex(), d.data_md5, "the point data (" + printable(d.data_name) + ")", map);
    if (d.data_type == "I" || d.data_type == "L") map.height_resolution = std::fabs(d.z_increment);
    else if (d.data_type == "F") map.height_resolution = detail::float32_spacing(static_cast<float>(largest)) * std::fabs(d.z_increment);
    else map.height_resolution = detail::float64_spacing(largest) * std::fabs(d.z_increment);
  }
  map.notes.push_back("X3P: axes CX, CY incremental (x fastest), CZ " + d.data_type + " in metres");
  detail::apply_overrides(map, options, true, true, 1.0);
  return map;
}

}  // namespace asperity::topography
