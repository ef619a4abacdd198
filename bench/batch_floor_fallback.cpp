// batch_floor.hpp where this binary has no x86 build: no floor kernels
#include "batch_floor.hpp"

namespace asperity::bench {
const BatchFloorKernels batch_floor_avx2{}, batch_floor_avx512{};
}
