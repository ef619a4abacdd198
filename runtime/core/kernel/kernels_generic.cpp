// The kernels built for the compiler's baseline (see curve_kernel.hpp). Without wide vectors the
// inline exp/log do not pay (one at a time the C library's are faster: bench_lookup BM_StdExp /
// BM_FastExp), so this build sorts by segment and calls the library's.
#include "kernels.hpp"

namespace asperity::detail {
const Kernels generic_kernels{exp4, block<LibraryMath>};
}
