// The surface formats' one list (ASPERITY_SURFACE_FORMATS, height_map_io.hpp) reaches every edge:
// each entry has its HeightMapFormat value, a row of surface_formats() with a reader, its names
// parsed back, a way to be chosen automatically; the IDs CMake reads from the list (the fuzz
// targets' list, cmake/surface_formats.cmake) are the table's; and, with the commands built, the
// --format help and message of `asperity surface` and `asperity exact-contact` name every format.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <cstring>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "asperity/topography/height_map_io.hpp"
#include "asperity/topography/surface_formats.hpp"

namespace t = asperity::topography;

namespace {

#define ASPERITY_TEST_FORMAT_ID(id, ...) #id,
const std::vector<std::string> list_ids = {ASPERITY_SURFACE_FORMATS(ASPERITY_TEST_FORMAT_ID)};
#undef ASPERITY_TEST_FORMAT_ID

std::string shortest_name(const t::SurfaceFormat& entry) {
  std::string shortest = entry.name;
  for (const char* alias : entry.aliases)
    if (std::strlen(alias) < shortest.size()) shortest = alias;
  return shortest;
}

}  // namespace

TEST(SurfaceFormats, EveryEntryOfTheListIsARowOfTheTableWithItsValueAndReader) {
  const std::vector<t::SurfaceFormat>& table = t::surface_formats();
  ASSERT_EQ(table.size(), list_ids.size());
  for (std::size_t k = 0; k < table.size(); ++k) {
    const t::SurfaceFormat& entry = table[k];
    SCOPED_TRACE(entry.name);
    EXPECT_EQ(entry.python_name, list_ids[k]);
    EXPECT_EQ(static_cast<std::size_t>(entry.format), k + 1);  // automatic is 0
    EXPECT_EQ(t::surface_format(entry.format), &entry);
    EXPECT_NE(entry.read, nullptr);
    EXPECT_TRUE(entry.description && *entry.description);
    EXPECT_TRUE(entry.magic || !entry.extensions.empty()) << "read_height_map could never choose it";
    t::HeightMapFormat parsed = t::HeightMapFormat::automatic;
    EXPECT_TRUE(t::parse_height_map_format(entry.name, parsed));
    EXPECT_EQ(parsed, entry.format);
    for (const char* alias : entry.aliases) {
      parsed = t::HeightMapFormat::automatic;
      EXPECT_TRUE(t::parse_height_map_format(alias, parsed)) << alias;
      EXPECT_EQ(parsed, entry.format) << alias;
    }
    EXPECT_NE(t::surface_format_names().find(shortest_name(entry)), std::string::npos);
    EXPECT_NE(t::surface_format_list().find(entry.name), std::string::npos);
    EXPECT_EQ(t::surface_formats_without_units().find(entry.name) != std::string::npos, entry.needs_units);
  }
  EXPECT_EQ(t::surface_format(t::HeightMapFormat::automatic), nullptr);
}

// ASPERITY_FORMAT_IDS: what cmake/surface_formats.cmake reads from the list, comma-separated
TEST(SurfaceFormats, CMakeReadsTheSameList) {
  std::string joined;
  for (const std::string& id : list_ids) joined += (joined.empty() ? "" : ",") + id;
  EXPECT_EQ(joined, ASPERITY_FORMAT_IDS) << "cmake/surface_formats.cmake's pattern misses an entry of the list";
}

#ifdef ASPERITY_COMMAND
namespace {
std::string run(const std::string& arguments) {
  std::string output;
  const std::string command = std::string(ASPERITY_COMMAND) + " " + arguments + " 2>&1";
  const std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(command.c_str(), "r"), &pclose);
  if (!pipe) return output;
  std::array<char, 4096> buffer{};
  while (std::size_t count = std::fread(buffer.data(), 1, buffer.size(), pipe.get())) output.append(buffer.data(), count);
  return output;
}
}  // namespace

TEST(SurfaceFormats, EveryHelpTextAndMessageNamesEveryFormat) {
  for (const char* command : {"surface", "exact-contact"}) {
    SCOPED_TRACE(command);
    const std::string help = run(std::string(command) + " --help");
    const std::string refusal = run(std::string(command) + " " ASPERITY_TEST_SURFACES "/afm-zsensor-10um.txt --modulus 1e11 --pressure 1e6 --format tiff");
    EXPECT_NE(refusal.find("unknown format 'tiff'"), std::string::npos) << refusal;
    for (const t::SurfaceFormat& entry : t::surface_formats()) {
      EXPECT_NE(help.find(shortest_name(entry)), std::string::npos) << entry.name << " not in:\n" << help;
      EXPECT_NE(refusal.find(shortest_name(entry)), std::string::npos) << entry.name << " not in:\n" << refusal;
    }
  }
  const std::string surface_help = run("surface --help");
  for (const t::SurfaceFormat& entry : t::surface_formats())
    EXPECT_NE(surface_help.find(entry.name), std::string::npos) << entry.name;  // the description
}
#endif
