// record_kernels.hpp for AVX-512 F/DQ/VL (the runtime's kernels_avx512.cpp flags).
#include "record_kernels_impl.hpp"

namespace asperity::bench {
const RecordKernels record_kernels_avx512 = make_record_kernels<LanesExp>();
}
