// The batch kernel built for generic (compile options in CMakeLists.txt; see curve_kernel.hpp).
#include "kernels.hpp"

namespace asperity::detail {
namespace {

void exp4(const double* logs, double* out) noexcept {
  for (int k = 0; k < 4; ++k) out[k] = fast_exp(logs[k]);
}

// Without wide vectors the inline exp/log do not pay (one at a time the C library's are
// faster: bench_lookup BM_StdExp / BM_FastExp), so the baseline build sorts by segment and
// calls the library's.
int block(const KernelCurve& curve, int twice_order, const double* separations, double* out, int count,
          bool log_output, int* rest) noexcept {
  return evaluate_block<LibraryMath>(curve, twice_order, separations, out, count, log_output, rest);
}

}  // namespace

const Kernels generic_kernels{InstructionSet::generic, exp4, block};

}  // namespace asperity::detail
