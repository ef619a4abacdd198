// The kernels built for AVX-512 F/DQ/VL (compile options in runtime/CMakeLists.txt; see kernels.hpp).
#include "kernels_x86.hpp"

namespace asperity::detail {
const Kernels avx512_kernels = x86_kernels;
}
