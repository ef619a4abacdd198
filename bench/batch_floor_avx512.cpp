// batch_floor.hpp's kernels for AVX-512 (the runtime's kernels_avx512.cpp flags)
#include "batch_floor_impl.hpp"

namespace asperity::bench {
const BatchFloorKernels batch_floor_avx512 = floor_kernels;
}
