// libFuzzer target fuzz_ID for each surface format without a target of its own (fuzz_ID.cpp):
// fuzz/CMakeLists.txt compiles this file once per entry of ASPERITY_SURFACE_FORMATS
// (height_map_io.hpp) with ASPERITY_FUZZ_FORMAT=ID. A file's bytes for that format's reader, then
// the surface analysis on what it returns (fuzz/surface_harness.hpp); files of a format that
// carries no units are read in micrometres (else every input would stop at the missing unit).
#include <cstddef>
#include <cstdint>

#include "asperity/topography/surface_formats.hpp"
#include "surface_harness.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  namespace topo = asperity::topography;
  static const topo::SurfaceFormat& format = *topo::surface_format(topo::HeightMapFormat::ASPERITY_FUZZ_FORMAT);
  asperity::fuzz::read_and_analyse(data, size, format.read, format.needs_units ? "um" : "");
  return 0;
}
