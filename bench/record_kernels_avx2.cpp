// record_kernels.hpp for AVX2 + FMA (the runtime's kernels_avx2.cpp flags).
#include "record_kernels_impl.hpp"

namespace asperity::bench {
const RecordKernels record_kernels_avx2 = make_record_kernels<LanesExp>();
}
