// The kernels built for AVX2 + FMA (compile options in runtime/CMakeLists.txt; see kernels.hpp).
#include "kernels_x86.hpp"

namespace asperity::detail {
const Kernels avx2_kernels = x86_kernels;
}
