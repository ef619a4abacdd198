// The batch kernels, one per instruction set (kernels_<isa>.cpp), and the choice among them
// (kernels_dispatch.cpp).
#pragma once
#include "asperity/instruction_set.hpp"
#include "curve_kernel.hpp"

namespace asperity::detail {

struct Kernels {
  InstructionSet isa;
  // out[k] = exp(logs[k]) for k < 4, as one vector (the four quantities of contact_at).
  void (*exp4)(const double* logs, double* out) noexcept;
  // One block of a batch (count <= batch_block): ln X or X for every query inside the table;
  // returns how many were not (NaN, infinite, beyond the table), their indices in `rest`.
  int (*block)(const KernelCurve& curve, int twice_order, const double* separations, double* out, int count,
               bool log_output, int* rest) noexcept;
};

extern const Kernels generic_kernels;
#if ASPERITY_X86_KERNELS
extern const Kernels avx2_kernels;
extern const Kernels avx512_kernels;
#endif

// The kernels for `isa`; automatic, or a set this machine lacks, gives the best available.
const Kernels& kernels_for(InstructionSet isa) noexcept;

}  // namespace asperity::detail
