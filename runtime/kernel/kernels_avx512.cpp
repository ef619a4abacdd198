// The batch kernel built for avx512 (compile options in CMakeLists.txt; see curve_kernel.hpp).
#include "kernels.hpp"

namespace asperity::detail {
namespace {

void exp4(const double* logs, double* out) noexcept {
  for (int k = 0; k < 4; ++k) out[k] = fast_exp(logs[k]);
}

int block(const KernelCurve& curve, int twice_order, const double* separations, double* out, int count,
          bool log_output, int* rest) noexcept {
  return evaluate_block<FastMath>(curve, twice_order, separations, out, count, log_output, rest);
}

}  // namespace

const Kernels avx512_kernels{InstructionSet::avx512, exp4, block};

}  // namespace asperity::detail
