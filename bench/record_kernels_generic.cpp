// record_kernels.hpp for the compiler's baseline (the runtime's kernels_generic.cpp flags).
#include "record_kernels_impl.hpp"

namespace asperity::bench {
const RecordKernels record_kernels_generic = make_record_kernels<InlineExp>();
}
