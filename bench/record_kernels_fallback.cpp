// record_kernels.hpp on targets without the x86 vector builds: the baseline build stands in
// for them (bench_lookup skips instruction sets the CPU lacks anyway).
#include "record_kernels_impl.hpp"

namespace asperity::bench {
const RecordKernels record_kernels_avx2 = make_record_kernels<LibraryExp>();
const RecordKernels record_kernels_avx512 = make_record_kernels<LibraryExp>();
}
