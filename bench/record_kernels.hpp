// Issue 13's question: the lookup grid's interval records are 48 bytes (6 doubles,
// detail::fast_stride), so in an array they straddle 64-byte cache lines about half the time.
// Would 64-byte records (8 doubles, 2 of them padding, the array 64-byte aligned: one line per
// record) be faster? These are bench-local copies of the runtime's scalar lookup (Curve::value)
// and of its former batch loop, one fused loop the compiler vectorizes (run_block: position,
// six coefficient gathers, quintic, exp; the runtime now runs three passes,
// runtime/core/kernel/kernels.hpp), with the record stride as a parameter, compiled per
// instruction set with the flags the runtime used (bench/CMakeLists.txt), so that both strides
// run the same code. The fused loop stays as the baseline the three passes are measured
// against (BM_Record/batch_ISA/48B against BM_Batch/ISA). bench_lookup --check compares their
// answers with Curve's.
#pragma once
#include <cstdint>

#include "asperity/detail/fast_grid.hpp"

namespace asperity::bench {

// Curve::value on the grid (include/asperity/curve.hpp), with the record stride as a parameter;
// inline like Curve::value, so that it is compiled into the caller's loop. NaN off the grid.
template <int stride>
ASPERITY_ALWAYS_INLINE double record_lookup(const detail::FastGrid& grid, const double* coefficients,
                                            double separation) noexcept {
  detail::FastPosition at;
  if (__builtin_expect(!detail::fast_position(grid, separation, at), 0)) return __builtin_nan("");
  return detail::fast_exp(detail::fast_quintic(coefficients, at.interval * stride, at.y));
}

// The same, 6 doubles a record, as a function built for one instruction set (what a scalar
// kernel chosen at load time would be): ln X -> X by the C library's exp or the runtime's inline one.
using ScalarLookup = double (*)(const detail::FastGrid& grid, const double* coefficients, double separation);
// out[j] = X for j < count, every query through the branch-free loop; returns how many were
// off the grid (their out[j] are to be answered by the caller).
using BlockLookup = std::uint64_t (*)(const detail::FastGrid& grid, const double* coefficients,
                                      const double* separations, double* out, int count);

struct RecordKernels {
  ScalarLookup scalar6;             // the C library's exp (as Curve::value)
  ScalarLookup scalar6_inline_exp;  // the runtime's inline exp (detail/fast_math.hpp)
  BlockLookup block6, block8;       // the batch loop, records of 6 and 8 doubles
};

extern const RecordKernels record_kernels_generic;
extern const RecordKernels record_kernels_avx2;    // built with -mavx2 -mfma
extern const RecordKernels record_kernels_avx512;  // built with -mavx512f/dq/vl

}  // namespace asperity::bench
