// The kernels built for AVX2 + FMA (compile options in runtime/CMakeLists.txt; see kernels.hpp).
#include "kernels.hpp"

namespace asperity::detail {
const Kernels avx2_kernels{scalar_value<ScalarMath>, contact4<FastMath>, block<FastMath>};
}
