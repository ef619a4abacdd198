// libFuzzer target: the X3P reader (topography/x3p_reader.cpp), then the surface analysis on
// what it returns (fuzz/surface_harness.hpp). Structure-aware: a zip's CRCs stop nearly every
// mutated archive at the first entry, so the input is mostly the archive's entries, which the
// target zips itself (stored entries, in memory) before reading:
//   byte 0 odd:  entries, each [name length: 1 byte][name][size: 4 bytes LE, cut to what is
//                left][bytes]; "@MD5:name@" in an entry becomes the MD5 of entry `name` (so
//                checksums can match and the mutations reach past them)
//   byte 0 even: the rest is the archive's raw bytes (libzip's own checks)
#include <zlib.h>

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <map>
#include <string>
#include <vector>

#include "input/md5.hpp"
#include "surface_harness.hpp"

namespace {

void put16(std::string& out, unsigned v) {
  out += static_cast<char>(v & 0xff);
  out += static_cast<char>((v >> 8) & 0xff);
}
void put32(std::string& out, std::uint32_t v) {
  put16(out, v & 0xffff);
  put16(out, v >> 16);
}

// A zip of stored (uncompressed) entries, written here (PKWARE APPNOTE 4.3.7, 4.3.12, 4.3.16):
// small, valid, and independent of the reader's libzip.
std::string zipped(const std::vector<std::pair<std::string, std::string>>& entries) {
  std::string out, directory;
  for (const auto& [name, bytes] : entries) {
    const std::uint32_t crc =
        static_cast<std::uint32_t>(crc32(0, reinterpret_cast<const Bytef*>(bytes.data()), static_cast<uInt>(bytes.size())));
    const std::uint32_t offset = static_cast<std::uint32_t>(out.size());
    put32(out, 0x04034b50);
    put16(out, 20);
    put16(out, 0);  // flags
    put16(out, 0);  // stored
    put16(out, 0);
    put16(out, 0);  // time, date
    put32(out, crc);
    put32(out, static_cast<std::uint32_t>(bytes.size()));
    put32(out, static_cast<std::uint32_t>(bytes.size()));
    put16(out, static_cast<unsigned>(name.size()));
    put16(out, 0);
    out += name;
    out += bytes;
    put32(directory, 0x02014b50);
    put16(directory, 20);
    put16(directory, 20);
    put16(directory, 0);
    put16(directory, 0);
    put16(directory, 0);
    put16(directory, 0);
    put32(directory, crc);
    put32(directory, static_cast<std::uint32_t>(bytes.size()));
    put32(directory, static_cast<std::uint32_t>(bytes.size()));
    put16(directory, static_cast<unsigned>(name.size()));
    put16(directory, 0);
    put16(directory, 0);
    put16(directory, 0);
    put16(directory, 0);
    put32(directory, 0);
    put32(directory, offset);
    directory += name;
  }
  const std::uint32_t start = static_cast<std::uint32_t>(out.size());
  out += directory;
  put32(out, 0x06054b50);
  put16(out, 0);
  put16(out, 0);
  put16(out, static_cast<unsigned>(entries.size()));
  put16(out, static_cast<unsigned>(entries.size()));
  put32(out, static_cast<std::uint32_t>(directory.size()));
  put32(out, start);
  put16(out, 0);
  return out;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  if (!(data[0] & 1)) {
    asperity::fuzz::read_and_analyse(data + 1, size - 1, &asperity::topography::read_x3p);
    return 0;
  }
  std::vector<std::pair<std::string, std::string>> entries;
  std::size_t at = 1;
  while (at < size && entries.size() < 16) {
    const std::size_t name_size = data[at++];
    if (at + name_size + 4 > size) break;
    std::string name(reinterpret_cast<const char*>(data + at), name_size);
    at += name_size;
    std::uint32_t length = 0;
    std::memcpy(&length, data + at, 4);
    at += 4;
    const std::size_t count = std::min<std::size_t>(length, size - at);
    entries.emplace_back(std::move(name), std::string(reinterpret_cast<const char*>(data + at), count));
    at += count;
  }
  // checksums asked for by name
  std::map<std::string, std::string> sums;
  for (const auto& [name, bytes] : entries)
    sums[name] = asperity::topography::detail::md5_hex(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size());
  for (auto& entry : entries) {
    std::string& bytes = entry.second;
    for (std::size_t mark = bytes.find("@MD5:"); mark != std::string::npos; mark = bytes.find("@MD5:", mark + 1)) {
      const std::size_t end = bytes.find('@', mark + 5);
      if (end == std::string::npos) break;
      const auto found = sums.find(bytes.substr(mark + 5, end - mark - 5));
      if (found != sums.end()) bytes.replace(mark, end - mark + 1, found->second);
    }
  }
  const std::string archive = zipped(entries);
  asperity::fuzz::read_and_analyse(archive.data(), archive.size(), &asperity::topography::read_x3p);
  return 0;
}
