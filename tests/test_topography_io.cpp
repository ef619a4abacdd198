// Reading measured height maps: the two real surfaces, every format, and every bad file
// (truncated, wrong MD5, wrong sizes, missing points, hostile sizes, bad units).
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>
#include <zip.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include "asperity/error.hpp"
#include "asperity/topography/height_map_io.hpp"
#include "asperity/topography/units.hpp"
#include "input/md5.hpp"

namespace t = asperity::topography;
namespace fs = std::filesystem;

namespace {
const std::string surfaces = ASPERITY_TEST_SURFACES;
const std::string x3p_path = surfaces + "/digitalsurf-650x650.x3p";
const std::string afm_path = surfaces + "/afm-zsensor-10um.txt";

std::string scratch(const std::string& name) {
  const fs::path dir = fs::path(ASPERITY_TEST_BINARY_DIR) / "topography_io";
  fs::create_directories(dir);
  return (dir / name).string();
}

void write_bytes(const std::string& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

std::string read_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// An X3P archive from its parts (libzip); each entry's bytes as given.
void write_zip(const std::string& path, const std::vector<std::pair<std::string, std::string>>& entries) {
  fs::remove(path);
  int code = 0;
  zip_t* archive = zip_open(path.c_str(), ZIP_CREATE | ZIP_TRUNCATE, &code);
  ASSERT_NE(archive, nullptr);
  for (const auto& [name, bytes] : entries) {
    void* copy = std::malloc(bytes.size() + 1);
    std::memcpy(copy, bytes.data(), bytes.size());
    zip_source_t* source = zip_source_buffer(archive, copy, bytes.size(), 1);
    ASSERT_GE(zip_file_add(archive, name.c_str(), source, ZIP_FL_OVERWRITE), 0);
  }
  ASSERT_EQ(zip_close(archive), 0);
}

std::string main_xml(const std::string& size_x, const std::string& size_y, const std::string& data_type,
                     const std::string& md5, const std::string& extra_link = "", const std::string& feature = "SUR",
                     const std::string& cx_type = "I") {
  return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<p:ISO5436_2 xmlns:p=\"http://www.opengps.eu/2008/ISO5436_2\">"
         "<Record1><Revision>ISO5436 - 2000</Revision><FeatureType>" + feature + "</FeatureType><Axes>"
         "<CX><AxisType>" + cx_type + "</AxisType><DataType>D</DataType><Increment>1e-6</Increment><Offset>0</Offset></CX>"
         "<CY><AxisType>I</AxisType><DataType>D</DataType><Increment>2e-6</Increment><Offset>0</Offset></CY>"
         "<CZ><AxisType>A</AxisType><DataType>" + data_type + "</DataType></CZ></Axes></Record1>"
         "<Record3><MatrixDimension><SizeX>" + size_x + "</SizeX><SizeY>" + size_y + "</SizeY><SizeZ>1</SizeZ></MatrixDimension>"
         "<DataLink><PointDataLink>bindata/data.bin</PointDataLink>" +
         (md5.empty() ? "" : "<MD5ChecksumPointData>" + md5 + "</MD5ChecksumPointData>") + extra_link +
         "</DataLink></Record3><Record4><ChecksumFile>md5checksum.hex</ChecksumFile></Record4></p:ISO5436_2>\n";
}

std::string doubles(const std::vector<double>& values) {
  std::string bytes(values.size() * 8, '\0');
  for (std::size_t k = 0; k < values.size(); ++k) std::memcpy(&bytes[8 * k], &values[k], 8);  // little-endian host
  return bytes;
}

std::string md5(const std::string& bytes) {
  return t::detail::md5_hex(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size());
}

// A message matches a pattern of alternatives "a|b", each a sequence of pieces "x.*y" that must
// appear in that order (std::regex warns under GCC 12's sanitizer builds).
bool matches(const std::string& text, const std::string& pattern) {
  std::size_t start = 0;
  while (start <= pattern.size()) {
    const std::size_t bar = std::min(pattern.find('|', start), pattern.size());
    const std::string alternative = pattern.substr(start, bar - start);
    std::size_t at = 0, piece_start = 0;
    bool ok = true;
    while (ok && piece_start <= alternative.size()) {
      const std::size_t wildcard = std::min(alternative.find(".*", piece_start), alternative.size());
      const std::string piece = alternative.substr(piece_start, wildcard - piece_start);
      const std::size_t found = text.find(piece, at);
      ok = found != std::string::npos;
      at = ok ? found + piece.size() : at;
      piece_start = wildcard + 2;
    }
    if (ok) return true;
    start = bar + 1;
  }
  return false;
}

// Expect an asperity::Error whose message matches the pattern.
template <class F>
void expect_error(F&& read, const std::string& pattern) {
  try {
    read();
    ADD_FAILURE() << "no error; expected /" << pattern << "/";
  } catch (const asperity::Error& error) {
    EXPECT_TRUE(matches(error.what(), pattern)) << error.what() << "\n  expected /" << pattern << "/";
  }
}

const std::vector<double> small_values = {1e-9, 2e-9, 3e-9, 4e-9, 5e-9, 6e-9, 7e-9, 8e-9, 9e-9, 1e-8, 1.1e-8, 1.2e-8};
}  // namespace

TEST(TopographyIo, RealX3P) {
  const t::HeightMap map = t::read_height_map(x3p_path);
  EXPECT_EQ(map.format, "x3p");
  EXPECT_EQ(map.nx, 650u);
  EXPECT_EQ(map.ny, 650u);
  EXPECT_DOUBLE_EQ(map.dx, 1.27656509837346e-7);
  EXPECT_DOUBLE_EQ(map.dy, 3.14582113527746e-7);
  EXPECT_EQ(map.missing_points(), 0u);
  EXPECT_NO_THROW(map.validate());
  // both checksums are verified (md5checksum.hex for main.xml, MD5ChecksumPointData)
  int verified = 0;
  for (const std::string& note : map.notes) verified += note.find("verified") != std::string::npos && note.find("not") == std::string::npos;
  EXPECT_EQ(verified, 2);
  // the first point of bindata/data.bin (float64, little-endian, x fastest)
  zip_t* archive = zip_open(x3p_path.c_str(), ZIP_RDONLY, nullptr);
  ASSERT_NE(archive, nullptr);
  zip_file_t* file = zip_fopen(archive, "bindata/data.bin", 0);
  double first[2];
  ASSERT_EQ(zip_fread(file, first, sizeof first), static_cast<zip_int64_t>(sizeof first));
  zip_fclose(file);
  zip_discard(archive);
  EXPECT_EQ(map.at(0, 0), first[0]);
  EXPECT_EQ(map.at(1, 0), first[1]);
}

TEST(TopographyIo, RealGwyddionAsciiMatrix) {
  const t::HeightMap map = t::read_height_map(afm_path);
  EXPECT_EQ(map.format, "ascii-matrix");
  EXPECT_EQ(map.nx, 256u);
  EXPECT_EQ(map.ny, 256u);
  EXPECT_DOUBLE_EQ(map.dx, 10e-6 / 256);  // "# Width: 10.00 µm" is the whole field
  EXPECT_DOUBLE_EQ(map.dy, 10e-6 / 256);
  EXPECT_DOUBLE_EQ(map.at(0, 0), 1.8823e-8);  // "# Value units: m"
  EXPECT_DOUBLE_EQ(map.at(1, 0), 1.8497e-8);
  EXPECT_EQ(map.missing_points(), 0u);
}

TEST(TopographyIo, GsfRoundTripAndLayout) {
  t::HeightMap map = t::read_height_map(afm_path);
  map.heights[5] = NAN;  // a missing point survives the round trip
  const std::string path = scratch("afm.gsf");
  t::write_gsf(map, path);
  const t::HeightMap back = t::read_height_map(path);
  EXPECT_EQ(back.format, "gsf");
  EXPECT_EQ(back.nx, map.nx);
  EXPECT_EQ(back.ny, map.ny);
  EXPECT_NEAR(back.dx, map.dx, 1e-15);
  EXPECT_TRUE(std::isnan(back.heights[5]));
  EXPECT_EQ(back.missing_points(), 1u);
  for (std::size_t k : {0u, 1u, 256u, 65535u}) EXPECT_FLOAT_EQ(static_cast<float>(back.heights[k]), static_cast<float>(map.heights[k]));
  // the header's NUL padding aligns the data to 4 bytes
  const std::string bytes = read_bytes(path);
  const std::size_t nul = bytes.find('\0');
  EXPECT_EQ((bytes.size() - 4 * map.nx * map.ny) % 4, 0u);
  EXPECT_GE(bytes.size() - 4 * map.nx * map.ny, nul + 1);
}

TEST(TopographyIo, GsfUnitsAndBadFiles) {
  const std::string header = "Gwyddion Simple Field 1.0\nXRes = 4\nYRes = 3\nXReal = 4\nYReal = 6\nXYUnits = um\nZUnits = nm\n";
  std::string padded = header + std::string(4 - header.size() % 4, '\0');
  std::string data(48, '\0');
  for (int k = 0; k < 12; ++k) {
    const float v = static_cast<float>(k);
    std::memcpy(&data[4 * k], &v, 4);
  }
  const std::string good = scratch("units.gsf");
  write_bytes(good, padded + data);
  const t::HeightMap map = t::read_gsf(good);
  EXPECT_DOUBLE_EQ(map.dx, 1e-6);
  EXPECT_DOUBLE_EQ(map.dy, 2e-6);
  EXPECT_DOUBLE_EQ(map.at(3, 2), 11e-9);
  const std::string path = scratch("bad.gsf");
  write_bytes(path, padded + data.substr(0, 40));
  expect_error([&] { t::read_gsf(path); }, "truncated");
  write_bytes(path, padded + data + "xx");
  expect_error([&] { t::read_gsf(path); }, "extra bytes");
  write_bytes(path, header);  // no NUL
  expect_error([&] { t::read_gsf(path); }, "truncated");
  const std::string hostile = "Gwyddion Simple Field 1.0\nXRes = 1000000\nYRes = 1000000\n";
  write_bytes(path, hostile + std::string(4 - hostile.size() % 4, '\0'));
  expect_error([&] { t::read_gsf(path); }, "more than the limit");  // 1e12 points: never allocated
  const std::string negative = "Gwyddion Simple Field 1.0\nXRes = -4\nYRes = 3\n";
  write_bytes(path, negative + std::string(4 - negative.size() % 4, '\0'));
  expect_error([&] { t::read_gsf(path); }, "XRes is not a positive integer");
  const std::string no_x = "Gwyddion Simple Field 1.0\nYRes = 3\n";
  write_bytes(path, no_x + std::string(4 - no_x.size() % 4, '\0'));
  expect_error([&] { t::read_gsf(path); }, "no XRes");
  std::string bad_unit = "Gwyddion Simple Field 1.0\nXRes = 4\nYRes = 3\nXReal = 4\nYReal = 6\nZUnits = furlong\n";
  bad_unit += std::string(4 - bad_unit.size() % 4, '\0');
  write_bytes(path, bad_unit + data);
  expect_error([&] { t::read_gsf(path); }, "unknown length unit 'furlong'");
  std::string no_size = "Gwyddion Simple Field 1.0\nXRes = 4\nYRes = 3\n";
  no_size += std::string(4 - no_size.size() % 4, '\0');
  write_bytes(path, no_size + data);
  expect_error([&] { t::read_gsf(path); }, "no pixel size");
  t::ReadOptions given;
  given.pixel_size_x = 5e-9;
  EXPECT_DOUBLE_EQ(t::read_gsf(path, given).dy, 5e-9);
  float inf = INFINITY;
  std::memcpy(&data[0], &inf, 4);
  write_bytes(path, padded + data);
  expect_error([&] { t::read_gsf(path); }, "infinite height");
}

TEST(TopographyIo, AsciiMatrixBadFilesAndMissingPoints) {
  const std::string path = scratch("matrix.txt");
  write_bytes(path, "# Width: 3 nm\n# Height: 3 nm\n# Value units: nm\n1\t2\t3\n4\tnan\t6\n7\t8\t9\n");
  const t::HeightMap map = t::read_ascii_matrix(path);
  EXPECT_EQ(map.missing_points(), 1u);
  EXPECT_DOUBLE_EQ(map.at(2, 2), 9e-9);
  EXPECT_DOUBLE_EQ(map.dx, 1e-9);
  write_bytes(path, "# Width: 3 nm\n# Height: 3 nm\n# Value units: nm\n1\t2\t3\n4\t6\n7\t8\t9\n");
  expect_error([&] { t::read_ascii_matrix(path); }, "line 5 has 2 values; the first row has 3");
  write_bytes(path, "# Width: 3 nm\n# Height: 3 nm\n# Value units: nm\n1\t2\t3\n4\t5,5\t6\n");
  expect_error([&] { t::read_ascii_matrix(path); }, "line 5, column 2: '5,5' is not a number (a decimal comma");
  write_bytes(path, "# Width: 3 nm\n# Height: 3 nm\n1\t2\t3\n4\t5\t6\n7\t8\t9\n");
  expect_error([&] { t::read_ascii_matrix(path); }, "no height unit");
  t::ReadOptions nm;
  nm.height_unit = "nm";
  EXPECT_DOUBLE_EQ(t::read_ascii_matrix(path, nm).at(1, 1), 5e-9);
  write_bytes(path, "# Value units: V\n1\t2\t3\n");
  expect_error([&] { t::read_ascii_matrix(path); }, "not a length unit");
  write_bytes(path, "# Width: 3 parsecs\n1 2 3\n");
  expect_error([&] { t::read_ascii_matrix(path); }, "unknown length unit");
  write_bytes(path, "# Width: 3 nm\n# Height: 3 nm\n# Value units: nm\n1\t2\t3\n4\tinf\t6\n");
  expect_error([&] { t::read_ascii_matrix(path); }, "'inf' is not a number");
  write_bytes(path, "");
  expect_error([&] { t::read_ascii_matrix(path); }, "no data rows");
  t::ReadOptions tiny;
  tiny.max_points = 4;
  write_bytes(path, "# Width: 3 nm\n# Height: 3 nm\n# Value units: nm\n1 2 3\n4 5 6\n");
  expect_error([&] { t::read_ascii_matrix(path, tiny); }, "more than 4 points");
  expect_error([&] { t::read_height_map(scratch("no-such-file.txt")); }, "no such file");
}

// The OS's reason, not "no such file", for a path that exists but cannot be followed (issue 37)
TEST(TopographyIo, UnfollowablePathsNamedAsTheSystemNamesThem) {
  const std::string loop = scratch("loop.txt");
  fs::remove(loop);
  fs::create_symlink(loop, loop);  // a link to itself: ELOOP
  std::string message;
  try {
    t::read_height_map(loop);
  } catch (const asperity::Error& error) {
    message = error.what();
  }
  EXPECT_NE(message.find(std::strerror(ELOOP)), std::string::npos) << message;
  EXPECT_EQ(message.find("no such file"), std::string::npos) << message;
  const std::string file = scratch("plain-file.txt");
  write_bytes(file, "1 2\n3 4\n");
  message.clear();
  try {
    t::read_height_map(file + "/map.txt");  // a file where a folder should be: ENOTDIR
  } catch (const asperity::Error& error) {
    message = error.what();
  }
  EXPECT_NE(message.find(std::strerror(ENOTDIR)), std::string::npos) << message;
  EXPECT_EQ(message.find("no such file"), std::string::npos) << message;
  fs::remove(loop);
}

TEST(TopographyIo, XyzGridAndBadFiles) {
  const std::string path = scratch("map.xyz");
  std::string text = "x,y,z\n";
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 4; ++i)
      if (!(i == 2 && j == 1)) text += std::to_string(0.5 * i) + "," + std::to_string(10 + 0.25 * j) + "," + std::to_string(i + 4 * j) + "\n";
  write_bytes(path, text);
  expect_error([&] { t::read_height_map(path); }, "carry no units");
  t::ReadOptions um;
  um.lateral_unit = "um";
  const t::HeightMap map = t::read_height_map(path, um);
  EXPECT_EQ(map.nx, 4u);
  EXPECT_EQ(map.ny, 3u);
  EXPECT_DOUBLE_EQ(map.dx, 0.5e-6);
  EXPECT_DOUBLE_EQ(map.dy, 0.25e-6);
  EXPECT_DOUBLE_EQ(map.at(3, 2), 11e-6);
  EXPECT_TRUE(std::isnan(map.at(2, 1)));  // absent from the file: missing
  write_bytes(path, text + "0.5,10,99\n");
  expect_error([&] { t::read_xyz(path, um); }, "two points at the same x, y");
  write_bytes(path, text + "0.6,10,99\n");
  expect_error([&] { t::read_xyz(path, um); }, "not on a regular grid|less than half");
  write_bytes(path, text + "1e12,10,99\n");
  expect_error([&] { t::read_xyz(path, um); }, "regular grid|limit");
  write_bytes(path, text + "1,2\n");
  expect_error([&] { t::read_xyz(path, um); }, "columns");
}

TEST(TopographyIo, X3PBadFiles) {
  const std::string path = scratch("made.x3p");
  const std::string data = doubles(small_values);
  const auto make = [&](const std::string& xml, const std::string& bin, bool with_sum = true) {
    std::vector<std::pair<std::string, std::string>> entries = {{"main.xml", xml}, {"bindata/data.bin", bin}};
    if (with_sum) entries.push_back({"md5checksum.hex", md5(xml) + " *main.xml\n"});
    write_zip(path, entries);
  };
  make(main_xml("4", "3", "D", md5(data)), data);
  const t::HeightMap map = t::read_x3p(path);
  EXPECT_EQ(map.nx, 4u);
  EXPECT_DOUBLE_EQ(map.dy, 2e-6);
  EXPECT_DOUBLE_EQ(map.at(3, 2), 1.2e-8);

  make(main_xml("4", "3", "D", "00112233445566778899aabbccddeeff"), data);
  expect_error([&] { t::read_x3p(path); }, "MD5 checksum of the point data .* does not match");
  {
    const std::string xml = main_xml("4", "3", "D", md5(data));
    write_zip(path, {{"main.xml", xml}, {"bindata/data.bin", data}, {"md5checksum.hex", md5(xml + " ") + " *main.xml\n"}});
    expect_error([&] { t::read_x3p(path); }, "MD5 checksum of main.xml.*does not match");
  }
  make(main_xml("5", "3", "D", md5(data)), data);
  expect_error([&] { t::read_x3p(path); }, "holds 96 bytes; main.xml's sizes need 120");
  make(main_xml("1000000", "1000000", "D", md5(data)), data);
  expect_error([&] { t::read_x3p(path); }, "claims 1000000 x 1000000 points, more than the limit");
  make(main_xml("4", "0", "D", md5(data)), data);
  expect_error([&] { t::read_x3p(path); }, "SizeY is not a positive integer");
  make(main_xml("4", "3", "Q", md5(data)), data);
  expect_error([&] { t::read_x3p(path); }, "DataType 'Q'");
  make(main_xml("4", "3", "D", md5(data), "", "PRF"), data);
  expect_error([&] { t::read_x3p(path); }, "only areal surfaces");
  make(main_xml("4", "3", "D", md5(data), "", "SUR", "A"), data);
  expect_error([&] { t::read_x3p(path); }, "only incremental axes");
  make(main_xml("4", "3", "D", md5(data)).substr(0, 200), data);
  expect_error([&] { t::read_x3p(path); }, "not well-formed XML");
  write_zip(path, {{"bindata/data.bin", data}});
  expect_error([&] { t::read_x3p(path); }, "no 'main.xml'");

  // NaN and the valid-points mask both mark missing points; int16 with CZ scaling
  std::vector<double> with_nan = small_values;
  with_nan[4] = NAN;
  const std::string nan_data = doubles(with_nan);
  const std::string mask = std::string("\xF7\x0F", 2);  // point 3 invalid (bit 3 of byte 0), 12 bits set otherwise
  make(main_xml("4", "3", "D", md5(nan_data), "<ValidPointsLink>bindata/valid.bin</ValidPointsLink>"), nan_data);
  {
    const std::string xml = main_xml("4", "3", "D", md5(nan_data), "<ValidPointsLink>bindata/valid.bin</ValidPointsLink>");
    write_zip(path, {{"main.xml", xml}, {"bindata/data.bin", nan_data}, {"bindata/valid.bin", mask}, {"md5checksum.hex", md5(xml) + " *main.xml\n"}});
    const t::HeightMap masked = t::read_x3p(path);
    EXPECT_EQ(masked.missing_points(), 2u);
    EXPECT_TRUE(std::isnan(masked.at(3, 0)));
    EXPECT_TRUE(std::isnan(masked.at(0, 1)));
    write_zip(path, {{"main.xml", xml}, {"bindata/data.bin", nan_data}, {"bindata/valid.bin", "\x01"}, {"md5checksum.hex", md5(xml) + " *main.xml\n"}});
    expect_error([&] { t::read_x3p(path); }, "valid.bin' holds 1 bytes; main.xml's sizes need 2");
  }
  {
    std::string ints(24, '\0');
    for (int k = 0; k < 12; ++k) {
      const std::int16_t v = static_cast<std::int16_t>(k - 6);
      std::memcpy(&ints[2 * k], &v, 2);
    }
    std::string xml = main_xml("4", "3", "I", md5(ints));
    xml.replace(xml.find("<DataType>I</DataType>"), 22, "<DataType>I</DataType><Increment>1e-9</Increment><Offset>1e-6</Offset>");
    make(xml, ints);
    const t::HeightMap scaled = t::read_x3p(path);
    EXPECT_DOUBLE_EQ(scaled.at(0, 0), 1e-6 - 6e-9);
  }

  // the real file: truncated, and one byte of its compressed data changed
  const std::string real = read_bytes(x3p_path);
  write_bytes(path, real.substr(0, real.size() / 2));
  expect_error([&] { t::read_x3p(path); }, "not a readable X3P");
  std::string corrupt = real;
  corrupt[real.size() / 3] = static_cast<char>(corrupt[real.size() / 3] ^ 0x55);
  write_bytes(path, corrupt);
  expect_error([&] { t::read_x3p(path); }, "CRC|MD5|cannot read|Zlib|truncated|inconsistent|not a readable");
  write_bytes(path, "PK\x03\x04 not really a zip");
  expect_error([&] { t::read_height_map(path); }, "not a readable X3P");
}

TEST(TopographyIo, UnitsAndLengths) {
  EXPECT_DOUBLE_EQ(t::length_unit_in_metres("\xC2\xB5m"), 1e-6);
  EXPECT_DOUBLE_EQ(t::length_unit_in_metres("\xCE\xBCm"), 1e-6);
  EXPECT_DOUBLE_EQ(t::length_unit_in_metres(" nm "), 1e-9);
  EXPECT_DOUBLE_EQ(t::length_unit_in_metres("\xC3\x85"), 1e-10);
  EXPECT_DOUBLE_EQ(t::parse_length("1.5um"), 1.5e-6);
  EXPECT_DOUBLE_EQ(t::parse_length("2e-7 m"), 2e-7);
  EXPECT_DOUBLE_EQ(t::parse_length("3", "nm"), 3e-9);
  EXPECT_THROW(t::parse_length("3"), asperity::Error);
  EXPECT_THROW(t::parse_length("um"), asperity::Error);
  EXPECT_THROW(t::length_unit_in_metres("inch"), asperity::Error);
}

// ---- hostile files (issue 26): each of these crashed, hung, ran away or answered wrong before ----

namespace {
// The peak resident memory of `work` run in a child process [KiB], or -1 if it failed.
long child_peak_kib(const std::function<void()>& work) {
  const pid_t pid = fork();
  if (pid == 0) {
    try {
      work();
    } catch (...) {
    }
    _exit(0);
  }
  int status = 0;
  struct rusage usage {};
  if (wait4(pid, &status, 0, &usage) != pid || !WIFEXITED(status)) return -1;
  return usage.ru_maxrss;
}

long own_peak_kib() {
  struct rusage usage {};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss;
}

#if defined(__SANITIZE_ADDRESS__)
constexpr bool memory_is_measured = false;  // ASan's shadow and quarantine are not the reader's
#else
constexpr bool memory_is_measured = true;
#endif
}  // namespace

// A small X3P whose main.xml inflates to more elements than the limit is refused before a tree
// is built for them (before: 16 M elements in a 97 KB file took 1.2 GB).
TEST(TopographyHostile, X3PElementBombRefusedBeforeParsing) {
  const std::string path = scratch("element-bomb.x3p");
  const std::string data = doubles(small_values);
  std::string xml = main_xml("4", "3", "D", md5(data));
  std::string bomb;
  bomb.reserve(5 * ((std::size_t{1} << 21) + 2));
  for (std::size_t k = 0; k < (std::size_t{1} << 21) + 1; ++k) bomb += "<a/>";
  xml.insert(xml.find("<Record3>"), "<Record2>" + bomb + "</Record2>");
  write_zip(path, {{"main.xml", xml}, {"bindata/data.bin", data}});
  EXPECT_LT(fs::file_size(path), 100000u);
  expect_error([&] { t::read_x3p(path); }, "main.xml holds .* elements, more than the limit of 2097152");
  const long peak = child_peak_kib([&] { t::read_x3p(path); });
  ASSERT_GT(peak, 0);
  if (memory_is_measured) {
    EXPECT_LT(peak, own_peak_kib() + 64 * 1024) << "KiB";  // the XML's bytes, no tree
  }
}

// A zero-filled point entry (a data bomb: 32 MiB in a small zip) costs the heights and no more:
// the points are streamed, not held twice.
TEST(TopographyHostile, X3PDataBombCostsTheHeightsOnly) {
  const std::string path = scratch("data-bomb.x3p");
  const std::size_t side = 2048;
  const std::string data(side * side * 8, '\0');
  const std::string xml = main_xml(std::to_string(side), std::to_string(side), "D", md5(data));
  write_zip(path, {{"main.xml", xml}, {"bindata/data.bin", data}});
  EXPECT_LT(fs::file_size(path), 200000u);
  const t::HeightMap map = t::read_x3p(path);
  EXPECT_EQ(map.size(), side * side);
  const long peak = child_peak_kib([&] { t::read_x3p(path); });
  ASSERT_GT(peak, 0);
  // heights 32 MiB; before, the raw bytes were held beside them (64 MiB)
  if (memory_is_measured) {
    EXPECT_LT(peak, own_peak_kib() + 48 * 1024) << "KiB";
  }
}

// A CZ increment that is subnormal (every height would round to 0 or nearly) or zero, and
// sampling intervals far outside physics, are named, not analysed into "density 0, radius 0".
TEST(TopographyHostile, ScalesOutsidePhysicsAreRefused) {
  const std::string path = scratch("scales.x3p");
  std::string ints(24, '\0');
  for (int k = 0; k < 12; ++k) {
    const std::int16_t v = static_cast<std::int16_t>(3 * k - 6);
    std::memcpy(&ints[2 * k], &v, 2);
  }
  for (const char* increment : {"4e-320", "0"}) {
    std::string xml = main_xml("4", "3", "I", md5(ints));
    xml.replace(xml.find("<DataType>I</DataType>"), 22,
                std::string("<DataType>I</DataType><Increment>") + increment + "</Increment>");
    write_zip(path, {{"main.xml", xml}, {"bindata/data.bin", ints}});
    expect_error([&] { t::read_x3p(path); }, "CZ Increment .* is not a usable height scale");
  }
  for (const char* step : {"1e-200", "1e+200"}) {
    std::string xml = main_xml("4", "3", "D", md5(doubles(small_values)));
    xml.replace(xml.find("<Increment>1e-6</Increment>"), 27, std::string("<Increment>") + step + "</Increment>");
    write_zip(path, {{"main.xml", xml}, {"bindata/data.bin", doubles(small_values)}});
    expect_error([&] { t::read_x3p(path); }, "CX Increment " + std::string(step) + " m is outside [1e-13, 1e3] m");
  }
  // the same from an override and in any map
  const std::string gsf = scratch("scales.gsf");
  t::HeightMap map;
  map.nx = 4;
  map.ny = 3;
  map.dx = map.dy = 1e-6;
  map.heights = small_values;
  t::write_gsf(map, gsf);
  t::ReadOptions tiny;
  tiny.pixel_size_x = 1e-200;
  expect_error([&] { t::read_height_map(gsf, tiny).validate(); }, "a sampling interval of 1e-200 m is outside");
  map.heights[5] = 1e200;
  expect_error([&] { map.validate(); }, "the height 1e+200 m at point (1, 1) is beyond 1000 m");
}

// A Gwyddion ASCII matrix cut exactly at a row boundary reads as a smaller map; the header's
// field then gives pixels that are not square, which is refused (before: read, with a wrong dy).
TEST(TopographyHostile, AsciiMatrixCutAtARowBoundary) {
  const std::string whole = read_bytes(afm_path);
  const std::string path = scratch("cut.txt");
  std::size_t cut = whole.size();
  for (int rows = 0; rows < 3; ++rows) cut = whole.rfind('\n', cut - 2) + 1;  // 3 rows fewer
  write_bytes(path, whole.substr(0, cut));
  expect_error([&] { t::read_ascii_matrix(path); },
               "over 256 x 253 points gives pixels that are not square.*a file cut short");
  t::ReadOptions given;
  given.pixel_size_x = given.pixel_size_y = 10e-6 / 256;
  EXPECT_EQ(t::read_ascii_matrix(path, given).ny, 253u);  // read when the pixel size is given
  // one row fewer of 256 is still seen (the header's 4 digits: 5e-4 relative)
  write_bytes(path, whole.substr(0, whole.rfind('\n', whole.size() - 2) + 1));
  expect_error([&] { t::read_ascii_matrix(path); }, "not square");
  EXPECT_EQ(t::read_ascii_matrix(afm_path).ny, 256u);
}

// Special files are refused at once, never waited on (a FIFO as a surface hung the command).
TEST(TopographyHostile, FifoAndDirectoryAreRefusedWithoutWaiting) {
  const std::string fifo = scratch("surface.fifo");
  fs::remove(fifo);
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  for (const auto& read : {+[](const std::string& p) { t::read_height_map(p); },
                           +[](const std::string& p) { t::read_x3p(p); }, +[](const std::string& p) { t::read_gsf(p); },
                           +[](const std::string& p) { t::read_ascii_matrix(p); }})
    expect_error([&] { read(fifo); }, "not a regular file");
  expect_error([&] { t::read_gsf(scratch("")); }, "a directory, not a file");
  fs::remove(fifo);
}

// Bytes of a file quoted in a message cannot reach a terminal as an escape sequence; paths with
// a NUL are refused.
TEST(TopographyHostile, MessagesQuoteFileBytesPrintably) {
  const std::string path = scratch("escape.txt");
  write_bytes(path, "# Width: 1 um\n# Height: 1 um\n# Value units: m\n1 2 3\n4 \x1b[31mred\x1b[0m 6\n");
  try {
    t::read_ascii_matrix(path);
    ADD_FAILURE() << "no error";
  } catch (const asperity::Error& error) {
    const std::string text = error.what();
    EXPECT_EQ(text.find('\x1b'), std::string::npos) << text;
    EXPECT_NE(text.find("\\x1B[31mred\\x1B[0m"), std::string::npos) << text;
  }
  write_bytes(path, "# Value units: \xff\xfe\x9b" "2J\n1 2 3\n");
  try {
    t::read_ascii_matrix(path);
    ADD_FAILURE() << "no error";
  } catch (const asperity::Error& error) {
    EXPECT_NE(std::string(error.what()).find("\\xFF\\xFE\\x9B2J"), std::string::npos) << error.what();
  }
  expect_error([&] { t::read_height_map(std::string("a.x3p\0.txt", 10)); }, "a path with a NUL byte");
}

// The rounding step of the stored heights is known for every format: the noise floor needs it.
TEST(TopographyHostile, HeightResolutionOfEveryFormat) {
  const std::string gsf = scratch("resolution.gsf");
  t::HeightMap map;
  map.nx = 4;
  map.ny = 3;
  map.dx = map.dy = 1e-6;
  map.heights = small_values;  // largest 1.2e-8 m, stored as float32
  t::write_gsf(map, gsf);
  const double float_step = static_cast<double>(std::nextafter(1.2e-8f, 1.f)) - static_cast<double>(1.2e-8f);
  EXPECT_DOUBLE_EQ(t::read_gsf(gsf).height_resolution, float_step);
  // "%.5g" numbers up to "2.4022e-007": 5 significant digits at 1e-7
  EXPECT_DOUBLE_EQ(t::read_ascii_matrix(afm_path).height_resolution, 1e-11);
  EXPECT_LT(t::read_x3p(x3p_path).height_resolution, 1e-20);                   // float64
  const std::string path = scratch("resolution.x3p");
  std::string ints(24, '\0');
  std::string xml = main_xml("4", "3", "I", md5(ints));
  xml.replace(xml.find("<DataType>I</DataType>"), 22, "<DataType>I</DataType><Increment>2e-9</Increment>");
  write_zip(path, {{"main.xml", xml}, {"bindata/data.bin", ints}});
  EXPECT_DOUBLE_EQ(t::read_x3p(path).height_resolution, 2e-9);
  t::ReadOptions nm;
  nm.height_unit = "nm";  // the file's numbers read in nm: the step scales with them
  EXPECT_DOUBLE_EQ(t::read_ascii_matrix(afm_path, nm).height_resolution, 1e-20);
}
