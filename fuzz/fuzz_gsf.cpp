// libFuzzer target: the gsf reader (topography/gsf*), then the surface analysis on what it
// returns (fuzz/surface_harness.hpp).
#include <cstddef>
#include <cstdint>

#include "surface_harness.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  asperity::fuzz::read_and_analyse(data, size, &asperity::topography::read_gsf);
  return 0;
}
