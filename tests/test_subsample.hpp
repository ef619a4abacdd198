// ASPERITY_TEST_SUBSAMPLE=k: a test's sweeps keep every k-th point (or case). The sanitizer pass of
// CI sets it: it checks memory and undefined behaviour, and the full numerical sweep runs in the
// optimized pass.
#pragma once
#include <algorithm>
#include <cstddef>
#include <cstdlib>

namespace asperity::test {

inline std::size_t subsample_stride() {
  const char* text = std::getenv("ASPERITY_TEST_SUBSAMPLE");
  return text ? static_cast<std::size_t>(std::max(1L, std::strtol(text, nullptr, 10))) : 1;
}

}  // namespace asperity::test
