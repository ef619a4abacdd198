// The kernels built for the compiler's baseline (see kernels.hpp). With two doubles a vector
// the inline exp does not pay (one at a time the C library's is faster: bench_lookup
// BM_StdExp / BM_FastExp), so this build calls the library's.
#include "kernels.hpp"

namespace asperity::detail {
const Kernels generic_kernels{exp4, block<LibraryMath>};
}
