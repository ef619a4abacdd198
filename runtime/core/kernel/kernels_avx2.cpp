// The kernels built for AVX2 + FMA (compile options in runtime/CMakeLists.txt; see kernels.hpp).
#include "batch_x86.hpp"
#include "contact4_x86.hpp"

namespace asperity::detail {
const Kernels avx2_kernels{scalar_value<ScalarMath>, contact4_x86, contact_products_x86, block<X86Passes>, X86Passes::exps};
}
