// The kernels built for the compiler's baseline (see kernels.hpp). With two doubles a vector
// (and no 64-bit variable shifts) the masked exp does not pay: this build calls the inline
// exp one at a time (bench_lookup BM_StdExp / BM_FastExp: faster than the C library's, which
// also slows below e^-512 and for subnormal results).
#include "kernels.hpp"

namespace asperity::detail {
const Kernels generic_kernels{nullptr, contact4<ScalarMath>, block<ScalarMath>};
}
