// batch_floor.hpp's kernels for AVX2 + FMA (the runtime's kernels_avx2.cpp flags)
#include "batch_floor_impl.hpp"

namespace asperity::bench {
const BatchFloorKernels batch_floor_avx2 = floor_kernels;
}
