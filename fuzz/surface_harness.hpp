// What the surface fuzz targets share: the input written to an anonymous in-memory file
// (memfd, read through /proc/self/fd like any path), read by one reader with small limits, and
// the whole analysis on the map it returns. Whatever the bytes: a map or an asperity::Error; no
// crash, sanitizer report, hang or runaway memory (docs/reliability.md).
#pragma once
#include <sys/mman.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <string>

#include "asperity/error.hpp"
#include "asperity/topography/analysis.hpp"
#include "asperity/topography/height_map_io.hpp"

namespace asperity::fuzz {

using Reader = topography::HeightMap (*)(const std::string&, const topography::ReadOptions&);

inline void read_and_analyse(const void* data, std::size_t size, Reader read, const char* units = "") {
  const int fd = memfd_create("asperity-fuzz", MFD_CLOEXEC);
  if (fd < 0) return;
  std::size_t written = 0;
  while (written < size) {
    const ssize_t count = ::write(fd, static_cast<const char*>(data) + written, size - written);
    if (count <= 0) break;
    written += static_cast<std::size_t>(count);
  }
  topography::ReadOptions options;
  options.max_points = std::size_t{1} << 16;  // a fuzzed header may claim more: it is refused
  options.lateral_unit = units;
  try {
    topography::HeightMap map = read("/proc/self/fd/" + std::to_string(fd), options);
    topography::AnalysisOptions analysis;
    analysis.assessment.bootstrap = 0;
    analysis.assessment.threads = 1;
    analysis.max_fit_sample = 500;
    analysis.sampling_factors = {1, 2};
    analysis.max_height_sample = 200;
    topography::analyse_height_map(std::move(map), analysis);
  } catch (const Error&) {
  }
  ::close(fd);
}

}  // namespace asperity::fuzz
