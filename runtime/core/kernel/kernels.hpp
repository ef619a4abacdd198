// The batch kernels, one per instruction set (kernels_<isa>.cpp), and the choice among them
// (kernels_dispatch.cpp).
#pragma once
#include "asperity/instruction_set.hpp"
#include "curve_kernel.hpp"

namespace asperity::detail {

struct Kernels {
  // out[k] = exp(logs[k]) for k < 4, as one vector (the four quantities of contact_at).
  void (*exp4)(const double* logs, double* out) noexcept;
  // One block of a batch (count <= batch_block): ln X or X for every query inside the table;
  // returns how many were not (NaN, infinite, beyond the table), their indices in `rest`.
  int (*block)(const KernelCurve& curve, int twice_order, const double* separations, double* out, int count,
               bool log_output, int* rest) noexcept;
};

// What each instruction-set build instantiates (kernels_<isa>.cpp): internal linkage, so every
// build keeps its own copy (see curve_kernel.hpp).
namespace {
inline void exp4(const double* logs, double* out) noexcept {
  for (int k = 0; k < 4; ++k) out[k] = fast_exp(logs[k]);
}

template <class Math>
int block(const KernelCurve& curve, int twice_order, const double* separations, double* out, int count,
          bool log_output, int* rest) noexcept {
  return evaluate_block<Math>(curve, twice_order, separations, out, count, log_output, rest);
}
}  // namespace

extern const Kernels generic_kernels;
#if ASPERITY_X86_KERNELS
extern const Kernels avx2_kernels;
extern const Kernels avx512_kernels;
#endif

// The kernels for `isa`; automatic, or a set this machine lacks, gives the best available.
const Kernels& kernels_for(InstructionSet isa) noexcept;

}  // namespace asperity::detail
