// ISO 25178-72 X3P (the openGPS ISO5436_2 schema): a zip with main.xml and the point data.
#include <zip.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <pugixml.hpp>

#include "asperity/topography/height_map_io.hpp"
#include "md5.hpp"
#include "reader_support.hpp"

namespace asperity::topography {
namespace {
using detail::fail;

constexpr std::size_t max_main_xml_bytes = std::size_t{64} << 20;  // inline DataList up to ~2 M points

struct ZipCloser {
  void operator()(zip_t* archive) const noexcept { zip_discard(archive); }
};
struct ZipFileCloser {
  void operator()(zip_file_t* file) const noexcept { zip_fclose(file); }
};
using Archive = std::unique_ptr<zip_t, ZipCloser>;

Archive open_archive(const std::string& path) {
  int code = 0;
  zip_t* archive = zip_open(path.c_str(), ZIP_RDONLY | ZIP_CHECKCONS, &code);
  if (!archive) {
    zip_error_t error;
    zip_error_init_with_code(&error, code);
    const std::string message = zip_error_strerror(&error);
    zip_error_fini(&error);
    fail(path, "not a readable X3P (zip) file: " + message);
  }
  return Archive(archive);
}

// One entry of the archive, whole, refusing more than max_bytes; `expected` (if not 0) must
// be its exact size. Reading to the end makes libzip check the entry's CRC.
std::vector<unsigned char> read_entry(const std::string& path, zip_t* archive, const std::string& name,
                                      std::size_t max_bytes, std::size_t expected) {
  zip_stat_t stat;
  zip_stat_init(&stat);
  if (zip_stat(archive, name.c_str(), 0, &stat) != 0) fail(path, "the archive has no '" + name + "'");
  if (!(stat.valid & ZIP_STAT_SIZE)) fail(path, "'" + name + "' has no size in the archive");
  if (expected != 0 && stat.size != expected)
    fail(path, "'" + name + "' holds " + std::to_string(stat.size) + " bytes; main.xml's sizes need " +
                   std::to_string(expected));
  if (stat.size > max_bytes)
    fail(path, "'" + name + "' is " + std::to_string(stat.size) + " bytes, more than the limit of " +
                   std::to_string(max_bytes));
  std::unique_ptr<zip_file_t, ZipFileCloser> file(zip_fopen(archive, name.c_str(), 0));
  if (!file) fail(path, "cannot open '" + name + "' in the archive: " + zip_strerror(archive));
  std::vector<unsigned char> bytes(static_cast<std::size_t>(stat.size));
  std::size_t filled = 0;
  while (filled < bytes.size()) {
    const zip_int64_t got = zip_fread(file.get(), bytes.data() + filled, bytes.size() - filled);
    if (got < 0) fail(path, "cannot read '" + name + "': " + zip_file_strerror(file.get()));
    if (got == 0) break;
    filled += static_cast<std::size_t>(got);
  }
  if (filled < bytes.size())
    fail(path, "'" + name + "' is truncated: " + std::to_string(filled) + " of " + std::to_string(bytes.size()) +
                   " bytes");
  unsigned char extra;
  const zip_int64_t more = zip_fread(file.get(), &extra, 1);
  if (more < 0) fail(path, "cannot read '" + name + "': " + zip_file_strerror(file.get()));
  if (more > 0) fail(path, "'" + name + "' holds more bytes than the archive says");
  return bytes;
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
    fail(path, std::string("main.xml: ") + what + " is not a finite number ('" + text_of(node) + "')");
  return value;
}

std::string lower(std::string text) {
  for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

void verify_md5(const std::string& path, const std::vector<unsigned char>& bytes, const std::string& expected,
                const std::string& what, HeightMap& map) {
  if (expected.empty()) {
    map.notes.push_back("X3P: no MD5 checksum for " + what + " (not verified)");
    return;
  }
  const std::string actual = detail::md5_hex(bytes.data(), bytes.size());
  if (lower(expected) != actual)
    fail(path, "MD5 checksum of " + what + " does not match (file says " + expected + ", content is " + actual +
                   "): the file is corrupt");
  map.notes.push_back("X3P: MD5 of " + what + " verified");
}

}  // namespace

HeightMap read_x3p(const std::string& path, const ReadOptions& options) {
  detail::file_size_of(path);
  const Archive archive = open_archive(path);
  HeightMap map;
  map.source = path;
  map.format = "x3p";

  std::vector<unsigned char> xml_bytes = read_entry(path, archive.get(), "main.xml", max_main_xml_bytes, 0);
  // main.xml's own checksum: md5checksum.hex ("<32 hex digits> *main.xml")
  if (zip_name_locate(archive.get(), "md5checksum.hex", 0) >= 0) {
    const std::vector<unsigned char> sum = read_entry(path, archive.get(), "md5checksum.hex", 4096, 0);
    const std::string text(sum.begin(), sum.end());
    const std::string digest = std::string(detail::trim(text.substr(0, std::min<std::size_t>(32, text.size()))));
    if (digest.size() != 32 || !std::all_of(digest.begin(), digest.end(), [](char c) { return std::isxdigit(static_cast<unsigned char>(c)); }))
      fail(path, "md5checksum.hex does not start with an MD5 digest");
    verify_md5(path, xml_bytes, digest, "main.xml", map);
  } else {
    map.notes.push_back("X3P: no md5checksum.hex (main.xml not verified)");
  }

  pugi::xml_document document;
  const pugi::xml_parse_result parsed = document.load_buffer(xml_bytes.data(), xml_bytes.size());
  if (!parsed)
    fail(path, std::string("main.xml is not well-formed XML: ") + parsed.description() + " at byte " +
                   std::to_string(parsed.offset));
  const pugi::xml_node root = document.document_element();
  if (std::strcmp(local_name(root.name()), "ISO5436_2") != 0)
    fail(path, std::string("main.xml's root is '") + root.name() + "', not ISO5436_2");

  const pugi::xml_node record1 = child(path, root, "Record1", "ISO5436_2");
  const std::string feature = text_of(child(path, record1, "FeatureType", "Record1"));
  if (feature != "SUR")
    fail(path, "FeatureType is '" + feature + "': only areal surfaces (SUR) are supported, not profiles or point clouds");
  const pugi::xml_node axes = child(path, record1, "Axes", "Record1");
  const pugi::xml_node cx = child(path, axes, "CX", "Axes"), cy = child(path, axes, "CY", "Axes"),
                       cz = child(path, axes, "CZ", "Axes");
  for (const auto& [axis, name] : {std::pair{cx, "CX"}, std::pair{cy, "CY"}}) {
    const std::string type = text_of(child(path, axis, "AxisType", name));
    if (type != "I")
      fail(path, std::string("axis ") + name + " has AxisType '" + type +
                     "': only incremental axes (I, a regular grid) are supported");
  }
  if (text_of(child(path, cz, "AxisType", "CZ")) != "A") fail(path, "axis CZ must have AxisType A (absolute heights)");
  map.dx = number_of(path, child(path, cx, "Increment", "CX"), "CX Increment");
  map.dy = number_of(path, child(path, cy, "Increment", "CY"), "CY Increment");
  if (!(map.dx > 0) || !(map.dy > 0)) fail(path, "CX/CY Increment must be positive");
  const std::string data_type = text_of(child(path, cz, "DataType", "CZ"));
  std::size_t point_bytes = 0;
  if (data_type == "I") point_bytes = 2;
  else if (data_type == "L") point_bytes = 4;
  else if (data_type == "F") point_bytes = 4;
  else if (data_type == "D") point_bytes = 8;
  else fail(path, "CZ DataType '" + data_type + "' is not one of I, L, F, D");
  double z_increment = 1, z_offset = 0;
  if (const pugi::xml_node node = optional_child(cz, "Increment")) z_increment = number_of(path, node, "CZ Increment");
  if (const pugi::xml_node node = optional_child(cz, "Offset")) z_offset = number_of(path, node, "CZ Offset");

  const pugi::xml_node record3 = child(path, root, "Record3", "ISO5436_2");
  const pugi::xml_node dimension = child(path, record3, "MatrixDimension", "Record3");
  std::uint64_t sizes[3] = {0, 0, 0};
  const char* size_names[3] = {"SizeX", "SizeY", "SizeZ"};
  for (int k = 0; k < 3; ++k) {
    const std::string text = text_of(child(path, dimension, size_names[k], "MatrixDimension"));
    if (!detail::parse_size(text, std::numeric_limits<std::uint32_t>::max(), sizes[k]))
      fail(path, std::string("MatrixDimension/") + size_names[k] + " is not a positive integer ('" + text + "')");
  }
  if (sizes[2] != 1) fail(path, "SizeZ is " + std::to_string(sizes[2]) + ": only one layer of heights is supported");
  detail::check_point_count(path, sizes[0], sizes[1], options.max_points);
  map.nx = static_cast<std::size_t>(sizes[0]);
  map.ny = static_cast<std::size_t>(sizes[1]);
  const std::size_t n = map.nx * map.ny;

  std::vector<unsigned char> valid;  // one bit per point, least significant first; empty: all valid
  if (const pugi::xml_node link = optional_child(record3, "DataLink")) {
    const std::string data_name = text_of(child(path, link, "PointDataLink", "DataLink"));
    const std::vector<unsigned char> bytes = read_entry(path, archive.get(), data_name, n * point_bytes, n * point_bytes);
    const pugi::xml_node sum = optional_child(link, "MD5ChecksumPointData");
    verify_md5(path, bytes, sum ? text_of(sum) : std::string(), "the point data (" + data_name + ")", map);
    map.heights.resize(n);
    for (std::size_t k = 0; k < n; ++k) {
      const unsigned char* p = bytes.data() + k * point_bytes;
      double raw = 0;
      if (data_type == "I") raw = detail::load_le_int16(p);
      else if (data_type == "L") raw = detail::load_le_int32(p);
      else if (data_type == "F") raw = detail::load_le_float32(p);
      else raw = detail::load_le_float64(p);
      map.heights[k] = std::isnan(raw) ? raw : z_increment * raw + z_offset;
    }
    if (const pugi::xml_node valid_link = optional_child(link, "ValidPointsLink")) {
      const std::string valid_name = text_of(valid_link);
      valid = read_entry(path, archive.get(), valid_name, (n + 7) / 8, (n + 7) / 8);
      const pugi::xml_node valid_sum = optional_child(link, "MD5ChecksumValidPoints");
      verify_md5(path, valid, valid_sum ? text_of(valid_sum) : std::string(), "the valid-points mask (" + valid_name + ")", map);
    }
  } else if (const pugi::xml_node list = optional_child(record3, "DataList")) {
    map.heights.reserve(n);
    for (pugi::xml_node datum = list.first_child(); datum; datum = datum.next_sibling()) {
      if (datum.type() != pugi::node_element || std::strcmp(local_name(datum.name()), "Datum") != 0) continue;
      if (map.heights.size() == n) fail(path, "DataList holds more Datum elements than SizeX x SizeY");
      const std::string text = text_of(datum);
      double value = std::numeric_limits<double>::quiet_NaN();  // an empty Datum is a missing point
      if (!text.empty() && !detail::is_nan_token(text)) {
        if (!detail::parse_double(text, value)) fail(path, "DataList: Datum '" + text + "' is not a number");
        value = z_increment * value + z_offset;
      }
      map.heights.push_back(value);
    }
    if (map.heights.size() != n)
      fail(path, "DataList holds " + std::to_string(map.heights.size()) + " Datum elements for " + std::to_string(n) + " points");
    map.notes.push_back("X3P: heights inline (DataList), no checksum of their own");
  } else {
    fail(path, "Record3 has neither DataLink nor DataList");
  }
  if (!valid.empty())
    for (std::size_t k = 0; k < n; ++k)
      if (!(valid[k / 8] & (1u << (k % 8)))) map.heights[k] = std::numeric_limits<double>::quiet_NaN();
  for (double h : map.heights)
    if (std::isinf(h)) fail(path, "an infinite height in the point data");

  if (const pugi::xml_node record2 = optional_child(root, "Record2"))
    if (const pugi::xml_node instrument = optional_child(record2, "Instrument")) {
      std::string what;
      for (const char* key : {"Manufacturer", "Model", "Version"})
        if (const pugi::xml_node node = optional_child(instrument, key)) what += (what.empty() ? "" : ", ") + text_of(node);
      if (!what.empty()) map.notes.push_back("instrument: " + what);
    }
  map.notes.push_back("X3P: axes CX, CY incremental (x fastest), CZ " + data_type + " in metres");
  detail::apply_overrides(map, options, true, true, 1.0);
  return map;
}

}  // namespace asperity::topography
